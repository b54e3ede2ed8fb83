#include "png_writer.hpp"

#include <png.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace eoir::imageio {

std::vector<std::uint8_t> encode_png_gray8(const std::uint8_t* pixels, std::int64_t width, std::int64_t height,
                                           std::int64_t row_stride) {
  if (pixels == nullptr) throw ImageIoError("PNG: pixel buffer is null");
  constexpr std::int64_t kMax = 0x7fffffff;  // libpng's png_uint_31 limit
  if (width < 1 || height < 1 || width > kMax || height > kMax)
    throw ImageIoError("PNG: image size " + std::to_string(width) + " x " + std::to_string(height) + " out of range");
  if (row_stride == 0) row_stride = width;
  if (row_stride < width || row_stride > kMax)
    throw ImageIoError("PNG: row stride " + std::to_string(row_stride) + " is less than the width " +
                       std::to_string(width) + " or too large");
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(width);
  image.height = static_cast<png_uint_32>(height);
  image.format = PNG_FORMAT_GRAY;
  png_alloc_size_t size = 0;
  const auto stride = static_cast<png_int_32>(row_stride);
  if (!png_image_write_to_memory(&image, nullptr, &size, 0, pixels, stride, nullptr))
    throw ImageIoError(std::string("PNG: encode: ") + image.message);
  std::vector<std::uint8_t> out(static_cast<std::size_t>(size));
  if (!png_image_write_to_memory(&image, out.data(), &size, 0, pixels, stride, nullptr))
    throw ImageIoError(std::string("PNG: encode: ") + image.message);
  out.resize(static_cast<std::size_t>(size));
  png_image_free(&image);
  return out;
}

void write_png_gray8(const std::string& path, const std::uint8_t* pixels, std::int64_t width, std::int64_t height,
                     std::int64_t row_stride) {
  std::vector<std::uint8_t> bytes;
  try {
    bytes = encode_png_gray8(pixels, width, height, row_stride);
  } catch (const ImageIoError& e) {
    throw ImageIoError(std::string(e.what()) + " (" + path + ")");
  }
  write_file_atomically(path, bytes.data(), bytes.size());
}

std::vector<std::uint8_t> scale_to_gray8(const double* values, std::size_t count, double black, double white) {
  std::vector<std::uint8_t> out(count, 0);
  const double span = white - black;
  for (std::size_t i = 0; i < count; ++i) {
    const double v = values[i];
    if (std::isnan(v)) continue;
    double t;
    if (span == 0.0) {
      t = v >= black ? 1.0 : 0.0;
    } else {
      t = (v - black) / span;
    }
    if (!(t > 0.0)) t = 0.0;
    if (t > 1.0) t = 1.0;
    out[i] = static_cast<std::uint8_t>(std::lround(t * 255.0));
  }
  return out;
}

}  // namespace eoir::imageio

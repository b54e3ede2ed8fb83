// 8-bit grayscale PNG writer (host side, no engine dependency), built on
// libpng's simplified API. Written atomically like the FITS writer.
//
// Pixel order: row-major, row 0 = the top row as displayed (PNG's own
// order), col 0 = left; row_stride is in bytes between row starts (0 means
// width).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "atomic_write.hpp"

namespace eoir::imageio {

// Throws ImageIoError.
void write_png_gray8(const std::string& path, const std::uint8_t* pixels, std::int64_t width, std::int64_t height,
                     std::int64_t row_stride = 0);

// Encodes to memory (the bytes write_png_gray8 would write).
std::vector<std::uint8_t> encode_png_gray8(const std::uint8_t* pixels, std::int64_t width, std::int64_t height,
                                           std::int64_t row_stride = 0);

// Linear map of values to 0..255: black -> 0, white -> 255, clipped,
// rounded to nearest; NaN -> 0. white may be below black (inverted ramp);
// black == white maps everything >= black to 255 and the rest to 0.
// (Display compression/AGC policy is the caller's; this is only the mapping.)
std::vector<std::uint8_t> scale_to_gray8(const double* values, std::size_t count, double black, double white);

}  // namespace eoir::imageio

// FITS files of fixed content written through the public writer API, for
// the byte-equality test against the files the previous (in-memory) writer
// wrote from the same calls (their sizes and FNV-1a hashes are in
// imageio_test.cpp). Pixel values are exact arithmetic (no libm).
#pragma once
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "fits_writer.hpp"

namespace eoir::imageio::test_cases {

inline FitsHeader header_with(int extra_cards) {
  FitsHeader h;
  h.set_string("DATE-OBS", "2010-08-25T18:00:00.000", "start of the integration (UTC)");
  h.set_string("BUNIT", "electrons", "unit of the pixel values");
  h.set_double("EXPTIME", 0.0125, "[s] integration time");
  h.set_integer("FRAME", 3, "time-step index");
  h.set_logical("SIMULATE", true, "synthetic image");
  h.set_string("FID error_budget", "off", "fidelity");
  h.set_string("LONGTEXT", std::string(150, 'x') + " end", "a long string");
  h.add_comment("a comment card");
  h.add_history("a history card");
  for (int k = 0; k < extra_cards; ++k) h.set_double("EXTRA" + std::to_string(k), 0.1 * k, "filler");
  return h;
}

inline FitsPointing pointing(double time_step_s) {
  FitsPointing p;
  p.ra_deg = 83.633;
  p.dec_deg = 22.0145;
  p.crpix1 = 7.0;
  p.crpix2 = 4.0;
  p.cd1_1 = -2.7e-4;
  p.cd1_2 = 1.0e-6;
  p.cd2_1 = 1.0e-6;
  p.cd2_2 = 2.7e-4;
  p.time_step_s = time_step_s;
  p.mjdref = 55433.75;
  p.dateref = "2010-08-25T18:00:00.000";
  return p;
}

inline std::vector<double> pixels(std::int64_t width, std::int64_t height, int plane) {
  std::vector<double> v(static_cast<std::size_t>(width * height));
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = 1000.0 * plane + static_cast<double>((i * 7919) % 1000) * 0.37 - 100.0 + 1.0 / 3.0;
  return v;
}

inline FitsTable times_table(int planes) {
  FitsTable t;
  t.extname = "TIMES";
  FitsTableColumn frame{"FRAME", "", {}, {}}, date{"DATE-OBS", "", {}, {}}, mjd{"MJD-OBS", "d", {}, {}};
  for (int k = 0; k < planes; ++k) {
    frame.numbers.push_back(k);
    date.strings.push_back("2010-08-25T18:0" + std::to_string(k) + ":00.000");
    mjd.numbers.push_back(55433.75 + k / 1440.0);
  }
  t.columns = {frame, date, mjd};
  return t;
}

// (file name, writer of that file at the given path)
inline std::vector<std::pair<std::string, std::function<void(const std::string&)>>> cases() {
  std::vector<std::pair<std::string, std::function<void(const std::string&)>>> out;
  out.emplace_back("image_f32.fits", [](const std::string& path) {
    FitsHeader h = header_with(0);
    add_tan_pointing(h, pointing(0.0));
    std::vector<double> v = pixels(13, 7, 0);
    v[5] = std::numeric_limits<double>::quiet_NaN();
    write_fits_image(path, v.data(), 13, 7, h);
  });
  out.emplace_back("image_f64.fits", [](const std::string& path) {
    FitsWriteOptions o;
    o.pixel_type = FitsPixelType::Float64;
    const std::vector<double> v = pixels(5, 4, 1);
    write_fits_image(path, v.data(), 5, 4, header_with(2), o);
  });
  out.emplace_back("image_f32_from_float.fits", [](const std::string& path) {
    std::vector<float> v(35);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<float>(i) * 0.25f - 3.0f;
    write_fits_image(path, v.data(), 7, 5, header_with(1));
  });
  for (const bool u16 : {true, false})
    out.emplace_back(u16 ? "image_u16.fits" : "image_u32.fits", [u16](const std::string& path) {
      FitsWriteOptions o;
      o.pixel_type = u16 ? FitsPixelType::UInt16 : FitsPixelType::UInt32;
      std::vector<std::uint32_t> v(6 * 3);
      for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<std::uint32_t>(i * (u16 ? 3641u : 238609294u));
      write_fits_image(path, v.data(), 6, 3, header_with(0), o);
    });
  out.emplace_back("image_no_checksum.fits", [](const std::string& path) {
    FitsWriteOptions o;
    o.checksum = false;
    const std::vector<double> v = pixels(4, 4, 2);
    write_fits_image(path, v.data(), 4, 4, header_with(0), o);
  });
  // Headers whose CHECKSUM/DATASUM cards fall on either side of the end of
  // the first 2880-byte header block (36 cards).
  for (int extra = 7; extra <= 12; ++extra)
    out.emplace_back("image_cards_" + std::to_string(extra) + ".fits", [extra](const std::string& path) {
      const std::vector<double> v = pixels(3, 2, 0);
      write_fits_image(path, v.data(), 3, 2, header_with(extra));
    });
  for (int extra : {0, 4})
    out.emplace_back("cube_" + std::to_string(extra) + ".fits", [extra](const std::string& path) {
      FitsHeader h = header_with(extra);
      add_tan_pointing(h, pointing(60.0));
      h.set_integer("NFRAMES", 3, "frames in the cube (NAXIS3)");
      const std::vector<double> p0 = pixels(9, 6, 0), p1 = pixels(9, 6, 1), p2 = pixels(9, 6, 2);
      write_fits_cube(path, {p0.data(), p1.data(), p2.data()}, 9, 6, h, times_table(3));
    });
  // A cube larger than cfitsio's buffers (40 x 2880 bytes), no table, whose
  // checksum cards take the header into a second block.
  out.emplace_back("cube_large.fits", [](const std::string& path) {
    std::vector<std::vector<double>> planes;
    std::vector<const double*> ptrs;
    for (int k = 0; k < 5; ++k) planes.push_back(pixels(200, 150, k));
    for (const auto& p : planes) ptrs.push_back(p.data());
    write_fits_cube(path, ptrs, 200, 150, header_with(10));
  });
  return out;
}

}  // namespace eoir::imageio::test_cases

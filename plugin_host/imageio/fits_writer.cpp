#include "fits_writer.hpp"

#include <fitsio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace eoir::imageio {

namespace {

std::string upper(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

bool reserved_key(const std::string& key) {
  static const char* const kReserved[] = {"SIMPLE",   "BITPIX",  "EXTEND",  "BSCALE",  "BZERO",  "END",
                                          "CHECKSUM", "DATASUM", "COMMENT", "HISTORY", "PCOUNT", "GCOUNT"};
  for (const char* r : kReserved)
    if (key == r) return true;
  return key.rfind("NAXIS", 0) == 0;
}

// cfitsio status -> exception with its message stack.
[[noreturn]] void throw_fits(int status, const std::string& what) {
  char text[FLEN_STATUS] = {0};
  fits_get_errstatus(status, text);
  std::string msg = what + ": cfitsio error " + std::to_string(status) + " (" + text + ")";
  char line[FLEN_ERRMSG] = {0};
  while (fits_read_errmsg(line)) msg += std::string("; ") + line;
  throw ImageIoError(msg);
}

// Fewest significant digits (15..17) whose %G text reads back exactly, so
// 0.0125 is written as 0.0125 and every double round-trips.
int shortest_digits(double v) {
  for (int d = 15; d < 17; ++d) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.*G", d, v);
    if (std::strtod(buf, nullptr) == v) return d;
  }
  return 17;
}

// Owns the in-memory FITS file; closes it on every path.
struct MemFits {
  fitsfile* f = nullptr;
  void* buffer = nullptr;
  size_t size = 0;
  ~MemFits() {
    if (f != nullptr) {
      int st = 0;
      fits_close_file(f, &st);
    }
    std::free(buffer);
  }
};

// Placeholder cards with fixed comments first: cfitsio then updates the
// values and keeps the comments, instead of stamping the current time into
// them, so identical inputs give byte-identical files.
void write_checksums(fitsfile* f, const std::string& path, int& st) {
  fits_write_key_str(f, "CHECKSUM", "0000000000000000", "HDU checksum (FITS 4.0 standard)", &st);
  fits_write_key_str(f, "DATASUM", "0", "data unit checksum", &st);
  // Flush first: the data unit's fill bytes are only written (as zeros)
  // on a flush, and a checksum taken before it would sum whatever the
  // memory driver's fresh buffer held (then cfitsio restamps the comment).
  fits_flush_file(f, &st);
  unsigned long datasum = 0, hdusum = 0;
  fits_get_chksum(f, &datasum, &hdusum, &st);
  const std::string datasum_text = std::to_string(datasum);
  fits_update_key_str(f, "DATASUM", datasum_text.c_str(), "data unit checksum", &st);
  fits_write_chksum(f, &st);
  if (st) throw_fits(st, "FITS " + path + ": checksum");
}

void write_table(fitsfile* f, const std::string& path, const FitsTable& table, std::size_t rows,
                 const FitsWriteOptions& options, int& st) {
  std::vector<std::string> names, forms, units;
  for (const auto& c : table.columns) {
    const bool text = !c.strings.empty() || c.numbers.empty();
    const std::size_t n = text ? c.strings.size() : c.numbers.size();
    if (n != rows)
      throw ImageIoError("FITS " + path + ": table column " + c.name + " has " + std::to_string(n) +
                         " rows, expected " + std::to_string(rows));
    std::size_t width = 1;
    for (const auto& v : c.strings) width = std::max(width, v.size());
    names.push_back(c.name);
    forms.push_back(text ? std::to_string(width) + "A" : "1D");
    units.push_back(c.unit);
  }
  std::vector<char*> n, fo, u;
  for (std::size_t i = 0; i < names.size(); ++i) {
    n.push_back(const_cast<char*>(names[i].c_str()));
    fo.push_back(const_cast<char*>(forms[i].c_str()));
    u.push_back(const_cast<char*>(units[i].c_str()));
  }
  fits_create_tbl(f, BINARY_TBL, static_cast<LONGLONG>(rows), static_cast<int>(n.size()), n.data(), fo.data(),
                  u.data(), table.extname.c_str(), &st);
  if (st) throw_fits(st, "FITS " + path + ": create table " + table.extname);
  for (std::size_t k = 0; k < table.columns.size(); ++k) {
    const auto& c = table.columns[k];
    if (!c.strings.empty()) {
      std::vector<char*> v;
      for (const auto& x : c.strings) v.push_back(const_cast<char*>(x.c_str()));
      fits_write_col(f, TSTRING, static_cast<int>(k + 1), 1, 1, static_cast<LONGLONG>(rows), v.data(), &st);
    } else if (!c.numbers.empty()) {
      std::vector<double> v = c.numbers;
      fits_write_col(f, TDOUBLE, static_cast<int>(k + 1), 1, 1, static_cast<LONGLONG>(rows), v.data(), &st);
    }
    if (st) throw_fits(st, "FITS " + path + ": table column " + c.name);
  }
  if (options.checksum) write_checksums(f, path, st);
}

template <typename In>
void write_image(const std::string& path, const std::vector<const In*>& planes, std::int64_t width,
                 std::int64_t height, const FitsHeader& header, const FitsWriteOptions& options, bool cube,
                 const FitsTable& table = {}) {
  if (planes.empty()) throw ImageIoError("FITS " + path + ": no image planes");
  for (const In* p : planes)
    if (p == nullptr) throw ImageIoError("FITS " + path + ": pixel buffer is null");
  if (width < 1 || height < 1)
    throw ImageIoError("FITS " + path + ": image size " + std::to_string(width) + " x " + std::to_string(height) +
                       " must be at least 1 x 1");
  const bool f64 = options.pixel_type == FitsPixelType::Float64;
  const bool u16 = options.pixel_type == FitsPixelType::UInt16;
  const bool u32 = options.pixel_type == FitsPixelType::UInt32;
  const int image_type = f64 ? DOUBLE_IMG : u16 ? USHORT_IMG : u32 ? ULONG_IMG : FLOAT_IMG;

  MemFits m;
  m.size = 2880 * 4;
  m.buffer = std::malloc(m.size);
  if (m.buffer == nullptr) throw ImageIoError("FITS " + path + ": out of memory");
  int st = 0;
  fits_create_memfile(&m.f, &m.buffer, &m.size, 2880 * 16, std::realloc, &st);
  if (st) throw_fits(st, "FITS " + path + ": create in memory");

  LONGLONG naxes[3] = {width, height, static_cast<LONGLONG>(planes.size())};
  fits_create_imgll(m.f, image_type, cube ? 3 : 2, naxes, &st);
  if (st) throw_fits(st, "FITS " + path + ": create image");

  for (const auto& c : header.cards()) {
    char* key = const_cast<char*>(c.key.c_str());
    char* com = c.comment.empty() ? nullptr : const_cast<char*>(c.comment.c_str());
    switch (c.kind) {
      case FitsCard::Kind::String:
        if (c.text.size() > 68) fits_write_key_longwarn(m.f, &st);
        fits_write_key_longstr(m.f, key, c.text.c_str(), com, &st);
        break;
      case FitsCard::Kind::Double:
        fits_write_key_dbl(m.f, key, c.number, -shortest_digits(c.number), com, &st);
        break;
      case FitsCard::Kind::Integer:
        fits_write_key_lng(m.f, key, c.integer, com, &st);
        break;
      case FitsCard::Kind::Logical:
        fits_write_key_log(m.f, key, c.logical ? 1 : 0, com, &st);
        break;
      case FitsCard::Kind::Comment:
        fits_write_comment(m.f, c.text.c_str(), &st);
        break;
      case FitsCard::Kind::History:
        fits_write_history(m.f, c.text.c_str(), &st);
        break;
    }
    if (st) throw_fits(st, "FITS " + path + ": header card " + c.key);
  }

  // Rows bottom-up: FITS row j (1-based) = caller row height - j.
  const auto w = static_cast<std::size_t>(width);
  std::vector<float> row32(f64 || u16 || u32 ? 0 : w);
  std::vector<double> row64(f64 ? w : 0);
  std::vector<unsigned short> row_u16(u16 ? w : 0);
  std::vector<unsigned int> row_u32(u32 ? w : 0);
  for (std::size_t plane = 0; plane < planes.size(); ++plane)
  for (std::int64_t j = 1; j <= height; ++j) {
    const In* src = planes[plane] + static_cast<std::size_t>(height - j) * w;
    LONGLONG first[3] = {1, j, static_cast<LONGLONG>(plane + 1)};
    if (u16 || u32) {
      // Unsigned integers: BITPIX 16 or 32 with BZERO 2^15 or 2^31 (FITS 4.0 section 5.2.5).
      const double top = u16 ? 65535.0 : 4294967295.0;
      for (std::size_t i = 0; i < w; ++i) {
        const double v = static_cast<double>(src[i]);
        if (!(v >= 0.0 && v <= top && v == std::floor(v)))
          throw ImageIoError("FITS " + path + ": pixel value " + std::to_string(v) + " is not an unsigned " +
                             (u16 ? "16" : "32") + "-bit integer");
        if (u16) row_u16[i] = static_cast<unsigned short>(v);
        else row_u32[i] = static_cast<unsigned int>(v);
      }
      if (u16) fits_write_pixll(m.f, TUSHORT, first, static_cast<LONGLONG>(w), row_u16.data(), &st);
      else fits_write_pixll(m.f, TUINT, first, static_cast<LONGLONG>(w), row_u32.data(), &st);
    } else if (f64) {
      for (std::size_t i = 0; i < w; ++i) row64[i] = static_cast<double>(src[i]);
      fits_write_pixll(m.f, TDOUBLE, first, static_cast<LONGLONG>(w), row64.data(), &st);
    } else {
      for (std::size_t i = 0; i < w; ++i) row32[i] = static_cast<float>(src[i]);
      fits_write_pixll(m.f, TFLOAT, first, static_cast<LONGLONG>(w), row32.data(), &st);
    }
    if (st) throw_fits(st, "FITS " + path + ": write pixels");
  }
  if (options.checksum) write_checksums(m.f, path, st);
  if (!table.extname.empty()) write_table(m.f, path, table, planes.size(), options, st);
  fits_flush_file(m.f, &st);
  LONGLONG head = 0, data = 0, end = 0;
  fits_get_hduaddrll(m.f, &head, &data, &end, &st);
  if (st) throw_fits(st, "FITS " + path + ": finish");
  fits_close_file(m.f, &st);
  m.f = nullptr;
  if (st) throw_fits(st, "FITS " + path + ": close");
  // The memory driver reports its allocation; the file is the HDU's extent
  // (a multiple of 2880 bytes).
  const auto file_size = static_cast<std::size_t>(end);
  if (file_size == 0 || file_size % 2880 != 0 || file_size > m.size)
    throw ImageIoError("FITS " + path + ": unexpected in-memory file size " + std::to_string(file_size));
  write_file_atomically(path, m.buffer, file_size);
}

}  // namespace

FitsHeader& FitsHeader::append(FitsCard card) {
  if (card.kind != FitsCard::Kind::Comment && card.kind != FitsCard::Kind::History) {
    card.key = upper(card.key);
    if (card.key.empty()) throw ImageIoError("FITS header: empty keyword");
    if (reserved_key(card.key)) throw ImageIoError("FITS header: keyword " + card.key + " is set by the writer");
    for (char ch : card.key) {
      if (ch < 32 || ch > 126 || ch == '=')
        throw ImageIoError("FITS header: keyword '" + card.key + "' has an invalid character");
    }
  }
  cards_.push_back(std::move(card));
  return *this;
}

FitsHeader& FitsHeader::set_string(const std::string& key, const std::string& value, const std::string& comment) {
  FitsCard c;
  c.kind = FitsCard::Kind::String;
  c.key = key;
  c.text = value;
  c.comment = comment;
  return append(std::move(c));
}

FitsHeader& FitsHeader::set_double(const std::string& key, double value, const std::string& comment) {
  if (!std::isfinite(value)) throw ImageIoError("FITS header: keyword " + upper(key) + " value is not finite");
  FitsCard c;
  c.kind = FitsCard::Kind::Double;
  c.key = key;
  c.number = value;
  c.comment = comment;
  return append(std::move(c));
}

FitsHeader& FitsHeader::set_integer(const std::string& key, long long value, const std::string& comment) {
  FitsCard c;
  c.kind = FitsCard::Kind::Integer;
  c.key = key;
  c.integer = value;
  c.comment = comment;
  return append(std::move(c));
}

FitsHeader& FitsHeader::set_logical(const std::string& key, bool value, const std::string& comment) {
  FitsCard c;
  c.kind = FitsCard::Kind::Logical;
  c.key = key;
  c.logical = value;
  c.comment = comment;
  return append(std::move(c));
}

FitsHeader& FitsHeader::add_comment(const std::string& text) {
  FitsCard c;
  c.kind = FitsCard::Kind::Comment;
  c.key = "COMMENT";
  c.text = text;
  return append(std::move(c));
}

FitsHeader& FitsHeader::add_history(const std::string& text) {
  FitsCard c;
  c.kind = FitsCard::Kind::History;
  c.key = "HISTORY";
  c.text = text;
  return append(std::move(c));
}

void add_tan_pointing(FitsHeader& h, const FitsPointing& p) {
  const bool time_axis = p.time_step_s > 0.0;
  h.set_integer("WCSAXES", time_axis ? 3 : 2, "number of WCS axes");
  h.set_string("CTYPE1", "RA---TAN", "gnomonic projection, right ascension");
  h.set_string("CTYPE2", "DEC--TAN", "gnomonic projection, declination");
  h.set_string("CUNIT1", "deg");
  h.set_string("CUNIT2", "deg");
  h.set_double("CRVAL1", p.ra_deg, "[deg] RA at the reference pixel");
  h.set_double("CRVAL2", p.dec_deg, "[deg] Dec at the reference pixel");
  h.set_double("CRPIX1", p.crpix1, "reference pixel x (FITS, 1 = left)");
  h.set_double("CRPIX2", p.crpix2, "reference pixel y (FITS, 1 = bottom)");
  h.set_double("CD1_1", p.cd1_1, "[deg/pixel]");
  h.set_double("CD1_2", p.cd1_2, "[deg/pixel]");
  h.set_double("CD2_1", p.cd2_1, "[deg/pixel]");
  h.set_double("CD2_2", p.cd2_2, "[deg/pixel]");
  h.set_string("RADESYS", p.radesys);
  if (time_axis) {
    h.set_string("CTYPE3", "TIME", "time of the plane");
    h.set_string("CUNIT3", "s");
    h.set_double("CRVAL3", 0.0, "[s] time of the first plane from MJDREF");
    h.set_double("CRPIX3", 1.0, "the first plane");
    h.set_double("CD3_3", p.time_step_s, "[s/plane] time step");
    h.set_double("MJDREF", p.mjdref, "[d] time of the first plane (MJD)");
    if (!p.dateref.empty()) h.set_string("DATEREF", p.dateref, "time of the first plane");
  }
}

void write_fits_image(const std::string& path, const float* pixels, std::int64_t width, std::int64_t height,
                      const FitsHeader& header, const FitsWriteOptions& options) {
  write_image(path, std::vector<const float*>{pixels}, width, height, header, options, false);
}

void write_fits_image(const std::string& path, const double* pixels, std::int64_t width, std::int64_t height,
                      const FitsHeader& header, const FitsWriteOptions& options) {
  write_image(path, std::vector<const double*>{pixels}, width, height, header, options, false);
}

void write_fits_image(const std::string& path, const std::uint32_t* pixels, std::int64_t width, std::int64_t height,
                      const FitsHeader& header, const FitsWriteOptions& options) {
  write_image(path, std::vector<const std::uint32_t*>{pixels}, width, height, header, options, false);
}

void write_fits_cube(const std::string& path, const std::vector<const double*>& planes, std::int64_t width,
                     std::int64_t height, const FitsHeader& header, const FitsTable& table,
                     const FitsWriteOptions& options) {
  write_image(path, planes, width, height, header, options, true, table);
}

}  // namespace eoir::imageio

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

// Placeholder cards with fixed comments, written before the data unit (the
// header then has its final length and the data never move): cfitsio then
// updates the values and keeps the comments, instead of stamping the current
// time into them, so identical inputs give byte-identical files.
void write_checksum_placeholders(fitsfile* f, const std::string& path, int& st) {
  fits_write_key_str(f, "CHECKSUM", "0000000000000000", "HDU checksum (FITS 4.0 standard)", &st);
  fits_write_key_str(f, "DATASUM", "0", "data unit checksum", &st);
  if (st) throw_fits(st, "FITS " + path + ": checksum cards");
}

void write_checksum_values(fitsfile* f, const std::string& path, int& st) {
  // Flush first: the data unit's fill bytes are only written (as zeros)
  // on a flush, and a checksum taken before it would sum whatever the
  // driver's fresh buffer held (then cfitsio restamps the comment).
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
  if (options.checksum) {
    write_checksum_placeholders(f, path, st);
    write_checksum_values(f, path, st);
  }
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

struct FitsCubeWriter::State {
  std::string path;  // as the caller named it, for messages
  AtomicReplacement file;
  fitsfile* f = nullptr;
  std::int64_t width = 0, height = 0;
  FitsWriteOptions options;
  std::vector<bool> written;  // per plane
  bool failed = false;        // an error left the file incomplete
  explicit State(const std::string& p) : path(p), file(p) {}
  ~State() {
    if (f != nullptr) {
      int st = 0;
      fits_close_file(f, &st);
    }
  }  // then `file` removes the temporary
};

FitsCubeWriter::FitsCubeWriter() = default;
FitsCubeWriter::~FitsCubeWriter() = default;
FitsCubeWriter::FitsCubeWriter(FitsCubeWriter&&) noexcept = default;
FitsCubeWriter& FitsCubeWriter::operator=(FitsCubeWriter&&) noexcept = default;

void FitsCubeWriter::open(const std::string& path, std::int64_t width, std::int64_t height, std::int64_t planes,
                          const FitsHeader& header, const FitsWriteOptions& options) {
  start(path, width, height, planes, true, header, options);
}

void FitsCubeWriter::open_image(const std::string& path, std::int64_t width, std::int64_t height,
                                const FitsHeader& header, const FitsWriteOptions& options) {
  start(path, width, height, 1, false, header, options);
}

void FitsCubeWriter::start(const std::string& path, std::int64_t width, std::int64_t height, std::int64_t planes,
                           bool cube, const FitsHeader& header, const FitsWriteOptions& options) {
  if (state_ != nullptr) throw ImageIoError("FITS " + path + ": the writer is already open for " + state_->path);
  if (planes < 1) throw ImageIoError("FITS " + path + ": no image planes");
  if (width < 1 || height < 1)
    throw ImageIoError("FITS " + path + ": image size " + std::to_string(width) + " x " + std::to_string(height) +
                       " must be at least 1 x 1");
  const bool f64 = options.pixel_type == FitsPixelType::Float64;
  const bool u16 = options.pixel_type == FitsPixelType::UInt16;
  const bool u32 = options.pixel_type == FitsPixelType::UInt32;
  const int image_type = f64 ? DOUBLE_IMG : u16 ? USHORT_IMG : u32 ? ULONG_IMG : FLOAT_IMG;

  auto s = std::make_unique<State>(path);
  s->width = width;
  s->height = height;
  s->options = options;
  s->written.assign(static_cast<std::size_t>(planes), false);
  int st = 0;
  // The disk driver without extended file-name syntax; it refuses an
  // existing file, so the temporary is created exclusively.
  fits_create_diskfile(&s->f, s->file.temporary().c_str(), &st);
  if (st) {
    s->f = nullptr;
    throw_fits(st, "FITS " + path + ": create " + s->file.temporary());
  }
  fitsfile* f = s->f;
  LONGLONG naxes[3] = {width, height, static_cast<LONGLONG>(planes)};
  fits_create_imgll(f, image_type, cube ? 3 : 2, naxes, &st);
  if (st) throw_fits(st, "FITS " + path + ": create image");

  for (const auto& c : header.cards()) {
    char* key = const_cast<char*>(c.key.c_str());
    char* com = c.comment.empty() ? nullptr : const_cast<char*>(c.comment.c_str());
    switch (c.kind) {
      case FitsCard::Kind::String:
        if (c.text.size() > 68) fits_write_key_longwarn(f, &st);
        fits_write_key_longstr(f, key, c.text.c_str(), com, &st);
        break;
      case FitsCard::Kind::Double:
        fits_write_key_dbl(f, key, c.number, -shortest_digits(c.number), com, &st);
        break;
      case FitsCard::Kind::Integer:
        fits_write_key_lng(f, key, c.integer, com, &st);
        break;
      case FitsCard::Kind::Logical:
        fits_write_key_log(f, key, c.logical ? 1 : 0, com, &st);
        break;
      case FitsCard::Kind::Comment:
        fits_write_comment(f, c.text.c_str(), &st);
        break;
      case FitsCard::Kind::History:
        fits_write_history(f, c.text.c_str(), &st);
        break;
    }
    if (st) throw_fits(st, "FITS " + path + ": header card " + c.key);
  }
  if (options.checksum) write_checksum_placeholders(f, path, st);
  state_ = std::move(s);
}

template <typename In>
void FitsCubeWriter::write_plane_of(std::int64_t k, const In* pixels) {
  if (state_ == nullptr) throw ImageIoError("FITS: write_plane before open");
  State& s = *state_;
  const std::string& path = s.path;
  if (s.failed) throw ImageIoError("FITS " + path + ": an earlier error left the file incomplete");
  if (pixels == nullptr) throw ImageIoError("FITS " + path + ": pixel buffer is null");
  if (k < 0 || k >= static_cast<std::int64_t>(s.written.size()))
    throw ImageIoError("FITS " + path + ": plane " + std::to_string(k) + " is outside 0.." +
                       std::to_string(s.written.size() - 1));
  const bool f64 = s.options.pixel_type == FitsPixelType::Float64;
  const bool u16 = s.options.pixel_type == FitsPixelType::UInt16;
  const bool u32 = s.options.pixel_type == FitsPixelType::UInt32;
  s.failed = true;  // until the plane is complete
  int st = 0;
  // Rows bottom-up: FITS row j (1-based) = caller row height - j.
  const auto w = static_cast<std::size_t>(s.width);
  std::vector<float> row32(f64 || u16 || u32 ? 0 : w);
  std::vector<double> row64(f64 ? w : 0);
  std::vector<unsigned short> row_u16(u16 ? w : 0);
  std::vector<unsigned int> row_u32(u32 ? w : 0);
  for (std::int64_t j = 1; j <= s.height; ++j) {
    const In* src = pixels + static_cast<std::size_t>(s.height - j) * w;
    LONGLONG first[3] = {1, j, static_cast<LONGLONG>(k + 1)};
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
      if (u16) fits_write_pixll(s.f, TUSHORT, first, static_cast<LONGLONG>(w), row_u16.data(), &st);
      else fits_write_pixll(s.f, TUINT, first, static_cast<LONGLONG>(w), row_u32.data(), &st);
    } else if (f64) {
      for (std::size_t i = 0; i < w; ++i) row64[i] = static_cast<double>(src[i]);
      fits_write_pixll(s.f, TDOUBLE, first, static_cast<LONGLONG>(w), row64.data(), &st);
    } else {
      for (std::size_t i = 0; i < w; ++i) row32[i] = static_cast<float>(src[i]);
      fits_write_pixll(s.f, TFLOAT, first, static_cast<LONGLONG>(w), row32.data(), &st);
    }
    if (st) throw_fits(st, "FITS " + path + ": write pixels");
  }
  s.written[static_cast<std::size_t>(k)] = true;
  s.failed = false;
}

void FitsCubeWriter::write_plane(std::int64_t k, const double* pixels) { write_plane_of(k, pixels); }
void FitsCubeWriter::write_plane(std::int64_t k, const float* pixels) { write_plane_of(k, pixels); }
void FitsCubeWriter::write_plane(std::int64_t k, const std::uint32_t* pixels) { write_plane_of(k, pixels); }

void FitsCubeWriter::finish(const FitsTable& table) {
  if (state_ == nullptr) throw ImageIoError("FITS: finish before open");
  // Whatever happens below, the writer is closed afterwards (the temporary
  // removed unless the file is in place).
  const std::unique_ptr<State> s = std::move(state_);
  const std::string& path = s->path;
  if (s->failed) throw ImageIoError("FITS " + path + ": an earlier error left the file incomplete");
  for (std::size_t k = 0; k < s->written.size(); ++k)
    if (!s->written[k])
      throw ImageIoError("FITS " + path + ": plane " + std::to_string(k) + " of " +
                         std::to_string(s->written.size()) + " was not written");
  int st = 0;
  if (s->options.checksum) write_checksum_values(s->f, path, st);
  if (!table.extname.empty()) write_table(s->f, path, table, s->written.size(), s->options, st);
  fits_close_file(s->f, &st);
  s->f = nullptr;
  if (st) throw_fits(st, "FITS " + path + ": close");
  s->file.commit();
}

namespace {
template <typename In>
void write_image(const std::string& path, const In* pixels, std::int64_t width, std::int64_t height,
                 const FitsHeader& header, const FitsWriteOptions& options) {
  if (pixels == nullptr) throw ImageIoError("FITS " + path + ": pixel buffer is null");
  FitsCubeWriter w;
  w.open_image(path, width, height, header, options);
  w.write_plane(0, pixels);
  w.finish();
}
}  // namespace

void write_fits_image(const std::string& path, const float* pixels, std::int64_t width, std::int64_t height,
                      const FitsHeader& header, const FitsWriteOptions& options) {
  write_image(path, pixels, width, height, header, options);
}

void write_fits_image(const std::string& path, const double* pixels, std::int64_t width, std::int64_t height,
                      const FitsHeader& header, const FitsWriteOptions& options) {
  write_image(path, pixels, width, height, header, options);
}

void write_fits_image(const std::string& path, const std::uint32_t* pixels, std::int64_t width, std::int64_t height,
                      const FitsHeader& header, const FitsWriteOptions& options) {
  write_image(path, pixels, width, height, header, options);
}

void write_fits_cube(const std::string& path, const std::vector<const double*>& planes, std::int64_t width,
                     std::int64_t height, const FitsHeader& header, const FitsTable& table,
                     const FitsWriteOptions& options) {
  if (planes.empty()) throw ImageIoError("FITS " + path + ": no image planes");
  for (const double* p : planes)
    if (p == nullptr) throw ImageIoError("FITS " + path + ": pixel buffer is null");
  FitsCubeWriter w;
  w.open(path, width, height, static_cast<std::int64_t>(planes.size()), header, options);
  for (std::size_t k = 0; k < planes.size(); ++k) w.write_plane(static_cast<std::int64_t>(k), planes[k]);
  w.finish(table);
}

}  // namespace eoir::imageio

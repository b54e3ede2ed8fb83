#include "universe/star_catalog.hpp"

#include <erfa.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <sstream>
#include <string_view>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "core/mapped_file.hpp"
#include "core/read_file.hpp"
#include "core/utf8.hpp"

#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "the binary star catalogue is little-endian; add byte swapping for this host"
#endif

namespace eoir::universe {
namespace {

constexpr double kMasToRad = constants::rad_per_deg / 3.6e6;
constexpr double kMetresPerAu = constants::au_m;
constexpr double kSecondsPerDay = constants::seconds_per_day;
constexpr double kJ2000_jd = 2451545.0;
constexpr double kDaysPerJulianYear = 365.25;

// Binary layout v2 (data/stars/README.md), little-endian.
constexpr char kMagic[8] = {'E', 'O', 'I', 'R', 'S', 'T', 'A', 'R'};
constexpr std::uint32_t kFormatVersion = 2;
constexpr std::size_t kFixedHeaderBytes = 84;
constexpr std::size_t kRecordBytes = 48;
constexpr std::uint32_t kNoName = 0xFFFFFFFFu;
constexpr std::uint32_t kFlagHipparcos = 4;
// Integrated-starlight table of the binary file: V = 0 equivalent stars with
// V <= kFluxFirstMag + k kFluxStepMag.
constexpr double kFluxFirstMag = -2.0;
constexpr double kFluxStepMag = 0.1;
// Largest CSV catalogue read: 256 MiB, three million stars; /dev/zero is
// refused, not read forever. The binary file (28 MB) is mapped, up to 2 GiB.
constexpr std::size_t kMaxFileBytes = std::size_t{256} << 20;
constexpr std::size_t kMaxMappedBytes = std::size_t{2} << 30;

template <typename T>
T read_le(const char* p) {
  T value;
  std::memcpy(&value, p, sizeof(T));
  return value;
}

[[noreturn]] void corrupt(const std::string& path, const std::string& what) {
  throw Error(Status::corrupt_file, path + ": " + what);
}

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

// Calls line(text, number) for each line of `bytes` (1-based numbers), in
// place: no copies.
template <typename F>
void for_each_line(const std::string& bytes, F&& line) {
  long number = 0;
  for (std::size_t pos = 0; pos < bytes.size();) {
    const std::size_t end = std::min(bytes.find('\n', pos), bytes.size());
    line(std::string_view(bytes).substr(pos, end - pos), ++number);
    pos = end + 1;
  }
}

// A field's text for a message: at most 40 bytes, cut at a character boundary.
std::string shown(std::string_view text) {
  constexpr std::size_t kMax = 40;
  if (text.size() <= kMax) return std::string(text);
  return std::string(text.substr(0, utf8_prefix_length(text, kMax))) + "...";
}

double epoch_tdb_julian_year(const EngineTime& t) {
  const JulianDate tdb = t.to(TimeScale::tdb);
  return 2000.0 + ((tdb.jd1 - kJ2000_jd) + tdb.jd2) / kDaysPerJulianYear;
}

void require_finite_vec(const Vec3& v, const char* field) {
  if (!v.allFinite()) throw Error(Status::out_of_range, std::string(field) + ": not finite");
}

ApparentPlaceContext context_from_astrom(const eraASTROM& astrom, const EngineTime& t, double epoch) {
  ApparentPlaceContext c;
  // astrom.pmt counts from J2000.0; shift to the catalogue epoch.
  c.proper_motion_years = epoch_tdb_julian_year(t) - epoch;
  c.barycentric_position_au = Vec3(astrom.eb[0], astrom.eb[1], astrom.eb[2]);
  c.sun_to_observer_unit = Vec3(astrom.eh[0], astrom.eh[1], astrom.eh[2]);
  c.sun_distance_au = astrom.em;
  c.barycentric_velocity_over_c = Vec3(astrom.v[0], astrom.v[1], astrom.v[2]);
  c.inverse_lorentz_factor = astrom.bm1;
  return c;
}

}  // namespace


// What a catalogue holds, shared by its copies at other epochs.
struct StarCatalog::Data {
  std::string source;
  double brightest_v_mag = 0.0, faintest_v_mag = 0.0, max_proper_motion_mas_yr = 0.0;
  std::size_t count = 0;
  // CSV: the stars in file order and, per cell, their indices by V.
  std::vector<CatalogStar> stars;
  std::vector<std::uint32_t> by_cell;
  std::vector<std::uint32_t> cell_start_owned;
  std::vector<double> sorted_v, cumulative_v0;  // for v0_equivalent_stars
  // Binary: the mapped file; records in cell order (index = record).
  std::shared_ptr<const MappedFile> file;
  const char* records = nullptr;
  const char* names = nullptr;
  std::uint32_t names_bytes = 0;
  std::vector<double> flux_table;  // binary: V = 0 equivalent stars at kFluxFirstMag + k kFluxStepMag
  const std::uint32_t* cell_start = nullptr;  // cells + 1 entries (owned or mapped)
  SkyCells cells;

  std::size_t slot_star(std::size_t slot) const { return by_cell.empty() ? slot : by_cell[slot]; }
  double v_at(std::size_t i) const {
    return records ? static_cast<double>(read_le<float>(records + i * kRecordBytes + 28)) : stars[i].v_mag;
  }
};

namespace {
constexpr double kFullCircle = 2.0 * constants::pi;
}  // namespace

SkyCells::SkyCells() : band_first(bands + 1, 0) {
  for (int b = 0; b < bands; ++b) {
    const double mid = (-90.0 + band_deg * (b + 0.5)) * constants::rad_per_deg;
    // (the converter's numpy.rint: round half to even, as nearbyint)
    const auto n = std::max(1.0, std::nearbyint(360.0 * std::cos(mid)));
    band_first[static_cast<std::size_t>(b) + 1] = band_first[static_cast<std::size_t>(b)] + static_cast<std::uint32_t>(n);
  }
}

std::uint32_t SkyCells::cell_of(double ra_rad, double dec_rad) const {
  const int band = std::clamp(static_cast<int>(std::floor((dec_rad / constants::rad_per_deg + 90.0) / band_deg)), 0,
                              bands - 1);
  const std::uint32_t n = cells_in_band(band);
  double ra = std::fmod(ra_rad, kFullCircle);
  if (ra < 0) ra += kFullCircle;
  const auto k = std::min(static_cast<std::uint32_t>(std::floor(ra / kFullCircle * n)), n - 1);
  return band_first[static_cast<std::size_t>(band)] + k;
}

StarCatalog StarCatalog::at_epoch(double epoch_julian_year) const {
  require_finite(epoch_julian_year, "star_catalogue.epoch_julian_year");
  return StarCatalog(data_, epoch_julian_year);
}

std::size_t StarCatalog::size() const { return data_->count; }
const std::string& StarCatalog::source() const { return data_->source; }
double StarCatalog::brightest_v_mag() const { return data_->brightest_v_mag; }
double StarCatalog::faintest_v_mag() const { return data_->faintest_v_mag; }
double StarCatalog::max_proper_motion_mas_yr() const { return data_->max_proper_motion_mas_yr; }
double StarCatalog::v_mag(std::size_t i) const { return data_->v_at(i); }

Vec3 StarCatalog::unit_vector(std::size_t i) const {
  double ra = 0, dec = 0;
  if (data_->records) {
    const char* r = data_->records + i * kRecordBytes;
    ra = read_le<double>(r);
    dec = read_le<double>(r + 8);
  } else {
    ra = data_->stars[i].ra_rad;
    dec = data_->stars[i].dec_rad;
  }
  return Vec3(std::cos(dec) * std::cos(ra), std::cos(dec) * std::sin(ra), std::sin(dec));
}

CatalogStar StarCatalog::star(std::size_t i) const {
  const Data& d = *data_;
  if (i >= d.count) throw Error(Status::out_of_range, "star index: " + std::to_string(i) + " beyond the catalogue");
  if (!d.records) return d.stars[i];
  const std::string& path = d.file->path();
  const char* r = d.records + i * kRecordBytes;
  CatalogStar s;
  s.ra_rad = read_le<double>(r + 0);
  s.dec_rad = read_le<double>(r + 8);
  s.pm_ra_cosdec_mas_per_yr = read_le<float>(r + 16);
  s.pm_dec_mas_per_yr = read_le<float>(r + 20);
  s.parallax_mas = read_le<float>(r + 24);
  s.v_mag = read_le<float>(r + 28);
  s.b_v_mag = read_le<float>(r + 32);
  const auto flags = static_cast<std::uint8_t>(r[38]);
  const auto number = read_le<std::uint32_t>(r + 40);
  const auto name_offset = read_le<std::uint32_t>(r + 44);
  s.id = ((flags & kFlagHipparcos) ? "HIP" : "HT") + std::to_string(number);
  if (name_offset != kNoName) {
    if (name_offset >= d.names_bytes) corrupt(path, "record " + std::to_string(i) + ": name_offset out of range");
    const char* start = d.names + name_offset;
    const void* end = std::memchr(start, '\0', d.names_bytes - name_offset);
    if (end == nullptr) corrupt(path, "record " + std::to_string(i) + ": name not terminated");
    s.name.assign(start, static_cast<const char*>(end));
  }
  if (!std::isfinite(s.ra_rad) || !std::isfinite(s.dec_rad) || !std::isfinite(s.v_mag) || !std::isfinite(s.b_v_mag) ||
      !std::isfinite(s.parallax_mas) || !std::isfinite(s.pm_ra_cosdec_mas_per_yr) ||
      !std::isfinite(s.pm_dec_mas_per_yr))
    corrupt(path, "record " + std::to_string(i) + ": non-finite value");
  return s;
}

StarCatalog StarCatalog::load_binary(const std::string& path) {
  auto file = MappedFile::open(path, kMaxMappedBytes, "star catalogues");
  const std::size_t file_bytes = file->size();
  const char* p = file->data();
  if (file_bytes < kFixedHeaderBytes) corrupt(path, "header: file shorter than the 84-byte header");
  if (std::memcmp(p, kMagic, sizeof kMagic) != 0) corrupt(path, "magic: not an EOIRSTAR file");
  const auto version = read_le<std::uint32_t>(p + 8);
  if (version != kFormatVersion)
    throw Error(Status::file_version, path + ": format_version: " + std::to_string(version) + " (expected " +
                                          std::to_string(kFormatVersion) + ")");
  const auto header_bytes = read_le<std::uint32_t>(p + 12);
  const auto count = read_le<std::uint32_t>(p + 16);
  const auto record_bytes = read_le<std::uint32_t>(p + 20);
  const auto epoch = read_le<double>(p + 24);
  const auto brightest = read_le<double>(p + 32);
  const auto faintest = read_le<double>(p + 40);
  const auto source_bytes = read_le<std::uint32_t>(p + 48);
  const auto names_bytes = read_le<std::uint32_t>(p + 52);
  const auto cell_count = read_le<std::uint32_t>(p + 56);
  const auto flux_steps = read_le<std::uint32_t>(p + 60);
  const auto band_deg = read_le<double>(p + 64);
  const auto max_pm = read_le<double>(p + 72);
  const auto tables_bytes = read_le<std::uint32_t>(p + 80);
  if (record_bytes != kRecordBytes) corrupt(path, "record_bytes: " + std::to_string(record_bytes) + " (expected 48)");
  if (header_bytes < kFixedHeaderBytes + source_bytes || header_bytes > file_bytes || header_bytes % 8 != 0)
    corrupt(path, "header_bytes: inconsistent with source_text_bytes or the file size");
  if (!std::isfinite(epoch)) corrupt(path, "epoch_julian_year: not finite");
  if (!std::isfinite(brightest) || !std::isfinite(faintest) || brightest > faintest)
    corrupt(path, "brightest_v_mag, faintest_v_mag: not finite or out of order");
  if (!(max_pm >= 0.0) || !std::isfinite(max_pm)) corrupt(path, "max_proper_motion: not finite and >= 0");
  Data d;
  if (band_deg != SkyCells::band_deg || cell_count != d.cells.count())
    corrupt(path, "cell_count: " + std::to_string(cell_count) + " cells of " + std::to_string(band_deg) +
                      " deg bands (expected " + std::to_string(d.cells.count()) + " of 1 deg)");
  const std::size_t table_needed = (std::size_t{cell_count} + 1) * 4 + std::size_t{flux_steps} * 8;
  if (tables_bytes < table_needed || tables_bytes % 8 != 0 || tables_bytes - table_needed >= 8)
    corrupt(path, "tables_bytes: " + std::to_string(tables_bytes) + " for " + std::to_string(cell_count) +
                      " cells and " + std::to_string(flux_steps) + " flux steps");
  const std::size_t needed =
      std::size_t{header_bytes} + tables_bytes + std::size_t{count} * kRecordBytes + names_bytes;
  if (needed != file_bytes)
    corrupt(path, "star_count: " + std::to_string(count) + " records and " + std::to_string(names_bytes) +
                      " name bytes need " + std::to_string(needed) + " bytes, the file has " +
                      std::to_string(file_bytes));
  // The cell table: starts rise from 0 to the star count (so that no query
  // reads past the records).
  const char* tables = p + header_bytes;
  d.cell_start = reinterpret_cast<const std::uint32_t*>(tables);  // 8-byte aligned in the mapping
  if (d.cell_start[0] != 0 || d.cell_start[cell_count] != count)
    corrupt(path, "cell_start: must run from 0 to star_count");
  for (std::uint32_t c = 0; c < cell_count; ++c)
    if (d.cell_start[c + 1] < d.cell_start[c]) corrupt(path, "cell_start[" + std::to_string(c + 1) + "]: decreases");
  d.flux_table.resize(flux_steps);
  std::memcpy(d.flux_table.data(), tables + (std::size_t{cell_count} + 1) * 4, std::size_t{flux_steps} * 8);
  for (std::uint32_t k = 0; k < flux_steps; ++k)
    if (!std::isfinite(d.flux_table[k]) || d.flux_table[k] < (k ? d.flux_table[k - 1] : 0.0))
      corrupt(path, "flux_table[" + std::to_string(k) + "]: not finite or decreasing");
  d.source.assign(p + kFixedHeaderBytes, source_bytes);
  d.count = count;
  d.brightest_v_mag = brightest;
  d.faintest_v_mag = faintest;
  d.max_proper_motion_mas_yr = max_pm;
  d.records = tables + tables_bytes;
  d.names = d.records + std::size_t{count} * kRecordBytes;
  d.names_bytes = names_bytes;
  d.file = std::move(file);
  return StarCatalog(std::make_shared<const Data>(std::move(d)), epoch);
}

namespace {

// The CSV catalogue's summaries and cell index (the binary file has them).
void index_stars(const std::vector<CatalogStar>& stars, const SkyCells& cells, std::vector<std::uint32_t>& by_cell,
                 std::vector<std::uint32_t>& cell_start, std::vector<double>& sorted_v, std::vector<double>& cumulative,
                 double& brightest, double& faintest, double& max_pm) {
  brightest = faintest = max_pm = 0.0;
  std::vector<std::uint32_t> cell_of(stars.size());
  sorted_v.resize(stars.size());
  for (std::size_t i = 0; i < stars.size(); ++i) {
    const CatalogStar& s = stars[i];
    cell_of[i] = cells.cell_of(s.ra_rad, s.dec_rad);
    sorted_v[i] = s.v_mag;
    max_pm = std::max(max_pm, std::hypot(s.pm_ra_cosdec_mas_per_yr, s.pm_dec_mas_per_yr));
  }
  by_cell.resize(stars.size());
  for (std::size_t i = 0; i < by_cell.size(); ++i) by_cell[i] = static_cast<std::uint32_t>(i);
  std::stable_sort(by_cell.begin(), by_cell.end(), [&](std::uint32_t a, std::uint32_t b) {
    return cell_of[a] != cell_of[b] ? cell_of[a] < cell_of[b] : stars[a].v_mag < stars[b].v_mag;
  });
  cell_start.assign(cells.count() + 1, 0);
  for (const std::uint32_t i : by_cell) ++cell_start[cell_of[i] + 1];
  for (std::size_t c = 1; c < cell_start.size(); ++c) cell_start[c] += cell_start[c - 1];
  std::sort(sorted_v.begin(), sorted_v.end());
  cumulative.resize(sorted_v.size() + 1);
  cumulative[0] = 0.0;
  for (std::size_t i = 0; i < sorted_v.size(); ++i) cumulative[i + 1] = cumulative[i] + std::pow(10.0, -0.4 * sorted_v[i]);
  if (!sorted_v.empty()) {
    brightest = sorted_v.front();
    faintest = sorted_v.back();
  }
}

}  // namespace

StarCatalog StarCatalog::load_csv(const std::string& path, double epoch_julian_year) {
  require_finite(epoch_julian_year, "star_catalogue.epoch_julian_year");
  std::string bytes = read_file(path, kMaxFileBytes, "star catalogues");
  if (bytes.rfind("\xEF\xBB\xBF", 0) == 0) bytes.erase(0, 3);  // a UTF-8 byte-order mark (spreadsheets write one)

  static const char* const kColumns[] = {"id",           "ra_deg",  "dec_deg", "pm_ra_mas_yr", "pm_dec_mas_yr",
                                         "parallax_mas", "v_mag",   "b_v"};
  constexpr std::size_t kColumnCount = sizeof kColumns / sizeof kColumns[0];
  // Memory stays a small multiple of the file size: fields are views into
  // the file, the stars are reserved once (a data line has at least 16
  // bytes) and duplicate ids are found by sorting indices.
  std::size_t data_lines = 0;
  for_each_line(bytes, [&](std::string_view line, long) {
    const std::string_view content = trim(line);
    data_lines += !content.empty() && content[0] != '#';
  });
  Data catalogue;
  catalogue.source = path;
  catalogue.stars.reserve(std::min(data_lines > 0 ? data_lines - 1 : 0, kMaxCsvStars));
  std::vector<std::uint32_t> line_of_star;
  line_of_star.reserve(catalogue.stars.capacity());

  std::size_t column_of[kColumnCount];
  std::size_t header_fields = 0;
  bool have_header = false;
  std::vector<std::string_view> fields;
  std::string field_text;  // a field NUL-terminated for strtod
  for_each_line(bytes, [&](std::string_view line, long line_number) {
    const std::string_view content = trim(line);
    if (content.empty() || content[0] == '#') return;
    const std::string where = path + ":" + std::to_string(line_number) + ": ";
    if (content.find('\0') != std::string_view::npos)
      throw Error(Status::corrupt_file, where + "line: a NUL byte (not text)");
    const std::size_t count = 1 + static_cast<std::size_t>(std::count(content.begin(), content.end(), ','));
    if (count > kMaxCsvColumns)
      throw Error(Status::corrupt_file, where + (have_header ? "line: " : "header: ") + std::to_string(count) +
                                            " columns, at most " + std::to_string(kMaxCsvColumns));
    fields.clear();
    for (std::size_t start = 0;;) {
      const std::size_t comma = content.find(',', start);
      fields.push_back(trim(content.substr(start, comma == std::string_view::npos ? comma : comma - start)));
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
    if (!have_header) {
      header_fields = fields.size();
      for (std::size_t c = 0; c < kColumnCount; ++c) {
        const auto it = std::find(fields.begin(), fields.end(), kColumns[c]);
        if (it == fields.end())
          throw Error(Status::corrupt_file, where + kColumns[c] + ": missing column in the header line");
        column_of[c] = static_cast<std::size_t>(it - fields.begin());
      }
      have_header = true;
      return;
    }
    if (fields.size() != header_fields)
      throw Error(Status::corrupt_file, where + "line: " + std::to_string(fields.size()) + " fields, the header has " +
                                            std::to_string(header_fields));
    if (catalogue.stars.size() == kMaxCsvStars)
      throw Error(Status::corrupt_file, where + "line: more than " + std::to_string(kMaxCsvStars) +
                                            " stars, the limit of a catalogue");
    auto number = [&](std::size_t c, double lo, double hi) {
      const std::string_view text = fields[column_of[c]];
      if (text.empty()) throw Error(Status::corrupt_file, where + kColumns[c] + ": empty");
      field_text.assign(text);
      char* end = nullptr;
      const double value = std::strtod(field_text.c_str(), &end);
      // Underflow (ERANGE with a subnormal or zero) is a number; overflow is inf.
      if (end == field_text.c_str() || *end != '\0')
        throw Error(Status::corrupt_file, where + kColumns[c] + ": '" + shown(text) + "' is not a number");
      if (!std::isfinite(value))
        throw Error(Status::corrupt_file, where + kColumns[c] + ": '" + shown(text) + "' is not a finite number");
      if (value < lo || value > hi) {
        std::ostringstream msg;
        msg << where << kColumns[c] << ": " << shown(text) << " outside [" << lo << ", " << hi << "]";
        throw Error(Status::corrupt_file, msg.str());
      }
      return value;
    };
    const std::string_view id = fields[column_of[0]];
    if (id.empty()) throw Error(Status::corrupt_file, where + "id: empty");
    const std::string problem = printable_utf8_problem(id);  // ids travel into truth (JSON, FITS)
    if (!problem.empty()) throw Error(Status::corrupt_file, where + "id: " + problem);
    CatalogStar s;
    const double ra_deg = number(1, 0.0, 360.0);
    if (ra_deg >= 360.0) throw Error(Status::corrupt_file, where + "ra_deg: must be < 360");
    s.ra_rad = ra_deg * constants::rad_per_deg;
    s.dec_rad = number(2, -90.0, 90.0) * constants::rad_per_deg;
    s.pm_ra_cosdec_mas_per_yr = number(3, -kMaxProperMotion_mas_yr, kMaxProperMotion_mas_yr);
    s.pm_dec_mas_per_yr = number(4, -kMaxProperMotion_mas_yr, kMaxProperMotion_mas_yr);
    s.parallax_mas = number(5, 0.0, kMaxParallax_mas);
    s.v_mag = number(6, kMinVMag, kMaxVMag);
    s.b_v_mag = number(7, kMinBV, kMaxBV);
    s.id.assign(id);
    catalogue.stars.push_back(std::move(s));
    line_of_star.push_back(static_cast<std::uint32_t>(line_number));
  });
  if (!have_header) throw Error(Status::corrupt_file, path + ":1: header: no header line (id,ra_deg,dec_deg,...)");

  // Duplicate ids: the first line that repeats an earlier one.
  const std::vector<CatalogStar>& stars = catalogue.stars;
  std::vector<std::uint32_t> order(stars.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<std::uint32_t>(i);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    const int c = stars[a].id.compare(stars[b].id);
    return c != 0 ? c < 0 : a < b;
  });
  std::size_t repeat = stars.size(), first = 0;
  for (std::size_t k = 1, group = 0; k < order.size(); ++k) {
    if (stars[order[k]].id != stars[order[group]].id) {
      group = k;  // the earliest star of the next id
    } else if (k == group + 1 && order[k] < repeat) {
      repeat = order[k];
      first = order[group];
    }
  }
  if (repeat < stars.size())
    throw Error(Status::corrupt_file, path + ":" + std::to_string(line_of_star[repeat]) + ": id: '" +
                                          shown(stars[repeat].id) + "' duplicates line " +
                                          std::to_string(line_of_star[first]));
  catalogue.count = catalogue.stars.size();
  index_stars(catalogue.stars, catalogue.cells, catalogue.by_cell, catalogue.cell_start_owned, catalogue.sorted_v,
              catalogue.cumulative_v0, catalogue.brightest_v_mag, catalogue.faintest_v_mag,
              catalogue.max_proper_motion_mas_yr);
  catalogue.cell_start = catalogue.cell_start_owned.data();
  auto data = std::make_shared<Data>(std::move(catalogue));
  data->cell_start = data->cell_start_owned.data();  // (the vector moved: point at its new home)
  return StarCatalog(std::move(data), epoch_julian_year);
}

namespace {

void warn_past_catalogue(const StarCatalog& c, StarSelection& selection) {
  // Magnitudes are given to 0.01 mag: a limit within kCatalogueCutTolerance
  // of the faintest star is the catalogue's own cut (V <= 10.5 for
  // Hipparcos/Tycho-2).
  if (c.size() == 0 || selection.limiting_v_mag > c.faintest_v_mag() + kCatalogueCutTolerance_mag) {
    selection.limit_beyond_catalogue = true;
    std::ostringstream msg;
    msg << "limiting_v_mag: " << selection.limiting_v_mag
        << " is fainter than the faintest star of the catalogue (V = " << c.faintest_v_mag()
        << "); stars between the two are missing from the scene";
    selection.warning = msg.str();
  }
}

}  // namespace

StarSelection StarCatalog::select_brighter_than(double limiting_v_mag) const {
  if (std::isnan(limiting_v_mag)) throw Error(Status::out_of_range, "limiting_v_mag: NaN");
  StarSelection selection;
  selection.limiting_v_mag = limiting_v_mag;
  const Data& d = *data_;
  for (std::uint32_t c = 0; c < d.cells.count(); ++c)
    for (std::uint32_t slot = d.cell_start[c]; slot < d.cell_start[c + 1]; ++slot) {
      const std::size_t i = d.slot_star(slot);
      if (d.v_at(i) > limiting_v_mag) break;  // (V order within a cell)
      selection.indices.push_back(i);
    }
  warn_past_catalogue(*this, selection);
  return selection;
}

StarSelection StarCatalog::select_in_cone(const Vec3& axis, double radius_rad, double limiting_v_mag) const {
  if (std::isnan(limiting_v_mag)) throw Error(Status::out_of_range, "limiting_v_mag: NaN");
  if (!(radius_rad >= 0.0 && radius_rad <= constants::pi))
    throw Error(Status::out_of_range, "star query: radius_rad must be in [0, pi]");
  if (!axis.allFinite() || !(axis.norm() > 0.0)) throw Error(Status::out_of_range, "star query: axis not a direction");
  StarSelection selection;
  selection.limiting_v_mag = limiting_v_mag;
  const Data& d = *data_;
  d.cells.for_each_cell_in_cone(axis.normalized(), radius_rad, [&](std::uint32_t c) {
    for (std::uint32_t slot = d.cell_start[c]; slot < d.cell_start[c + 1]; ++slot) {
      const std::size_t i = d.slot_star(slot);
      if (d.v_at(i) > limiting_v_mag) break;
      selection.indices.push_back(i);
    }
  });
  warn_past_catalogue(*this, selection);
  return selection;
}

double StarCatalog::v0_equivalent_stars(double limiting_v_mag) const {
  if (std::isnan(limiting_v_mag)) throw Error(Status::out_of_range, "limiting_v_mag: NaN");
  const Data& d = *data_;
  if (!d.records) {
    const auto n = std::upper_bound(d.sorted_v.begin(), d.sorted_v.end(), limiting_v_mag) - d.sorted_v.begin();
    return d.cumulative_v0[static_cast<std::size_t>(n)];
  }
  if (d.flux_table.empty()) return 0.0;
  const double x = (limiting_v_mag - kFluxFirstMag) / kFluxStepMag;
  if (x <= 0) return x < 0 ? 0.0 : d.flux_table.front();
  const double last = static_cast<double>(d.flux_table.size() - 1);
  if (x >= last) return d.flux_table.back();
  const auto k = static_cast<std::size_t>(x);
  return d.flux_table[k] + (x - static_cast<double>(k)) * (d.flux_table[k + 1] - d.flux_table[k]);
}

ApparentPlaceContext apparent_place_context_geocentric(const EngineTime& t, const Vec3& geocentric_position_m,
                                                       const Vec3& geocentric_velocity_m_per_s,
                                                       double catalogue_epoch_julian_year) {
  require_finite_vec(geocentric_position_m, "observer.geocentric_position_m");
  require_finite_vec(geocentric_velocity_m_per_s, "observer.geocentric_velocity_m_per_s");
  require_finite(catalogue_epoch_julian_year, "star_catalogue.epoch_julian_year");
  const JulianDate tdb = t.to(TimeScale::tdb);
  double pv[2][3];
  for (int k = 0; k < 3; ++k) {
    pv[0][k] = geocentric_position_m[k];
    pv[1][k] = geocentric_velocity_m_per_s[k];
  }
  eraASTROM astrom;
  eraApcs13(tdb.jd1, tdb.jd2, pv, &astrom);
  return context_from_astrom(astrom, t, catalogue_epoch_julian_year);
}

ApparentPlaceContext apparent_place_context_barycentric(const EngineTime& t, const Vec3& barycentric_position_m,
                                                        const Vec3& barycentric_velocity_m_per_s,
                                                        const Vec3& heliocentric_position_m,
                                                        double catalogue_epoch_julian_year) {
  require_finite_vec(barycentric_position_m, "observer.barycentric_position_m");
  require_finite_vec(barycentric_velocity_m_per_s, "observer.barycentric_velocity_m_per_s");
  require_finite_vec(heliocentric_position_m, "observer.heliocentric_position_m");
  require_finite(catalogue_epoch_julian_year, "star_catalogue.epoch_julian_year");
  const double sun_distance_m = heliocentric_position_m.norm();
  if (!(sun_distance_m > 0.0)) throw Error(Status::out_of_range, "observer.heliocentric_position_m: zero");
  // eraApcs with a zero geocentric offset and the observer as "Earth".
  const JulianDate tdb = t.to(TimeScale::tdb);
  double pv[2][3] = {{0, 0, 0}, {0, 0, 0}};
  double ebpv[2][3], ehp[3];
  for (int k = 0; k < 3; ++k) {
    ebpv[0][k] = barycentric_position_m[k] / kMetresPerAu;
    ebpv[1][k] = barycentric_velocity_m_per_s[k] * kSecondsPerDay / kMetresPerAu;
    ehp[k] = heliocentric_position_m[k] / kMetresPerAu;
  }
  eraASTROM astrom;
  eraApcs(tdb.jd1, tdb.jd2, pv, ebpv, ehp, &astrom);
  if (!(astrom.bm1 > 0.0)) throw Error(Status::out_of_range, "observer.barycentric_velocity_m_per_s: not below c");
  return context_from_astrom(astrom, t, catalogue_epoch_julian_year);
}

Vec3 apparent_direction(const CatalogStar& star, const ApparentPlaceContext& c, const ApparentPlaceOptions& options) {
  // Space motion and parallax (eraPmpx takes d(alpha)/dt, not mu_alpha*).
  const double cos_dec = std::cos(star.dec_rad);
  const double pm_ra_rad_per_yr =
      cos_dec > 0.0 ? star.pm_ra_cosdec_mas_per_yr * kMasToRad / cos_dec : 0.0;
  const double pm_dec_rad_per_yr = star.pm_dec_mas_per_yr * kMasToRad;
  const double years = options.proper_motion ? c.proper_motion_years : 0.0;
  double observer_au[3] = {0.0, 0.0, 0.0};
  if (options.parallax)
    for (int k = 0; k < 3; ++k) observer_au[k] = c.barycentric_position_au[k];
  double coordinate_direction[3];
  eraPmpx(star.ra_rad, star.dec_rad, options.proper_motion ? pm_ra_rad_per_yr : 0.0,
          options.proper_motion ? pm_dec_rad_per_yr : 0.0, star.parallax_mas * 1.0e-3, 0.0, years, observer_au,
          coordinate_direction);
  double natural_direction[3] = {coordinate_direction[0], coordinate_direction[1], coordinate_direction[2]};
  if (options.light_deflection) {
    double e[3] = {c.sun_to_observer_unit[0], c.sun_to_observer_unit[1], c.sun_to_observer_unit[2]};
    eraLdsun(coordinate_direction, e, c.sun_distance_au, natural_direction);
  }
  if (!options.aberration) return Vec3(natural_direction[0], natural_direction[1], natural_direction[2]);
  double v[3] = {c.barycentric_velocity_over_c[0], c.barycentric_velocity_over_c[1], c.barycentric_velocity_over_c[2]};
  double proper_direction[3];
  eraAb(natural_direction, v, c.sun_distance_au, c.inverse_lorentz_factor, proper_direction);
  return Vec3(proper_direction[0], proper_direction[1], proper_direction[2]).normalized();
}

void apparent_directions(const StarCatalog& catalogue, const std::vector<std::size_t>& indices,
                         const ApparentPlaceContext& context, std::vector<Vec3>& out,
                         const ApparentPlaceOptions& options) {
  const auto& stars = catalogue.stars();
  out.resize(indices.size());
  for (std::size_t i = 0; i < indices.size(); ++i) {
    if (indices[i] >= stars.size()) throw Error(Status::out_of_range, "star index: beyond the catalogue");
    out[i] = apparent_direction(stars[indices[i]], context, options);
  }
}

}  // namespace eoir::universe

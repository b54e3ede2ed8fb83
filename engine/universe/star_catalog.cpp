#include "universe/star_catalog.hpp"

#include <erfa.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

#include "core/constants.hpp"
#include "core/error.hpp"

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

// Binary layout (data/stars/README.md), little-endian.
constexpr char kMagic[8] = {'E', 'O', 'I', 'R', 'S', 'T', 'A', 'R'};
constexpr std::uint32_t kFormatVersion = 1;
constexpr std::size_t kFixedHeaderBytes = 56;
constexpr std::size_t kRecordBytes = 48;
constexpr std::uint32_t kNoName = 0xFFFFFFFFu;

template <typename T>
T read_le(const char* p) {
  T value;
  std::memcpy(&value, p, sizeof(T));
  return value;
}

[[noreturn]] void corrupt(const std::string& path, const std::string& what) {
  throw Error(Status::corrupt_file, path + ": " + what);
}

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  for (;;) {
    const auto comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return fields;
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

void StarCatalog::finish() {
  brightest_v_mag_ = faintest_v_mag_ = 0.0;
  if (!stars_.empty()) {
    const auto [lo, hi] = std::minmax_element(stars_.begin(), stars_.end(), [](const CatalogStar& a,
                                                                             const CatalogStar& b) {
      return a.v_mag < b.v_mag;
    });
    brightest_v_mag_ = lo->v_mag;
    faintest_v_mag_ = hi->v_mag;
  }
  sorted_by_v_ = std::is_sorted(stars_.begin(), stars_.end(),
                                [](const CatalogStar& a, const CatalogStar& b) { return a.v_mag < b.v_mag; });
  unit_vectors_.resize(stars_.size());
  max_proper_motion_mas_yr_ = 0.0;
  for (std::size_t i = 0; i < stars_.size(); ++i) {
    const CatalogStar& s = stars_[i];
    unit_vectors_[i] = Vec3(std::cos(s.dec_rad) * std::cos(s.ra_rad), std::cos(s.dec_rad) * std::sin(s.ra_rad),
                            std::sin(s.dec_rad));
    max_proper_motion_mas_yr_ =
        std::max(max_proper_motion_mas_yr_, std::hypot(s.pm_ra_cosdec_mas_per_yr, s.pm_dec_mas_per_yr));
  }
}

StarCatalog StarCatalog::load_binary(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(Status::io, path + ": cannot open the star catalogue");
  in.seekg(0, std::ios::end);
  const auto file_bytes = static_cast<std::size_t>(in.tellg());
  in.seekg(0, std::ios::beg);
  std::vector<char> bytes(file_bytes);
  if (file_bytes > 0 && !in.read(bytes.data(), static_cast<std::streamsize>(file_bytes)))
    throw Error(Status::io, path + ": read failed");

  if (file_bytes < kFixedHeaderBytes) corrupt(path, "header: file shorter than the 56-byte header");
  const char* p = bytes.data();
  if (std::memcmp(p, kMagic, sizeof kMagic) != 0) corrupt(path, "magic: not an EOIRSTAR file");
  const auto version = read_le<std::uint32_t>(p + 8);
  if (version != kFormatVersion)
    throw Error(Status::file_version, path + ": format_version: " + std::to_string(version) + " (expected " +
                                          std::to_string(kFormatVersion) + ")");
  const auto header_bytes = read_le<std::uint32_t>(p + 12);
  const auto count = read_le<std::uint32_t>(p + 16);
  const auto record_bytes = read_le<std::uint32_t>(p + 20);
  const auto epoch = read_le<double>(p + 24);
  const auto source_bytes = read_le<std::uint32_t>(p + 48);
  const auto names_bytes = read_le<std::uint32_t>(p + 52);
  if (record_bytes != kRecordBytes) corrupt(path, "record_bytes: " + std::to_string(record_bytes) + " (expected 48)");
  if (header_bytes < kFixedHeaderBytes + source_bytes || header_bytes > file_bytes)
    corrupt(path, "header_bytes: inconsistent with source_text_bytes or the file size");
  if (!std::isfinite(epoch)) corrupt(path, "epoch_julian_year: not finite");
  const std::size_t needed = std::size_t{header_bytes} + std::size_t{count} * kRecordBytes + names_bytes;
  if (needed != file_bytes)
    corrupt(path, "star_count: " + std::to_string(count) + " records and " + std::to_string(names_bytes) +
                      " name bytes need " + std::to_string(needed) + " bytes, the file has " +
                      std::to_string(file_bytes));

  StarCatalog catalogue;
  catalogue.epoch_julian_year_ = epoch;
  catalogue.source_.assign(p + kFixedHeaderBytes, source_bytes);
  const char* names = p + header_bytes + std::size_t{count} * kRecordBytes;
  catalogue.stars_.resize(count);
  char id[16] = {'H', 'T'};
  for (std::uint32_t i = 0; i < count; ++i) {
    const char* r = p + header_bytes + std::size_t{i} * kRecordBytes;
    CatalogStar& s = catalogue.stars_[i];
    s.ra_rad = read_le<double>(r + 0);
    s.dec_rad = read_le<double>(r + 8);
    s.pm_ra_cosdec_mas_per_yr = read_le<float>(r + 16);
    s.pm_dec_mas_per_yr = read_le<float>(r + 20);
    s.parallax_mas = read_le<float>(r + 24);
    s.v_mag = read_le<float>(r + 28);
    s.b_v_mag = read_le<float>(r + 32);
    const auto number = read_le<std::uint32_t>(r + 40);
    const auto name_offset = read_le<std::uint32_t>(r + 44);
    // Integer to text without allocation beyond the small-string buffer.
    int n = 0;
    char digits[12];
    std::uint32_t v = number;
    do {
      digits[n++] = static_cast<char>('0' + v % 10);
      v /= 10;
    } while (v != 0);
    for (int k = 0; k < n; ++k) id[2 + k] = digits[n - 1 - k];
    s.id.assign(id, static_cast<std::size_t>(2 + n));
    if (name_offset != kNoName) {
      if (name_offset >= names_bytes) corrupt(path, "record " + std::to_string(i) + ": name_offset out of range");
      const char* start = names + name_offset;
      const void* end = std::memchr(start, '\0', names_bytes - name_offset);
      if (end == nullptr) corrupt(path, "record " + std::to_string(i) + ": name not terminated");
      s.name.assign(start, static_cast<const char*>(end));
    }
    if (!std::isfinite(s.ra_rad) || !std::isfinite(s.dec_rad) || !std::isfinite(s.v_mag) ||
        !std::isfinite(s.b_v_mag) || !std::isfinite(s.parallax_mas) || !std::isfinite(s.pm_ra_cosdec_mas_per_yr) ||
        !std::isfinite(s.pm_dec_mas_per_yr))
      corrupt(path, "record " + std::to_string(i) + ": non-finite value");
  }
  catalogue.finish();
  return catalogue;
}

StarCatalog StarCatalog::load_csv(const std::string& path, double epoch_julian_year) {
  require_finite(epoch_julian_year, "star_catalogue.epoch_julian_year");
  std::ifstream in(path);
  if (!in) throw Error(Status::io, path + ": cannot open the star catalogue");

  static const char* const kColumns[] = {"id",           "ra_deg",  "dec_deg", "pm_ra_mas_yr", "pm_dec_mas_yr",
                                         "parallax_mas", "v_mag",   "b_v"};
  constexpr std::size_t kColumnCount = sizeof kColumns / sizeof kColumns[0];
  std::size_t column_of[kColumnCount];
  std::size_t header_fields = 0;
  bool have_header = false;

  StarCatalog catalogue;
  catalogue.epoch_julian_year_ = epoch_julian_year;
  catalogue.source_ = path;
  std::unordered_map<std::string, long> first_line_of_id;
  std::string line;
  long line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string content = trim(line);
    if (content.empty() || content[0] == '#') continue;
    const std::string where = path + ":" + std::to_string(line_number) + ": ";
    const auto fields = split_commas(content);
    if (!have_header) {
      header_fields = fields.size();
      for (std::size_t c = 0; c < kColumnCount; ++c) {
        const auto it = std::find(fields.begin(), fields.end(), kColumns[c]);
        if (it == fields.end())
          throw Error(Status::corrupt_file, where + kColumns[c] + ": missing column in the header line");
        column_of[c] = static_cast<std::size_t>(it - fields.begin());
      }
      have_header = true;
      continue;
    }
    if (fields.size() != header_fields)
      throw Error(Status::corrupt_file, where + "line: " + std::to_string(fields.size()) + " fields, the header has " +
                                            std::to_string(header_fields));
    auto number = [&](std::size_t c, double lo, double hi) {
      const std::string& text = fields[column_of[c]];
      if (text.empty()) throw Error(Status::corrupt_file, where + kColumns[c] + ": empty");
      char* end = nullptr;
      errno = 0;
      const double value = std::strtod(text.c_str(), &end);
      if (end == text.c_str() || *end != '\0' || errno == ERANGE)
        throw Error(Status::corrupt_file, where + kColumns[c] + ": '" + text + "' is not a number");
      if (!std::isfinite(value))
        throw Error(Status::corrupt_file, where + kColumns[c] + ": '" + text + "' is not a finite number");
      if (value < lo || value > hi) {
        std::ostringstream msg;
        msg << where << kColumns[c] << ": " << text << " outside [" << lo << ", " << hi << "]";
        throw Error(Status::corrupt_file, msg.str());
      }
      return value;
    };
    CatalogStar s;
    s.id = fields[column_of[0]];
    if (s.id.empty()) throw Error(Status::corrupt_file, where + "id: empty");
    const auto [it, inserted] = first_line_of_id.emplace(s.id, line_number);
    if (!inserted)
      throw Error(Status::corrupt_file,
                  where + "id: '" + s.id + "' duplicates line " + std::to_string(it->second));
    const double ra_deg = number(1, 0.0, 360.0);
    if (ra_deg >= 360.0) throw Error(Status::corrupt_file, where + "ra_deg: must be < 360");
    s.ra_rad = ra_deg * constants::rad_per_deg;
    s.dec_rad = number(2, -90.0, 90.0) * constants::rad_per_deg;
    s.pm_ra_cosdec_mas_per_yr = number(3, -kMaxProperMotion_mas_yr, kMaxProperMotion_mas_yr);
    s.pm_dec_mas_per_yr = number(4, -kMaxProperMotion_mas_yr, kMaxProperMotion_mas_yr);
    s.parallax_mas = number(5, 0.0, kMaxParallax_mas);
    s.v_mag = number(6, kMinVMag, kMaxVMag);
    s.b_v_mag = number(7, kMinBV, kMaxBV);
    catalogue.stars_.push_back(std::move(s));
  }
  if (!have_header) throw Error(Status::corrupt_file, path + ":1: header: no header line (id,ra_deg,dec_deg,...)");
  catalogue.finish();
  return catalogue;
}

StarSelection StarCatalog::select_brighter_than(double limiting_v_mag) const {
  if (std::isnan(limiting_v_mag)) throw Error(Status::out_of_range, "limiting_v_mag: NaN");
  StarSelection selection;
  selection.limiting_v_mag = limiting_v_mag;
  if (sorted_by_v_) {
    const auto end = std::upper_bound(stars_.begin(), stars_.end(), limiting_v_mag,
                                      [](double v, const CatalogStar& s) { return v < s.v_mag; });
    selection.indices.resize(static_cast<std::size_t>(end - stars_.begin()));
    for (std::size_t i = 0; i < selection.indices.size(); ++i) selection.indices[i] = i;
  } else {
    for (std::size_t i = 0; i < stars_.size(); ++i)
      if (stars_[i].v_mag <= limiting_v_mag) selection.indices.push_back(i);
  }
  // Magnitudes are given to 0.01 mag: a limit within kCatalogueCutTolerance
  // of the faintest star is the catalogue's own cut (V <= 9 for Hipparcos/Tycho).
  if (stars_.empty() || limiting_v_mag > faintest_v_mag_ + kCatalogueCutTolerance_mag) {
    selection.limit_beyond_catalogue = true;
    std::ostringstream msg;
    msg << "limiting_v_mag: " << limiting_v_mag << " is fainter than the faintest star of the catalogue (V = "
        << faintest_v_mag_ << "); stars between the two are missing from the scene";
    selection.warning = msg.str();
  }
  return selection;
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

// Star catalogue and apparent places of stars (spec 4.3.2, 4.1.6.1).
//
// Two sources:
//  - the converted Hipparcos/Tycho-2 catalogue to V = 10.5 (data/stars/
//    README.md: binary format v2, ICRS positions at epoch J2000.0), opened
//    with load_binary(): the file is mapped read-only and read where a query
//    touches it (opening costs a few system calls and the check of its
//    header and cell table; tests/bench/bench_stars.cpp measures it);
//  - a user catalogue in CSV, loaded with load_csv(). Columns (header line
//    required, any order, extra columns ignored, '#' comments and blank lines
//    skipped):
//      id             text, unique, no comma, valid UTF-8 without control
//                     characters (a truth row gives its first 63 bytes,
//                     cut at a character boundary)
//      ra_deg         ICRS right ascension at the epoch, [0, 360)
//      dec_deg        ICRS declination at the epoch, [-90, 90]
//      pm_ra_mas_yr   mu_alpha* = mu_alpha cos(delta) [mas/yr] (as Hipparcos
//                     and Gaia give it; NOT d(alpha)/dt)
//      pm_dec_mas_yr  mu_delta [mas/yr]
//      parallax_mas   [0, 1e4] (0 = unknown / infinitely far)
//      v_mag          Johnson V, [kMinVMag, kMaxVMag]
//      b_v            Johnson B-V, [kMinBV, kMaxBV]
//    |proper motion| components at most kMaxProperMotion_mas_yr.
//    Bad input throws eoir::Error(Status::corrupt_file, "file:line: field: why").
//    Bounds: at most kMaxCsvColumns columns and kMaxCsvStars stars in a file
//    of at most 256 MiB; loading holds the file and about 160 bytes per star
//    (at least 16 bytes of file each): at most about 11 times the file size.
//
// Sky cells: both kinds are indexed by the same cells (1-degree declination
// bands, each cut into max(1, round(360 cos(dec_mid))) equal cells of right
// ascension: 41,252 cells of about one square degree), the stars of a cell
// in V order, so that select_in_cone() reads only the cells a field meets
// and, in each, only the stars brighter than the limit.
//
// Apparent place (the direction in which the observer sees the star, in the
// engine's geocentric J2000 = GCRS axes) follows ERFA's astrometry chain for
// an observer in space (eraApcs / eraAtciq, SOFA "Astrometry Tools"): space
// motion and annual + orbital parallax (eraPmpx), light deflection by the Sun
// (eraLdsun, optional) and stellar aberration from the observer's total
// barycentric velocity, Earth's orbital velocity plus the observer's own
// velocity relative to the Earth (eraAb, relativistic). Radial velocity is not
// in the catalogues and is taken as zero (perspective acceleration neglected:
// 0.06" in 10 yr for Barnard's star).
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/time.hpp"

namespace eoir::universe {

using Vec3 = Eigen::Vector3d;

// Validation ranges of user catalogues.
constexpr double kMinVMag = -30.0;
constexpr double kMaxVMag = 30.0;
constexpr double kMinBV = -1.0;
constexpr double kMaxBV = 6.0;
constexpr double kMaxParallax_mas = 1.0e4;
constexpr double kMaxProperMotion_mas_yr = 1.0e5;
// A limiting magnitude up to this much fainter than the catalogue's faintest
// star is not reported as beyond the catalogue (magnitudes are given to 0.01).
constexpr double kCatalogueCutTolerance_mag = 0.05;
// Bounds of user catalogues (CSV).
constexpr std::size_t kMaxCsvColumns = 1024;
constexpr std::size_t kMaxCsvStars = 4000000;

struct CatalogStar {
  std::string id;                        // converted catalogue: "HIP<n>" (Stellarium's Hipparcos stars) or
                                         // "HT<n>" (n = rank in V); user id otherwise
  double ra_rad = 0.0;                   // ICRS, at the catalogue epoch
  double dec_rad = 0.0;                  // ICRS, at the catalogue epoch
  double pm_ra_cosdec_mas_per_yr = 0.0;  // mu_alpha* = mu_alpha cos(delta)
  double pm_dec_mas_per_yr = 0.0;        // mu_delta
  double parallax_mas = 0.0;
  double v_mag = 0.0;    // Johnson V
  double b_v_mag = 0.0;  // Johnson B-V
  std::string name;      // "genitive|common" (e.g. "bet Gem|Pollux"); may be empty
};

// Result of a selection by limiting magnitude. When the limit is fainter than
// the faintest star of the catalogue, the catalogue cannot deliver the stars
// asked for: limit_beyond_catalogue is set and warning says so, for the
// caller to surface (the selection itself is still every star).
struct StarSelection {
  std::vector<std::size_t> indices;  // into the catalogue (star(i)), in cell order, V order within a cell
  double limiting_v_mag = 0.0;
  bool limit_beyond_catalogue = false;
  std::string warning;
};

// The sky cells (see the top of this file).
struct SkyCells {
  static constexpr double band_deg = 1.0;
  static constexpr int bands = 180;
  std::vector<std::uint32_t> band_first;  // first cell of each band (south to north), bands + 1 entries
  SkyCells();
  std::uint32_t count() const { return band_first.back(); }
  std::uint32_t cells_in_band(int band) const { return band_first[band + 1] - band_first[band]; }
  std::uint32_t cell_of(double ra_rad, double dec_rad) const;
  // Calls cell(c) for every cell that may hold a direction within radius_rad
  // of the unit vector `axis` (a superset: whole cells).
  template <class F>
  void for_each_cell_in_cone(const Vec3& axis, double radius_rad, F&& cell) const;
};

class StarCatalog {
 public:
  // The converted catalogue (data/stars/README.md), mapped. Throws
  // eoir::Error(io) if unreadable, (corrupt_file) / (file_version) naming
  // the file and field if its header or cell table is malformed; a record
  // is checked where it is read (star(): corrupt_file naming the record).
  static StarCatalog load_binary(const std::string& path);
  // A user catalogue (see the top of this file). epoch_julian_year is the
  // epoch of its positions (TDB Julian year, e.g. 2000.0 or 2016.0 for Gaia
  // DR3).
  static StarCatalog load_csv(const std::string& path, double epoch_julian_year = 2000.0);

  // The same stars with their positions at another epoch; shares the stars
  // (no copy).
  StarCatalog at_epoch(double epoch_julian_year) const;
  bool shares_stars_with(const StarCatalog& other) const { return data_ == other.data_; }

  std::size_t size() const;
  // Star i (binary: made from its record on each call). Throws
  // out_of_range past the end, corrupt_file for a malformed record.
  CatalogStar star(std::size_t i) const;
  // Its catalogue position (ICRS, at the epoch) as a unit vector, and its V.
  Vec3 unit_vector(std::size_t i) const;
  double v_mag(std::size_t i) const;
  // Every star, by value (for whole-catalogue walks and tests).
  class StarsView {
   public:
    explicit StarsView(const StarCatalog* c) : c_(c) {}
    CatalogStar operator[](std::size_t i) const { return c_->star(i); }
    std::size_t size() const { return c_->size(); }
    CatalogStar front() const { return c_->star(0); }
    struct iterator {
      const StarCatalog* c;
      std::size_t i;
      CatalogStar operator*() const { return c->star(i); }
      iterator& operator++() {
        ++i;
        return *this;
      }
      bool operator!=(const iterator& o) const { return i != o.i; }
    };
    iterator begin() const { return {c_, 0}; }
    iterator end() const { return {c_, c_->size()}; }

   private:
    const StarCatalog* c_;
  };
  StarsView stars() const { return StarsView(this); }
  // Epoch of positions and origin of proper motion [TDB Julian year].
  double epoch_julian_year() const { return epoch_julian_year_; }
  // Where the data came from (the binary header's source text, or the CSV path).
  const std::string& source() const;
  double brightest_v_mag() const;
  double faintest_v_mag() const;
  // The largest total proper motion of the catalogue [mas/yr].
  double max_proper_motion_mas_yr() const;

  // All stars with V <= limiting_v_mag. Throws out_of_range for NaN.
  StarSelection select_brighter_than(double limiting_v_mag) const;
  // The stars with V <= limiting_v_mag of the sky cells that meet the cone
  // of radius_rad about the unit vector axis (catalogue positions: widen the
  // radius by what moves them). Throws out_of_range for NaN or a radius
  // outside [0, pi].
  StarSelection select_in_cone(const Vec3& axis, double radius_rad, double limiting_v_mag) const;
  // Integrated starlight of the catalogue (spec 4.1.4): the number of V = 0
  // stars whose light equals that of its stars with V <= limiting_v_mag,
  // sum of 10^(-0.4 V) (binary: its table per 0.1 mag, interpolated).
  double v0_equivalent_stars(double limiting_v_mag) const;

 private:
  struct Data;
  StarCatalog(std::shared_ptr<const Data> data, double epoch_julian_year)
      : data_(std::move(data)), epoch_julian_year_(epoch_julian_year) {}
  std::shared_ptr<const Data> data_;
  double epoch_julian_year_ = 2000.0;
};

template <class F>
void SkyCells::for_each_cell_in_cone(const Vec3& axis, double radius_rad, F&& cell) const {
  constexpr double kDeg = 0.017453292519943295;
  const double dec0 = std::asin(std::clamp(axis.z(), -1.0, 1.0)) / kDeg;
  double ra0 = std::atan2(axis.y(), axis.x());
  if (ra0 < 0) ra0 += 2.0 * 3.141592653589793;
  const double r_deg = radius_rad / kDeg, lo = dec0 - r_deg, hi = dec0 + r_deg;
  const int b_lo = std::clamp(static_cast<int>(std::floor((lo + 90.0) / band_deg)), 0, bands - 1);
  const int b_hi = std::clamp(static_cast<int>(std::floor((hi + 90.0) / band_deg)), 0, bands - 1);
  for (int b = b_lo; b <= b_hi; ++b) {
    const std::uint32_t n = cells_in_band(b), first = band_first[b];
    const double band_lo = -90.0 + b * band_deg, band_hi = band_lo + band_deg;
    // The largest |dec| of the band inside the cone's declinations: there a
    // point of the cone strays furthest in right ascension,
    // sin|d ra| <= sin r / cos dec.
    const double d_max = std::max(std::fabs(std::max(band_lo, lo)), std::fabs(std::min(band_hi, hi)));
    const double s = std::sin(std::min(radius_rad, 1.5707963267948966)) / std::cos(d_max * kDeg);
    const bool all = n == 1 || hi >= 90.0 || lo <= -90.0 || radius_rad >= 1.5707963267948966 || s >= 1.0;
    if (all) {
      for (std::uint32_t k = 0; k < n; ++k) cell(first + k);
      continue;
    }
    const double half = std::asin(s), per_cell = 2.0 * 3.141592653589793 / n;
    const auto k_lo = static_cast<long>(std::floor((ra0 - half) / per_cell));
    const auto k_hi = static_cast<long>(std::floor((ra0 + half) / per_cell));
    if (k_hi - k_lo + 1 >= static_cast<long>(n)) {
      for (std::uint32_t k = 0; k < n; ++k) cell(first + k);
      continue;
    }
    for (long k = k_lo; k <= k_hi; ++k) cell(first + static_cast<std::uint32_t>(((k % static_cast<long>(n)) + n) % n));
  }
}

// The observer-dependent part of the apparent-place chain for one instant
// (ERFA's eraASTROM restricted to what stars need); build once per frame.
struct ApparentPlaceContext {
  double proper_motion_years = 0.0;        // TDB Julian years since the catalogue epoch
  Vec3 barycentric_position_au = Vec3::Zero();  // observer, BCRS (GCRS axes)
  Vec3 sun_to_observer_unit = Vec3::UnitX();    // heliocentric direction of the observer
  double sun_distance_au = 1.0;
  Vec3 barycentric_velocity_over_c = Vec3::Zero();  // observer velocity / c
  double inverse_lorentz_factor = 1.0;              // sqrt(1 - |v/c|^2)
};

// Observer given geocentrically (GCRS position [m] and velocity [m/s], e.g. a
// satellite; zeros = the geocentre); the Earth's barycentric and heliocentric
// state comes from ERFA's eraEpv00 (via eraApcs13) at t (TDB).
ApparentPlaceContext apparent_place_context_geocentric(const EngineTime& t, const Vec3& geocentric_position_m,
                                                       const Vec3& geocentric_velocity_m_per_s,
                                                       double catalogue_epoch_julian_year = 2000.0);
// Observer given barycentrically (BCRS position [m], velocity [m/s]) with its
// heliocentric position [m] (for light deflection).
ApparentPlaceContext apparent_place_context_barycentric(const EngineTime& t, const Vec3& barycentric_position_m,
                                                        const Vec3& barycentric_velocity_m_per_s,
                                                        const Vec3& heliocentric_position_m,
                                                        double catalogue_epoch_julian_year = 2000.0);

struct ApparentPlaceOptions {
  bool proper_motion = true;
  bool parallax = true;
  bool light_deflection = true;  // by the Sun (1.75" at the limb, 4 mas at 90 deg)
  bool aberration = true;
};

// Unit vector towards the star's apparent place, GCRS (geocentric J2000) axes.
Vec3 apparent_direction(const CatalogStar& star, const ApparentPlaceContext& context,
                        const ApparentPlaceOptions& options = {});
// The same for many stars: out[i] for catalogue.stars()[indices[i]].
void apparent_directions(const StarCatalog& catalogue, const std::vector<std::size_t>& indices,
                         const ApparentPlaceContext& context, std::vector<Vec3>& out,
                         const ApparentPlaceOptions& options = {});

}  // namespace eoir::universe

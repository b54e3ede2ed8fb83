// Star catalogue and apparent places of stars (spec 4.3.2, 4.1.6.1).
//
// Two sources:
//  - the converted Hipparcos/Tycho catalogue (data/stars/README.md: binary,
//    ICRS positions at epoch J2000.0), loaded with load_binary();
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
//    of at most 256 MiB; loading holds the file and about 150 bytes per star
//    (at least 16 bytes of file each): at most about 11 times the file size.
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
  std::string id;                        // "HT<n>" for the converted catalogue (n = rank in V), user id otherwise
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
  std::vector<std::size_t> indices;  // into StarCatalog::stars(), in catalogue order
  double limiting_v_mag = 0.0;
  bool limit_beyond_catalogue = false;
  std::string warning;
};

class StarCatalog {
 public:
  // The converted catalogue (data/stars/README.md). Throws
  // eoir::Error(io) if unreadable, (corrupt_file) / (file_version) naming
  // the file and field if malformed.
  static StarCatalog load_binary(const std::string& path);
  // A user catalogue (see the top of this file). epoch_julian_year is the
  // epoch of its positions (TDB Julian year, e.g. 2000.0 or 2016.0 for Gaia
  // DR3).
  static StarCatalog load_csv(const std::string& path, double epoch_julian_year = 2000.0);

  // The same stars with their positions at another epoch; shares the stars
  // (no copy).
  StarCatalog at_epoch(double epoch_julian_year) const;

  const std::vector<CatalogStar>& stars() const { return data_->stars; }
  std::size_t size() const { return data_->stars.size(); }
  // Epoch of positions and origin of proper motion [TDB Julian year].
  double epoch_julian_year() const { return epoch_julian_year_; }
  // Where the data came from (the binary header's source text, or the CSV path).
  const std::string& source() const { return data_->source; }
  double brightest_v_mag() const { return data_->brightest_v_mag; }
  double faintest_v_mag() const { return data_->faintest_v_mag; }

  // All stars with V <= limiting_v_mag. Throws out_of_range for NaN.
  StarSelection select_brighter_than(double limiting_v_mag) const;
  // Unit vectors of the catalogue positions (ICRS, at the epoch), for culling.
  const std::vector<Vec3>& unit_vectors() const { return data_->unit_vectors; }
  // The largest total proper motion of the catalogue [mas/yr].
  double max_proper_motion_mas_yr() const { return data_->max_proper_motion_mas_yr; }

 private:
  // Everything but the epoch, shared by the copies at other epochs.
  struct Stars {
    std::vector<CatalogStar> stars;
    std::string source;
    double brightest_v_mag = 0.0;
    double faintest_v_mag = 0.0;
    bool sorted_by_v = false;
    std::vector<Vec3> unit_vectors;
    double max_proper_motion_mas_yr = 0.0;
    void finish();
  };
  StarCatalog(std::shared_ptr<const Stars> data, double epoch_julian_year)
      : data_(std::move(data)), epoch_julian_year_(epoch_julian_year) {}
  std::shared_ptr<const Stars> data_;
  double epoch_julian_year_ = 2000.0;
};

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

// What an engine reads from its data folder (data/README.md) and what the
// user adds to it: materials (spec 4.1.4.1, Appendix A), the table of
// tabulated spectral radiances (4.1.4, the Sun first), the central bodies'
// surface maps (4.2.3), the Earth's surface climatology (4.3.1.3) and the
// predefined composite satellites (4.3.3). Loaded once, when a
// world first needs it; shared read-only by every world built from it.
#pragma once
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "universe/central_bodies.hpp"
#include "universe/material.hpp"
#include "universe/predefined_composites.hpp"
#include "universe/spectrum_table.hpp"
#include "universe/star_catalog.hpp"
#include "universe/surface_climatology.hpp"
#include "universe/surface_map.hpp"

namespace eoir::universe {

// The converted Hipparcos/Tycho-2 catalogue in the data folder (data/stars/).
constexpr const char* kStarCatalogueFile = "stars/hipparcos_tycho2_v10p5.eoirstars";

struct Library {
  std::string data_dir;
  MaterialLibrary materials;
  PredefinedComposites satellites;  // spec 4.3.3, satellites/*.json
  SpectrumTable spectra;
  std::map<CentralBody, BodyMaps> maps;
  std::shared_ptr<const SurfaceClimatology> climatology;
  // Reads data_dir/materials/*.json, satellites/*.json, solar/e490.txt, the map pyramids of
  // earth/ and moon/ (their sidecars and row tables; rows on first use) and
  // the climatology tables (throws io or corrupt_file naming the file).
  static Library load(const std::string& data_dir);
  const BodyMaps* maps_of(CentralBody body) const;

  // A star catalogue, read on first use and kept (thread-safe; shared by the
  // copies of this library): csv_path "" is the data folder's
  // kStarCatalogueFile, else a user CSV whose positions are
  // at epoch_julian_year. Throws io / corrupt_file naming the file and line.
  // One copy of each file's stars serves every epoch; the
  // kCachedStarCatalogues files used last are kept (a catalogue in use stays
  // alive with its users).
  std::shared_ptr<const StarCatalog> star_catalog(const std::string& csv_path = "",
                                                  double epoch_julian_year = 2000.0) const;
  static constexpr std::size_t kCachedStarCatalogues = 4;

 private:
  struct Catalogues {
    std::mutex mutex;
    std::list<std::pair<std::string, std::shared_ptr<const StarCatalog>>> recent;  // most recent first
  };
  std::shared_ptr<Catalogues> catalogues_ = std::make_shared<Catalogues>();
};

}  // namespace eoir::universe

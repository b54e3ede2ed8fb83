#include "universe/library.hpp"

#include <algorithm>
#include <filesystem>

#include "core/error.hpp"

namespace eoir::universe {

Library Library::load(const std::string& data_dir) {
  Library lib;
  lib.data_dir = data_dir;
  lib.spectra = SpectrumTable::load(data_dir);
  const std::string materials = data_dir + "/materials";
  std::error_code ec;
  if (!std::filesystem::is_directory(materials, ec))
    throw Error(Status::io, "data: no materials folder '" + materials + "' (build the data folder: .ci/setup)");
  lib.materials.load_directory(materials);
  lib.satellites.load_directory(data_dir + "/satellites");
  const std::string earth = data_dir + "/earth/", moon = data_dir + "/moon/";
  BodyMaps& e = lib.maps[CentralBody::earth];
  e.land_mask = SurfaceMap::load({earth + "landmask_L0.json", earth + "landmask_L1.json", earth + "landmask_L2.json"});
  e.land_cover =
      SurfaceMap::load({earth + "landcover_L0.json", earth + "landcover_L1.json", earth + "landcover_L2.json"});
  // (optional: a data folder built without them has flat land classes and no clouds)
  std::error_code missing;
  if (std::filesystem::exists(earth + "land_brightness_L0.json", missing))
    e.land_brightness = SurfaceMap::load({earth + "land_brightness_L0.json"});
  if (std::filesystem::exists(earth + "clouds_L0.json", missing)) e.clouds = SurfaceMap::load({earth + "clouds_L0.json"});
  lib.maps[CentralBody::moon].albedo = SurfaceMap::load({moon + "moon_albedo_L0.json", moon + "moon_albedo_L1.json"});
  lib.maps[CentralBody::mars].albedo = SurfaceMap::load({moon + "mars_albedo_L0.json"});
  lib.climatology = std::make_shared<const SurfaceClimatology>(SurfaceClimatology::load(data_dir));
  return lib;
}

std::shared_ptr<const StarCatalog> Library::star_catalog(const std::string& csv_path, double epoch_julian_year) const {
  std::lock_guard<std::mutex> lock(catalogues_->mutex);
  auto& recent = catalogues_->recent;
  auto it = std::find_if(recent.begin(), recent.end(), [&](const auto& entry) { return entry.first == csv_path; });
  if (it != recent.end()) {
    recent.splice(recent.begin(), recent, it);
  } else {
    recent.emplace_front(csv_path, std::make_shared<const StarCatalog>(
                                       csv_path.empty()
                                           ? StarCatalog::load_binary(data_dir + "/" + kStarCatalogueFile)
                                           : StarCatalog::load_csv(csv_path, epoch_julian_year)));
    if (recent.size() > kCachedStarCatalogues) recent.pop_back();
  }
  const std::shared_ptr<const StarCatalog>& cached = recent.front().second;
  // The binary catalogue has its own epoch; a CSV's positions are at the one asked.
  if (csv_path.empty() || cached->epoch_julian_year() == epoch_julian_year) return cached;
  return std::make_shared<const StarCatalog>(cached->at_epoch(epoch_julian_year));
}

const BodyMaps* Library::maps_of(CentralBody body) const {
  auto it = maps.find(body);
  return it == maps.end() ? nullptr : &it->second;
}

}  // namespace eoir::universe

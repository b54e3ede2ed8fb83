#include "scene/cloud_top.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace eoir::scene {

universe::Material cloud_top_material(const universe::MaterialLibrary& materials, double reflectance_550nm,
                                      const std::string& field) {
  const universe::Material* snow = materials.find("fine_snow");
  if (!snow)
    throw Error(Status::unknown_name,
                field + ": the cloud tops take the spectral shape of the material fine_snow, which the data folder "
                        "lacks (data/materials/README.md)");
  const double at_550nm = snow->reflectance(0.55);
  const double scale = at_550nm > 0 ? reflectance_550nm / at_550nm : 0.0;
  std::vector<double> srf = snow->reflectance.values();
  for (double& r : srf) r = std::clamp(r * scale, 0.0, 1.0);
  universe::Material m;
  m.name = "cloud_top";
  m.description = "Cloud tops: fine_snow's SRF scaled to the cloud_reflectance at 0.55 um, backscattering";
  m.reflectance = TabulatedFunction(snow->reflectance.wavelengths_um(), std::move(srf), field);
  m.brdf.k0 = 0.5;   // half Lambertian,
  m.brdf.k1 = 1.0;   // the rest back toward the source
  m.brdf.beta = 0.82;
  m.brdf.alpha = 1.0;  // (the forward lobe has no weight)
  return m;
}

}  // namespace eoir::scene

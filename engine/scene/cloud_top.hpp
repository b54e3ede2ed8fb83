// The material of the Earth's cloud tops (issue 20 item 7; the layer's
// settings: universe/cloud_settings.hpp): the spectral shape of the data
// folder's fine_snow (water ice: clouds of ice and water droplets are bright
// to 1 um, absorb at 1.5 and 2 um and are nearly black in the thermal
// infrared, as fine-grained snow is), scaled to the cloud_reflectance
// property at 0.55 um and capped at 1, and eq. 1's BRDF with a backscatter
// lobe: k0 0.5, k1 1, beta 0.82. The Earth's Bond albedo 0.306 and visual
// geometric albedo 0.367 (Allen's Astrophysical Quantities) give it the
// phase integral q = 0.834: it sends 1.20 x its Bond albedo back toward the
// Sun where a Lambertian sphere sends 2/3 x. Its clouds make most of that
// light; a sphere of this BRDF has p / A = 1.20 (A = SRF: eq. 1 conserves
// the flux; 2 integral of I/F mu dmu at zero phase, by quadrature).
#pragma once
#include <string>

#include "universe/material.hpp"

namespace eoir::scene {

// Throws unknown_name naming `field` if the data folder has no fine_snow.
universe::Material cloud_top_material(const universe::MaterialLibrary& materials, double reflectance_550nm,
                                      const std::string& field);

}  // namespace eoir::scene

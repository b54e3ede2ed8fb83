// The Earth's cloud layer as its central body's properties (issue 20 item
// 7): off by default; on, the cloud fraction of the data folder's cloud map
// (data/earth/README.md, "Clouds") blends, over the surface beneath, a
// reflecting and emitting cloud top at its own height and temperature.
// Read by scene/surface_model (the blend) and scene/world (the cloud top's
// material, scene/cloud_top.hpp).
#pragma once

namespace eoir::universe {

struct CloudSettings {
  bool enabled = false;
  double top_altitude_km = 5.0;       // ISCCP's mean cloud-top pressure, ~550 hPa (US76: 5.0 km)
  double top_temperature_K = 255.7;   // US76 at 5 km
  double reflectance = 0.8;           // SRF at 0.55 um (the spectral shape: scene/cloud_top.hpp)
};

}  // namespace eoir::universe

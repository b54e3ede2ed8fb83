// Composite shapes (spec 4.1.5.1): simple shapes or other composites at
// offsets and orientations, each part with its own surface.
#include <gtest/gtest.h>

#include <cmath>

#include "scenario_host.hpp"

using eoir::test::Image;
using eoir::test::ScenarioHost;

namespace {
// The uniform-source scenario's Satellite2 (1000 km ahead) made a composite:
// a 100 km sphere at 300 K on the left (body +x) and, nested and rotated,
// a 60 km sphere at 200 K on the right.
void make_composite(nlohmann::json& doc) {
  for (auto& o : doc["objects"])
    if (o["name"] == "Satellite2") {
      o["properties"]["shape"] = "composite";
      o["properties"].erase("dimensions_m");
      // The nested group is turned 180 deg about z, so its +x offset puts
      // its sphere toward the object's -x.
      o["properties"]["composite"] =
          R"([{"shape": "sphere", "dimensions_m": [100e3], "offset_m": [150e3, 0, 0]},
              {"parts": [{"shape": "sphere", "dimensions_m": [60e3], "offset_m": [150e3, 0, 0], "temperature_K": 200}],
               "orientation_wxyz": [0, 0, 0, 1]}])";
    }
}
}  // namespace

TEST(Composite, PartsAtOffsetsWithTheirOwnSurfaces) {
  ScenarioHost host("valid_sens_uniform_ext_area_src.json", [](nlohmann::json& doc) {
    make_composite(doc);
    doc["sensors"][0]["parameters"]["horizontal_fov_deg"] = 40.0;
    doc["sensors"][0]["parameters"]["vertical_fov_deg"] = 40.0;
  });
  host.render();
  // tan(offset) = 150 / 1000 -> 8.53 deg; the 40 deg field spans 512 samples
  // of tan(20 deg)/256 each: the part centres are ~206 samples from the centre.
  const double per_sample = 2 * std::tan(20 * M_PI / 180) / 512;
  const int offset = static_cast<int>(std::lround(0.15 / per_sample));
  const auto left = host.pick(256 - offset, 256), right = host.pick(256 + offset, 256);
  EXPECT_EQ(left.object, "Satellite2");
  EXPECT_EQ(right.object, "Satellite2");
  EXPECT_FALSE(host.pick(256, 256).hit);  // between the parts: sky
  // Each part shades with its own temperature (8-12 um band radiance).
  EXPECT_NEAR(left.effective_radiance, 3.850e-3, 0.005e-3);   // 300 K
  EXPECT_NEAR(right.effective_radiance, 3.481e-4, 0.005e-4);  // 200 K (spec 7.4.2)
  // Ranges: the near surface of each sphere.
  EXPECT_NEAR(left.range_m, std::hypot(1000e3, 150e3) - 100e3, 2e3);
  EXPECT_NEAR(right.range_m, std::hypot(1000e3, 150e3) - 60e3, 2e3);
}

// Seen as a point (far away), the composite's irradiance is the sum of its
// parts' L A* / R^2 (no part hides another from this side).
TEST(Composite, PointSourceIrradianceSumsItsParts) {
  ScenarioHost host("valid_sens_uniform_ext_area_src.json", [](nlohmann::json& doc) {
    make_composite(doc);
    for (auto& o : doc["objects"])
      if (o["name"] == "Satellite2")
        for (auto& p : o["motion"]["points"]) p["position_m"] = {7000e3, 0.0, 1e12};  // 1e9 km away
    doc["sensors"][0]["parameters"]["band_integration"] = "exact";
  });
  const double R = 1e12 - 0.0;  // m, from the sensor at (7000 km, 0, 0) along +z (offset negligible)
  const double expected = (3.850042e-3 * M_PI * std::pow(100e3, 2) + 3.481021e-4 * M_PI * std::pow(60e3, 2)) / (R * R);
  const double E = host.target_metric("Effective Target Irradiance", "Satellite2");
  // The composite uses the patch sum (patches of ~1/8 of 300 km): 1 %.
  EXPECT_NEAR(E / expected, 1.0, 0.01);
}

// Bad composites are refused with the JSON path of the problem.
TEST(Composite, BadPartsNameTheirPath) {
  ScenarioHost host("valid_sens_uniform_ext_area_src.json");
  auto refuse = [&](const char* json, eoir_status status, const char* path) {
    const eoir_status st = host.api().set_string(host.handle(), "Satellite2", "composite", json);
    EXPECT_EQ(st, status) << json;
    EXPECT_NE(std::string(host.api().last_error()).find(path), std::string::npos) << host.api().last_error();
  };
  refuse(R"([{"shape": "box", "dimensions_m": [1, -2, 3]}])", EOIR_ERR_OUT_OF_RANGE, "composite[0].dimensions_m[1]");
  refuse(R"([{"shape": "torus"}])", EOIR_ERR_UNKNOWN_NAME, "composite[0].shape");
  refuse(R"([{"parts": [{"shape": "sphere", "dimensions_m": [1], "offset_m": [0, 1]}]}])", EOIR_ERR_OUT_OF_RANGE,
         "composite[0].parts[0].offset_m");
  refuse(R"([{"shape": "sphere", "dimensions_m": [1], "colour": "red"}])", EOIR_ERR_UNKNOWN_NAME, "composite[0].colour");
  refuse(R"([{"shape": "sphere", "dimensions_m": [1], "orientation_wxyz": [1, 1, 0, 0]}])", EOIR_ERR_OUT_OF_RANGE,
         "orientation_wxyz");
  refuse("[{", EOIR_ERR_OUT_OF_RANGE, "composite: [0]: not valid JSON (truncated or corrupt)");
  refuse(R"([{"shape": "sphere", "dimensions_m": [1e999]}])", EOIR_ERR_OUT_OF_RANGE,
         "composite: [0].dimensions_m[0]: number out of range");
}

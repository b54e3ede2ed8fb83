// "For Each Pixel Pick" (spec 6.2.1 steps 6-10, 6.2.2, 6.2.3: the spec's
// experiments read their radiances from picks): a pick must return the
// spectral radiance that produced the image -- one radiance path. For sunlit
// samples, where reflected sunlight and self-emission both count (3-5 um by
// day), the band integral (eq. 48, the midpoint rule of the sensor's grid) of
// the pick's spectral vector must equal the image's sample, which the pick
// also reports, in every scene mode: the Earth in bitmap mode (land-cover
// materials) and a sunlit sphere in smooth and coarse modes.
#include <gtest/gtest.h>

#include <cmath>

#include "validation_support.hpp"

namespace v = eoir::validation;
using eoir::test::ScenarioHost;

namespace {

// Compares the pick of every 7th sample of the field with the image; returns
// the number of samples on `object`.
int compare_picks_with_image(ScenarioHost& host, const std::string& object, double low, double high, int intervals,
                             const std::string& sensor = "Sensor1") {
  host.render(sensor);
  const auto img = host.image(EOIR_IMAGE_SCENE_RADIANCE, sensor);
  int on_object = 0;
  for (int y = 3; y < img.height; y += 7)
    for (int x = 3; x < img.width; x += 7) {
      const v::SpectralPick sp = v::spectral_pick(host, x, y, sensor);
      if (sp.pick.object != object) continue;
      ++on_object;
      double band = 0;
      for (double L : sp.radiance) band += L * (high - low) / intervals;
      EXPECT_EQ(sp.pick.effective_radiance, img.at(x, y)) << x << "," << y;
      EXPECT_NEAR(band, img.at(x, y), 1e-9 * img.at(x, y)) << object << " sample " << x << "," << y;
      if (on_object == 1)
        std::printf("%s sample %d,%d: image %.9e, pick's spectrum integrated %.9e W cm^-2 sr^-1\n", object.c_str(), x,
                    y, img.at(x, y), band);
    }
  return on_object;
}

}  // namespace

TEST(Spec_6_2_1_Pick, EarthByDayInBitmapModeOneRadiancePath) {
  ScenarioHost host("v_test3_amazon.json", [](nlohmann::json& doc) {
    auto& p = doc["sensors"][0]["parameters"];
    p["band_low_um"] = 3.0;
    p["band_high_um"] = 5.0;
    p["spectral_intervals"] = 20;
    p["horizontal_pixels"] = p["vertical_pixels"] = 16;
  });
  EXPECT_GT(compare_picks_with_image(host, "Earth", 3.0, 5.0, 20), 40);
}

TEST(Spec_6_2_1_Pick, SunlitSphereInSmoothAndCoarseModesOneRadiancePath) {
  for (const char* mode : {"smooth", "coarse"}) {
    ScenarioHost host("v_phase2.json", [mode](nlohmann::json& doc) {
      auto& p = doc["sensors"][0]["parameters"];
      p["band_low_um"] = 3.0;
      p["band_high_um"] = 5.0;
      p["spectral_intervals"] = 20;
      p["horizontal_pixels"] = p["vertical_pixels"] = 32;
      p["horizontal_fov_deg"] = p["vertical_fov_deg"] = 0.0015;
      p["scene_mode"] = mode;
      v::object_named(doc, "Satellite2")["properties"]["reflectance"] = 0.5;
    });
    SCOPED_TRACE(mode);
    EXPECT_GT(compare_picks_with_image(host, "Satellite2", 3.0, 5.0, 20), 10);
  }
}

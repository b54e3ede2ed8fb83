// Edge sub-samples (Fidelity::edge_supersampling, scene/scene_generator.cpp):
// a scene sample whose hit differs from a 4-neighbour's takes the mean of
// s x s sub-samples over its footprint. Scene: the gray-body sphere of spec
// 7.2.2 (radius 100 km, 1000 km away, 300 K, 8-12 um, one radiance over its
// disc) wholly inside a 20 deg field, on an empty sky.
#include <gtest/gtest.h>

#include <cmath>

#include "scenario_host.hpp"

namespace eoir::test {
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double fov_deg = 20.0;
constexpr int pixels = 128;

ScenarioHost disc_host() {
  return ScenarioHost("valid_sens_uniform_ext_area_src.json", [](nlohmann::json& doc) {
    auto& p = doc["sensors"][0]["parameters"];
    p["horizontal_fov_deg"] = fov_deg;
    p["vertical_fov_deg"] = fov_deg;
    p["noise_enabled"] = false;
  });
}

Image scene_radiance(ScenarioHost& host, int samples_per_pixel, int edge_supersampling) {
  host.set_number("Sensor1", "samples_per_pixel", samples_per_pixel);
  host.set_number("Sensor1", "edge_supersampling", edge_supersampling);
  host.render();
  return host.image(EOIR_IMAGE_SCENE_RADIANCE);
}

// Pixel means of a scene radiance image of n x n samples per pixel.
std::vector<double> pixel_means(const Image& img, int n) {
  const int w = img.width / n, h = img.height / n;
  std::vector<double> out(static_cast<std::size_t>(w) * h, 0.0);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) out[static_cast<std::size_t>(y / n) * w + x / n] += img.at(x, y) / (n * n);
  return out;
}

// sum of L dOmega over the samples (pinhole: dOmega = (tangent step)^2 cos^3 theta).
double disc_flux(const Image& img, int n) {
  const double step = 2.0 * std::tan(0.5 * fov_deg * pi / 180.0) / (pixels * n);
  double flux = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const double tx = (0.5 * img.width - x - 0.5) * step, ty = (0.5 * img.height - y - 0.5) * step;
      flux += img.at(x, y) * step * step / std::pow(1.0 + tx * tx + ty * ty, 1.5);
    }
  return flux;
}

double max_value(const Image& img) {
  double m = 0;
  for (double v : img.values) m = std::max(m, v);
  return m;
}

// Expected: 2 x 2 samples with 4 x 4 sub-samples at edges put their
// sub-samples exactly on the 8 x 8 grid's samples, and every sample the limb
// crosses is refined, so each pixel mean equals the 8 x 8 grid's (a uniform
// disc: samples inside one footprint without an edge agree) to rounding.
TEST(EdgeSupersampling, EdgePixelsAsTheFinerGrid) {
  ScenarioHost host = disc_host();
  const std::vector<double> fine = pixel_means(scene_radiance(host, 8, 1), 8);
  const Image coarse_img = scene_radiance(host, 2, 4);
  const std::vector<double> refined = pixel_means(coarse_img, 2);
  const std::vector<double> plain = pixel_means(scene_radiance(host, 2, 1), 2);
  ASSERT_EQ(fine.size(), refined.size());
  const double L = max_value(coarse_img);
  ASSERT_GT(L, 0.0);
  int edge_pixels = 0, differing_plain = 0;
  for (std::size_t i = 0; i < fine.size(); ++i) {
    const bool edge = fine[i] > 0 && fine[i] < L * (1 - 1e-12);
    edge_pixels += edge;
    differing_plain += std::abs(plain[i] - fine[i]) > 1e-12 * L;
    EXPECT_NEAR(refined[i], fine[i], 1e-12 * L) << "pixel " << i;
  }
  // The disc (about 73 pixels across) has a few hundred edge pixels, and
  // without sub-samples most of them differ from the finer grid.
  EXPECT_GT(edge_pixels, 200);
  EXPECT_GT(differing_plain, edge_pixels / 2);
}

// Expected: the disc's flux sum L dOmega against L 2 pi (1 - cos theta),
// sin theta = 100/1000 (closed form). One sample per pixel errs by the
// coverage of its edge samples (4.9e-3 of the disc here); 16 x 16
// sub-samples at edges shrink each edge sample's error 16-fold: within
// 3e-4 (1.9e-5 measured).
TEST(EdgeSupersampling, DiscFluxConvergesToTheClosedForm) {
  ScenarioHost host = disc_host();
  const Image plain = scene_radiance(host, 1, 1);
  const Image refined = scene_radiance(host, 1, 16);
  const double L = max_value(refined);
  const double exact = L * 2.0 * pi * (1.0 - std::cos(std::asin(0.1)));
  const double e_plain = std::abs(disc_flux(plain, 1) - exact) / exact;
  const double e_refined = std::abs(disc_flux(refined, 1) - exact) / exact;
  EXPECT_LT(e_refined, 3e-4) << "1 x 1: " << e_plain;
  EXPECT_LT(e_refined, e_plain);
}

}  // namespace
}  // namespace eoir::test

// The night airglow's layer (issue 20 item 6; atmosphere/airglow.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "atmosphere/airglow.hpp"
#include "core/constants.hpp"
#include "core/data_dir.hpp"

namespace eoir::atmosphere {
namespace {

constexpr double kA = 6378137.0;

// From the ground: the layer's path over its thickness against van Rhijn's
// (1921) thin-layer factor 1 / sqrt(1 - (R / (R + h))^2 sin^2 z) at the
// layer's middle (h = 90 km): 1 at the zenith, within 0.2 % at 60 deg, 1 %
// at 80 deg and 2 % at the horizon (where the shell's thickness counts);
// the near pass is empty from below.
TEST(Airglow, VanRhijnFromTheGround) {
  const double h = 0.5 * (airglow_layer_bottom_m + airglow_layer_top_m);
  const auto van_rhijn = [&](double z_deg) {
    const double s = kA / (kA + h) * std::sin(z_deg * constants::rad_per_deg);
    return 1.0 / std::sqrt(1.0 - s * s);
  };
  const double tolerance[] = {1e-9, 0.002, 0.01, 0.02};
  const double zenith_deg[] = {0.0, 60.0, 80.0, 90.0};
  for (int k = 0; k < 4; ++k) {
    const Airglow::Passes g = Airglow::passes(kA, kA, std::cos(zenith_deg[k] * constants::rad_per_deg));
    EXPECT_EQ(g.near, 0.0);
    EXPECT_NEAR(g.far / van_rhijn(zenith_deg[k]), 1.0, tolerance[k]) << zenith_deg[k] << " deg";
  }
  // Below the horizon from the ground: the ground first.
  EXPECT_EQ(Airglow::passes(kA, kA, -0.1).far, 0.0);
}

// From orbit: a line grazing the layer's middle crosses it twice, each pass
// sqrt(r_top^2 - r_t^2) long (the chord's closed form); a line down to the
// ground crosses it once (straight down: one thickness); a line above the
// layer misses it.
TEST(Airglow, PassesFromOrbit) {
  const double r = kA + 700e3, thickness = airglow_layer_top_m - airglow_layer_bottom_m;
  const double tangent = kA + 90e3, rt = kA + airglow_layer_top_m;
  const double mu = -std::sqrt(1.0 - (tangent / r) * (tangent / r));
  const Airglow::Passes limb = Airglow::passes(kA, r, mu);
  const double half = std::sqrt(rt * rt - tangent * tangent) / thickness;
  EXPECT_NEAR(limb.near, half, 1e-6 * half);
  EXPECT_NEAR(limb.far, half, 1e-6 * half);
  const Airglow::Passes nadir = Airglow::passes(kA, r, -1.0);
  EXPECT_NEAR(nadir.near, 1.0, 1e-9);
  EXPECT_EQ(nadir.far, 0.0);
  const double above = kA + 120e3;
  const Airglow::Passes miss = Airglow::passes(kA, r, -std::sqrt(1.0 - (above / r) * (above / r)));
  EXPECT_EQ(miss.near + miss.far, 0.0);
}

// The table's units: the O I 557.7 nm line's 320 R (Johnson 1992) and the
// continuum's 1352 R over 0.45-0.76 um (4.36 R/nm) in the 1 nm interval
// around the line are (320 + 4.36) x 1e6 / (4 pi) photons s^-1 cm^-2 sr^-1
// of h c / 557.7 nm each (the rayleigh's definition, Hunten, Roach and
// Chamberlain 1956), within 1e-4; nothing where the table has nothing.
TEST(Airglow, RayleighsToRadiance) {
  const Airglow a = Airglow::load(resolve_data_dir(""));
  const std::vector<double> L = a.zenith_radiance(0.5572, 0.001, 1);
  const double photon_J = constants::planck_J_s * constants::speed_of_light_m_per_s / 0.5577e-6;
  const double rayleighs = 320.0 + 1352.0 * 0.001 / (0.760 - 0.450);
  EXPECT_NEAR(L[0] * 0.001 / (rayleighs * 1e6 / (4.0 * constants::pi) * photon_J), 1.0, 1e-4);
  EXPECT_EQ(a.zenith_radiance(8.0, 1.0, 4), std::vector<double>(4, 0.0));
}

}  // namespace
}  // namespace eoir::atmosphere

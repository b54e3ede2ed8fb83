// Spec 6.2.3.4 (inverse square law, area source), 6.2.4.3 (inverse square
// law, point source, and the phase law of a Lambertian sphere) and 6.2.5.1
// (area source, detailed and simple point source agree), with
// scenarios/validation/v_phase2.json: Satellite2, a sunlit 10 m gray-body
// sphere of reflectance 1 (emissivity 0, so reflection only), seen from
// Satellite1 at a distance r and a Sun-Satellite2-Satellite1 phase angle psi.
//
// Independent reference (eq. 7 for a sphere, spec 4.1.5.3): the irradiance at
// the observer of a Lambertian sphere of radius R and albedo rho at distance r,
//   E = E_sun rho (2 / (3 pi)) Phase(psi) pi R^2 / r^2,
//   Phase(psi) = (sin psi + (pi - psi) cos psi) / pi,
// with E_sun the E-490 table (read from its published file) integrated over
// the band times (1 au / d)^2, d the Sun-Satellite2 distance from ERFA.
// The area source is measured as the spec's TRACK_IRRAD does: the sum of the
// scene radiance samples times their solid angle.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "../support/mesh_files.hpp"
#include "validation_support.hpp"

namespace v = eoir::validation;
using eoir::test::ScenarioHost;

namespace {

constexpr const char* kScenario = "v_phase2.json";
constexpr const char* kEpoch = "2010-06-01T00:00:00Z";
constexpr const char* kStop = "2010-06-01T00:01:00Z";
constexpr double kGeo = 42164.2e3, kRadius = 10.0, kLow = 0.4, kHigh = 0.7;

struct Placement {
  v::V3 sat1, sat2, sun;
};

// Satellite1 on the dawn-dusk meridian at GEO radius; Satellite2 at distance
// r from it, the phase angle at Satellite2 psi (as tools/make_v_geo.py).
Placement placement(double r_m, double psi_rad) {
  Placement p;
  p.sun = v::sun_geocentric_m(kEpoch);
  const v::V3 s = v::unit(p.sun);
  const v::V3 e = v::unit(v::cross({0, 0, 1}, s));
  p.sat1 = kGeo * e;
  p.sat2 = p.sat1 - r_m * (std::cos(psi_rad) * s + std::sin(psi_rad) * e);
  return p;
}

std::function<void(nlohmann::json&)> placed(const Placement& p) {
  return [p](nlohmann::json& doc) {
    v::set_fixed_j2000(v::object_named(doc, "Satellite1"), kEpoch, kStop, p.sat1);
    v::set_fixed_j2000(v::object_named(doc, "Satellite2"), kEpoch, kStop, p.sat2);
  };
}

double phase_law(double psi) { return (std::sin(psi) + (v::kPi - psi) * std::cos(psi)) / v::kPi; }

// The closed form above, with psi and the distances from the placement.
double lambert_sphere_irradiance(const Placement& p) {
  static const v::Table e490 = v::read_e490(EOIR_E490_FILE);
  const v::V3 to_sun = p.sun - p.sat2, to_obs = p.sat1 - p.sat2;
  const double d = v::norm(to_sun), r = v::norm(to_obs);
  const double psi = std::acos(v::dot(to_sun, to_obs) / (d * r));
  const double E_sun = v::integrate_linear(e490, kLow, kHigh) * 1e-4 * (v::kAu_m / d) * (v::kAu_m / d);
  return E_sun * (2.0 / 3.0) * phase_law(psi) * (kRadius / r) * (kRadius / r);
}

// Sensor1's scene radiance image summed times the sample solid angle (the
// field's tangent step squared: within 1e-9 of the exact solid angle this
// close to the axis).
double area_source_irradiance(ScenarioHost& host) {
  host.render("Sensor1");
  const auto img = host.image(EOIR_IMAGE_SCENE_RADIANCE, "Sensor1");
  const double step = 2.0 * std::tan(0.5 * 0.0065 * v::kDeg) / (128 * 4);
  // The sphere must be wholly inside the field: the border samples see sky.
  for (int i = 0; i < img.width; ++i) {
    EXPECT_EQ(img.at(i, 0), 0.0);
    EXPECT_EQ(img.at(i, img.height - 1), 0.0);
    EXPECT_EQ(img.at(0, i), 0.0);
    EXPECT_EQ(img.at(img.width - 1, i), 0.0);
  }
  return img.sum() * step * step;
}

double point_source_irradiance(ScenarioHost& host) {
  EXPECT_EQ(host.target_metric("Target Is Point Source", "Satellite2", "Sensor2"), 1.0);
  return host.target_metric("Effective Target Irradiance", "Satellite2", "Sensor2");
}

}  // namespace

// 6.2.3.4: the area source (Sensor1 resolves Satellite2) at 200 to 2000 km:
// E r^2 constant within 0.5 % (spec), and E the closed form within 1 %.
TEST(Spec_6_2_3_4, InverseSquareAsAreaSource) {
  double first = 0;
  for (double r_km : {200.0, 400.0, 1000.0, 2000.0}) {
    const Placement p = placement(r_km * 1e3, 20.0 * v::kDeg);
    ScenarioHost host(kScenario, placed(p));
    const double E = area_source_irradiance(host);
    const double Er2 = E * r_km * r_km;
    if (first == 0) first = Er2;
    const double expected = lambert_sphere_irradiance(p);
    std::printf("area source r = %6.0f km: E = %.6e W/cm^2, E r^2 / first = %.6f, E / closed form = %.6f\n", r_km, E,
                Er2 / first, E / expected);
    EXPECT_NEAR(Er2 / first, 1.0, 5e-3) << r_km << " km";
    EXPECT_NEAR(E / expected, 1.0, 1e-2) << r_km << " km";
  }
}

// 6.2.4.3: the point source (Sensor2, detailed: the default for satellites)
// at 200 to 2000 km: E r^2 constant within 0.5 %, E the closed form within 1 %.
TEST(Spec_6_2_4_3, InverseSquareAsPointSource) {
  double first = 0;
  for (double r_km : {200.0, 400.0, 1000.0, 2000.0}) {
    const Placement p = placement(r_km * 1e3, 20.0 * v::kDeg);
    ScenarioHost host(kScenario, placed(p));
    const double E = point_source_irradiance(host);
    const double Er2 = E * r_km * r_km;
    if (first == 0) first = Er2;
    const double expected = lambert_sphere_irradiance(p);
    std::printf("point source r = %6.0f km: E = %.6e W/cm^2, E r^2 / first = %.6f, E / closed form = %.6f\n", r_km,
                E, Er2 / first, E / expected);
    EXPECT_NEAR(Er2 / first, 1.0, 5e-3) << r_km << " km";
    EXPECT_NEAR(E / expected, 1.0, 1e-2) << r_km << " km";
  }
}

// 6.2.4.3 phase law (V_Phase3): the detailed point-source irradiance of the
// Lambertian sphere against Phase(psi) of eq. 7 within 1 % for psi 0-170 deg;
// the simple model is eq. 7 itself (its psi and distances: within 1e-6).
// The detailed model is a sum over the sphere's patches, each evaluated at
// its centre: a quadrature whose error grows as the lit crescent narrows (at
// 170 deg it is 1.5 % of the radius wide). At the default tessellation
// (patches a diameter / 8 wide) it is within 1 % up to 120 deg but 2 % off
// at 150 deg and 21 % at 170 deg (measured); with 0.5 m patches (diameter /
// 40, patch_size_m) within 0.3 % at every angle. Both are checked: the
// default where it holds, the finer tessellation over the spec's range.
TEST(Spec_6_2_4_3, PhaseLawOfALambertianSphere) {
  for (double deg : {0.0, 10.0, 30.0, 60.0, 90.0, 120.0, 150.0, 170.0}) {
    const Placement p = placement(1000e3, deg * v::kDeg);
    ScenarioHost host(kScenario, placed(p));
    const double expected = lambert_sphere_irradiance(p);
    const double detailed_default = point_source_irradiance(host);
    host.set_number("Satellite2", "patch_size_m", 0.5);
    host.at(0);
    const double detailed = point_source_irradiance(host);
    host.set_string("Satellite2", "point_source_model", "simple");
    host.at(0);
    const double simple = point_source_irradiance(host);
    std::printf("psi %5.1f deg: Phase %.6f; detailed / eq. 7 = %.6f (0.5 m patches), %.6f (default); simple / eq. 7 "
                "= %.9f\n", deg, phase_law(deg * v::kDeg), detailed / expected, detailed_default / expected,
                simple / expected);
    EXPECT_NEAR(detailed / expected, 1.0, 1e-2) << "psi " << deg << " deg";
    if (deg <= 120.0) {
      EXPECT_NEAR(detailed_default / expected, 1.0, 1e-2) << "psi " << deg << " deg, default patches";
    }
    EXPECT_NEAR(simple / expected, 1.0, 1e-6) << "psi " << deg << " deg";
  }
}

// 6.2.5.1: at the same geometry (1000 km, psi 20 deg, and 2000 km) the area
// source (Sensor1), the detailed and the simple point source (Sensor2, the
// point_source_model property) agree within 2 %.
TEST(Spec_6_2_5_1, AreaDetailedAndSimpleAgree) {
  for (double r_km : {1000.0, 2000.0}) {
    const Placement p = placement(r_km * 1e3, 20.0 * v::kDeg);
    ScenarioHost host(kScenario, placed(p));
    const double area = area_source_irradiance(host);
    host.set_string("Satellite2", "point_source_model", "detailed");
    host.at(0);
    const double detailed = point_source_irradiance(host);
    host.set_string("Satellite2", "point_source_model", "simple");
    host.at(0);
    const double simple = point_source_irradiance(host);
    std::printf("r = %.0f km: area %.6e, detailed %.6e, simple %.6e W/cm^2\n", r_km, area, detailed, simple);
    EXPECT_NEAR(detailed / area, 1.0, 2e-2);
    EXPECT_NEAR(simple / area, 1.0, 2e-2);
    EXPECT_NEAR(simple / detailed, 1.0, 2e-2);
  }
}

namespace {
// A mesh file of the tests' own (tests/support/mesh_files.hpp) in a temporary
// folder: its absolute path.
std::string mesh_file(const std::string& name, const eoir::test::TriangleMesh& m) {
  const auto dir = std::filesystem::temp_directory_path() / ("eoir_geo_photometry_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / name).string();
  eoir::test::write_obj(path, m);
  return path;
}
}  // namespace

// 6.2.4.3 with a mesh target (shape mesh): Satellite2 as an icosphere of
// 20,480 triangles scaled to the 10 m sphere. Its detailed point-source
// irradiance (one patch per triangle) against eq. 7's closed form for the
// sphere within 0.5 % at 0, 60 and 120 deg phase; the polyhedron is
// inscribed in the sphere, its projected area 0.1 % smaller.
TEST(Spec_6_2_4_3, MeshIcospherePhaseLaw) {
  const std::string ico = mesh_file("icosphere_20480.obj", eoir::test::icosphere(5));
  for (double deg : {0.0, 60.0, 120.0}) {
    const Placement p = placement(1000e3, deg * v::kDeg);
    ScenarioHost host(kScenario, placed(p));
    host.set_string("Satellite2", "shape", "mesh");
    host.set_string("Satellite2", "mesh_file", ico);
    const double scale = kRadius;  // metres per file unit
    ASSERT_EQ(host.api().set_array(host.handle(), "Satellite2", "dimensions_m", &scale, 1), EOIR_OK);
    host.at(0);
    const double E = point_source_irradiance(host), expected = lambert_sphere_irradiance(p);
    std::printf("mesh icosphere psi %5.1f deg: detailed / eq. 7 = %.6f\n", deg, E / expected);
    EXPECT_NEAR(E / expected, 1.0, 5e-3) << "psi " << deg << " deg";
  }
}

// A mesh cube and the box primitive of the same size and orientation give
// the same resolved image: Sensor1's scene-radiance sums within 0.5 %
// (a 12 m cube, turned so three faces are seen, lit at 20 deg phase).
TEST(Spec_6_2_3_4, MeshCubeImagesAsTheBox) {
  const std::string cube = mesh_file("cube.obj", eoir::test::unit_cube());
  const Placement p = placement(300e3, 20.0 * v::kDeg);
  const std::string turn = R"("orientation_wxyz": [0.9396926207859084, 0.20259524806996376, 0.2633738224909529, 0.08103809922798551])";
  double sums[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    ScenarioHost host(kScenario, placed(p));
    const std::string part = k == 0 ? R"({"shape": "box", "dimensions_m": [12, 12, 12], )"
                                     : R"({"shape": "mesh", "mesh_file": ")" + cube + R"(", "dimensions_m": [12], )";
    host.set_string("Satellite2", "shape", "composite");
    host.set_string("Satellite2", "composite", "[" + part + turn + "}]");
    host.at(0);
    sums[k] = area_source_irradiance(host);
  }
  std::printf("box %.6e, mesh cube %.6e W/cm^2: ratio %.6f\n", sums[0], sums[1], sums[1] / sums[0]);
  EXPECT_GT(sums[0], 0.0);
  EXPECT_NEAR(sums[1] / sums[0], 1.0, 5e-3);
}

// The frame's occultation tests see, per tile of samples, only the bodies
// whose shadow can reach the tile (WorldObject::shadow_casters_near): every
// sample must shade as against all of the object's occulters (to rounding)
// (spec 4.1.5.3, eqs. 4 and 6: the Sun's visible fraction at the point).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine.hpp"
#include "geo_host.hpp"

namespace {
using eoir::Value;
using eoir::universe::ObjectKind;
using Vec3 = Eigen::Vector3d;

const eoir::scene::WorldObject& object_named(const eoir::scene::World& w, const std::string& name) {
  for (const auto& o : w.objects)
    if (o->name == name) return *o;
  throw std::runtime_error("no object " + name);
}

const double kZero[3] = {0, 0, 0}, kIdentity[4] = {1, 0, 0, 0};

// The Earth from GEO at 2010-05-05 12:00 UTC on 64 x 64 pixels of a 24 deg
// field (the whole disc), noise-free, in a band and scene mode.
std::unique_ptr<eoir::Engine> earth_view(double band_low_um, double band_high_um, const char* scene_mode) {
  auto e = eoir_test::geo_host_engine("2010-05-05T12:00:00Z");
  for (const char* p : {"horizontal_pixels", "vertical_pixels"}) e->set_property("Sensor", p, Value(std::int64_t{64}));
  for (const char* p : {"horizontal_fov_deg", "vertical_fov_deg"}) e->set_property("Sensor", p, Value(24.0));
  e->set_property("Sensor", "band_low_um", Value(band_low_um));
  e->set_property("Sensor", "band_high_um", Value(band_high_um));
  e->set_property("Sensor", "scene_mode", Value(std::string(scene_mode)));
  e->set_property("Sensor", "noise_enabled", Value(false));
  e->set_property("Sensor", "saturation_enabled", Value(false));
  const double look[4] = {std::sqrt(0.5), 0, -std::sqrt(0.5), 0};
  e->push_state("Sensor", e->time(), 0, kZero, kZero, look);
  return e;
}

// Each Earth sample of frame f away from silhouette edges (edge samples are
// means of sub-samples), shaded again at its own point with no tile's lists
// (radiance_at): f's value, that value, the point (observer frame and body)
// and the hit. Returns the samples visited.
template <class Visit>
std::int64_t for_each_earth_sample(const eoir::Frame& f, const eoir::scene::WorldObject& earth, Visit&& visit) {
  const eoir::scene::World& w = *f.world;
  const std::int64_t width = w.grid().width(), height = w.grid().height();
  const auto& hits = f.scene.hits;
  const auto& radiance = f.scene.image.radiance_W_cm2_sr;
  std::int64_t visited = 0;
  for (std::int64_t r = 1; r + 1 < height; ++r)
    for (std::int64_t c = 1; c + 1 < width; ++c) {
      const auto i = static_cast<std::size_t>(r * width + c);
      if (hits[i].object_id != earth.id) continue;
      bool edge = false;
      for (const std::size_t j : {i - 1, i + 1, i - static_cast<std::size_t>(width), i + static_cast<std::size_t>(width)})
        edge = edge || hits[j].object_id != hits[i].object_id || hits[j].part != hits[i].part;
      if (edge) continue;
      const Vec3 d = w.sample_direction(static_cast<double>(c), static_cast<double>(r));
      const eoir::geometry::Hit hit = w.caster.cast(d);
      EXPECT_EQ(hit.object_id, earth.id);
      const Vec3 point_frame = hit.range_m * d;
      const Vec3 point_body = earth.seen.body_to_frame.transpose() * (point_frame - earth.seen.position_m);
      const double again = earth.radiance_at(hit.part, point_body, earth.direction_to_body(hit.normal_frame), hit.facet);
      visit(radiance[i], again, point_frame, point_body, hit);
      ++visited;
    }
  return visited;
}

// The Earth in the visible band by day from GEO, smooth mode, and a 300 km
// sphere 10,000 km above the sub-solar point: its umbra (~250 km) and
// penumbra (~45 km wide) fall on the day side, away from the sphere's own
// image (the Sun ~45 deg from the host's line of sight in early May).
std::unique_ptr<eoir::Engine> shadow_scene() {
  auto e = earth_view(0.45, 0.75, "smooth");
  // The Sun's direction from the Earth at the frame time, from a first world.
  const eoir::Frame& probe = e->render("Sensor");
  const eoir::scene::World& w = *probe.world;
  const Vec3 earth = object_named(w, "Earth").placed.position_m;
  const Vec3 to_sun = (w.sun.position_m - earth).normalized();
  const Vec3 sphere = (6371e3 + 10000e3) * to_sun;  // Earth-centred (the engine's J2000 states)
  const double position_m[3] = {sphere.x(), sphere.y(), sphere.z()};
  e->add_object(ObjectKind::satellite, "Shade");
  e->set_property("Shade", "dimensions_m", Value(std::vector<double>{300e3}));
  e->push_state("Shade", e->time(), 0, position_m, kZero, kIdentity);
  return e;
}
}  // namespace

TEST(ShadowCasters, TilesShadeAsAgainstEveryOcculter) {
  auto e = shadow_scene();
  const eoir::Frame& f = e->render("Sensor");
  const eoir::scene::World& w = *f.world;
  const eoir::scene::WorldObject& earth = object_named(w, "Earth");
  std::int64_t penumbra = 0, umbra = 0;
  const std::int64_t compared = for_each_earth_sample(
      f, earth, [&](double frame, double all, const Vec3& point_frame, const Vec3& point_body,
                    const eoir::geometry::Hit& hit) {
        // Against all of the Earth's occulters (no tile's list), to rounding:
        // the frame takes a tile's latitudes and temperatures by vector maths,
        // radiance_at by libm (core/vector_math.hpp); a caster missing from
        // the tile's list would change a shadowed sample by far more.
        EXPECT_NEAR(frame, all, 1e-12 * all);
        const double fraction = earth.sun_fraction(point_frame);
        if (fraction > 0 && fraction < 1) ++penumbra;
        const Vec3 to_sun = earth.direction_to_body(w.sun.position_m - point_frame).normalized();
        if (fraction == 0 && earth.normal_at(hit.part, point_body).dot(to_sun) > 0) ++umbra;
      });
  EXPECT_GT(compared, 10000);
  // The comparison covers the shadow: samples in the penumbra and the umbra.
  EXPECT_GE(penumbra, 10);
  EXPECT_GE(umbra, 10);
}

TEST(ShadowCasters, FarTilesKeepNoCasterNearOnesKeepTheShade) {
  auto e = shadow_scene();
  const eoir::Frame& f = e->render("Sensor");
  const eoir::scene::World& w = *f.world;
  const eoir::scene::WorldObject& earth = object_named(w, "Earth");
  const Vec3 to_sun = (w.sun.position_m - earth.placed.position_m).normalized();
  const Vec3 sub_solar = earth.placed.position_m + 6378e3 * to_sun;
  const Vec3 far = earth.placed.position_m + 6378e3 * (to_sun + Vec3(0, 0, 1)).normalized();  // ~2,000+ km away
  eoir::scene::ShadowCasters near_shade, far_away;
  earth.shadow_casters_near(sub_solar, 50e3, near_shade);
  earth.shadow_casters_near(far, 50e3, far_away);
  const auto is_shade = [](const eoir::geometry::Occulter& o) { return o.equatorial_radius_m == 300e3; };
  ASSERT_FALSE(near_shade.occulters.empty());
  ASSERT_FALSE(far_away.occulters.empty());
  // The sphere may hide the Sun near the sub-solar point, nowhere near the far one.
  EXPECT_EQ(std::count_if(near_shade.occulters[0].begin(), near_shade.occulters[0].end(), is_shade), 1);
  EXPECT_EQ(std::count_if(far_away.occulters[0].begin(), far_away.occulters[0].end(), is_shade), 0);
}

namespace {
// The Earth in 8-12 um from GEO, bitmap mode (its emission first: reflected
// sunlight cannot make it negligible), and "Lamp", a sphere of radius 20 m
// at 300 K 10 km above the sub-observer point: its eq. 7 light matters
// within some 300 km of the point below it (kNegligible of the emission
// there; 1e-8 of it 100 km away) and nowhere far from it.
std::unique_ptr<eoir::Engine> lamp_scene() {
  auto e = earth_view(8.0, 12.0, "bitmap");
  const double lamp_m[3] = {6378.137e3 + 10e3, 0, 0};  // Earth-centred, on the host's line
  e->add_object(ObjectKind::satellite, "Lamp");
  e->set_property("Lamp", "shape", Value(std::string("sphere")));
  e->set_property("Lamp", "dimensions_m", Value(std::vector<double>{20.0}));
  e->set_property("Lamp", "temperature_K", Value(300.0));
  e->push_state("Lamp", e->time(), 0, lamp_m, kZero, kIdentity);
  return e;
}
}  // namespace

// The frame leaves out, for a tile's run of Earth samples, the lights whose
// light cannot reach the run's least threshold anywhere in the tile's region
// (WorldObject::lights_negligible_in, scene_generator's shade_rows): every
// sample shades as with each light tested at its own point (radiance_at, no
// tile; to the rounding of the vector maths, as above; a light wrongly left
// out below the lamp would change a sample by 1e-10 or more), and the test
// does leave the lamp out far from it and keeps it near it.
TEST(ShadowCasters, LightsLeftOutForATileAreNegligibleAtEachOfItsPoints) {
  auto e = lamp_scene();
  const eoir::Frame& f = e->render("Sensor");
  const eoir::scene::World& w = *f.world;
  const eoir::scene::WorldObject& earth = object_named(w, "Earth");
  const eoir::scene::WorldObject& lamp = object_named(w, "Lamp");
  std::size_t light = w.lights.size();
  for (std::size_t k = 0; k < w.lights.size(); ++k)
    if (w.lights[k].object == lamp.id) light = k;
  ASSERT_LT(light, w.lights.size());
  const Vec3 below = earth.placed.position_m + 6378.137e3 * (lamp.placed.position_m - earth.placed.position_m).normalized();
  std::int64_t near_lamp = 0;
  const std::int64_t compared = for_each_earth_sample(
      f, earth, [&](double frame, double each, const Vec3& point_frame, const Vec3&, const eoir::geometry::Hit&) {
        EXPECT_NEAR(frame, each, 1e-12 * each);
        if ((point_frame - below).norm() < 200e3) ++near_lamp;
      });
  EXPECT_GT(compared, 1000);
  EXPECT_GE(near_lamp, 4);  // (samples where the lamp's light counts)
  // The frame's threshold there: kNegligible (1e-10) shared among the lights
  // times the emission over the SRF bound (some 0.2 W/cm^2/sr in 8-12 um):
  // the lamp kept 30 km around the point below it, left out 30 km around a
  // point 6,000 km from it.
  const double threshold = 1e-10 / static_cast<double>(w.lights.size()) * 0.2;
  const Vec3 north = (lamp.placed.position_m - earth.placed.position_m).normalized() + Vec3(0, 0, 1.5);
  const Vec3 far = earth.placed.position_m + 6378.137e3 * north.normalized();
  eoir::scene::ShadowCasters at_below, at_far;
  earth.shadow_casters_near(below, 30e3, at_below);
  earth.shadow_casters_near(far, 30e3, at_far);
  std::vector<char> off;
  earth.lights_negligible_in(at_below, threshold, off);
  ASSERT_EQ(off.size(), w.lights.size());
  EXPECT_EQ(off[light], 0);
  earth.lights_negligible_in(at_far, threshold, off);
  EXPECT_EQ(off[light], 1);
}

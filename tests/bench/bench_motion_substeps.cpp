// Motion sub-steps (sensor property motion_substeps; scene/motion_substeps.hpp;
// issue 23 item 5): the cost of N sub-steps against one, in one run.
//
// Scene: the ground telescope of bench_scene.hpp (30 N 150 E by day, azimuth
// 270, elevation 30, no atmosphere), 256 x 256 pixels over 0.5 deg, 8-12 um,
// 20 ms, with a 10 m sphere 600 km along its boresight crossing the field at
// 7.5 km/s (a streak of about 7 pixels).
//
//  - BM_MotionSubsteps/N: each iteration renders the frame with 1 sub-step
//    and with N (two engines of the same scene), noise on. Counters from
//    the frames' own timings: the scene part (point sources, ray casting
//    and, with N > 1, the sub-steps' world builds: FrameTimings::shading_s +
//    ray_casting_s) with 1 and with N and its ratio (expected about N for
//    odd N, whose middle sub-step is the frame time, and N + 1 for even N:
//    the frame time's scene is made as well, for its point sources and the
//    picks' hits), and the whole frame's ratio.
#include <benchmark/benchmark.h>

#include "bench_scene.hpp"
#include "universe/object_motion.hpp"

namespace {

using eoir::Value;

std::unique_ptr<eoir::Engine> crossing_scene() {
  eoir::bench::SensorSetup s;
  s.pixels = 256;
  s.fov_deg = 0.5;
  s.noise = true;
  auto e = eoir::bench::make_ground_scene(s);
  e->set_property("Sensor", "integration_time_ms", Value(20.0));
  const auto k = eoir::universe::kinematics_at(e->universe(), e->universe().sensor("Sensor"), e->time());
  const Eigen::Vector3d look = k.attitude * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d across = look.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d p = k.position_m + 600e3 * look, v = 7500.0 * across;
  const double pos[3] = {p.x(), p.y(), p.z()}, vel[3] = {v.x(), v.y(), v.z()};
  eoir::bench::add_satellite(*e, "Leo", "sphere", {10.0}, 300.0, pos, vel);
  return e;
}

void BM_MotionSubsteps(benchmark::State& state) {
  const std::int64_t n = state.range(0);
  auto one = crossing_scene(), many = crossing_scene();  // two engines: each keeps its world and plans
  many->set_property("Sensor", "motion_substeps", Value(n));
  const auto scene_s = [](const eoir::Frame& f) { return f.timings.shading_s + f.timings.ray_casting_s; };
  one->render("Sensor");  // the worlds and the FFT plans, outside the timing
  many->render("Sensor");
  double one_scene = 0, many_scene = 0, one_total = 0, many_total = 0, in_field = 0;
  for (auto _ : state) {
    const eoir::Frame& a = one->render("Sensor");
    one_scene += scene_s(a);
    one_total += a.timings.total_s();
    const eoir::Frame& b = many->render("Sensor");
    many_scene += scene_s(b);
    many_total += b.timings.total_s();
    in_field = static_cast<double>(b.truth.size());
  }
  const double frames = static_cast<double>(state.iterations());
  state.counters["scene_1_ms"] = 1e3 * one_scene / frames;
  state.counters["scene_N_ms"] = 1e3 * many_scene / frames;
  state.counters["scene_ratio"] = many_scene / one_scene;
  state.counters["frame_1_ms"] = 1e3 * one_total / frames;
  state.counters["frame_N_ms"] = 1e3 * many_total / frames;
  state.counters["frame_ratio"] = many_total / one_total;
  state.counters["objects_in_field"] = in_field;  // the sphere (per-frame truth)
}

}  // namespace

BENCHMARK(BM_MotionSubsteps)->Arg(1)->Arg(2)->Arg(3)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();

// Ray-casting throughput (DESIGN.md section 8): 1024 x 1024 pinhole fan from
// GEO at the Earth + the Moon + 3 small satellites, on 1 and 2 threads.
#include <benchmark/benchmark.h>

#include <cmath>

#include "geometry/scene_geometry.hpp"

namespace g = eoir::geometry;
using g::Vec3;

namespace {

g::ShapePart part(const std::string& shape, std::vector<double> dims) {
  return g::ShapePart{g::shape_geom(eoir::universe::parse_shape(shape, "shape"), dims)};
}

g::PlacedObject object(int id, const std::string& shape, std::vector<double> dims, const Vec3& pos) {
  g::PlacedObject o;
  o.object_id = id;
  o.parts = {part(shape, std::move(dims))};
  o.position_m = pos;
  return o;
}

struct Scene {
  std::vector<g::PlacedObject> objects;
  std::vector<Vec3> dirs;
  std::vector<const g::PlacedObject*> pointers() const {
    std::vector<const g::PlacedObject*> out;
    for (const auto& o : objects) out.push_back(&o);
    return out;
  }
  Scene() {
    const double geo = 42164.2e3;
    objects.push_back(object(0, "oblate", {6378137.0, 6356752.314245}, Vec3(geo, 0, 0)));
    objects.push_back(object(1, "sphere", {1737.4e3}, Vec3(4.0e8, -6.0e7, 0)));
    // Three satellites, each a bus with two solar panels, 5-50 km away in the view.
    for (int k = 0; k < 3; ++k) {
      const double range = 5e3 * std::pow(3.2, k);
      g::PlacedObject sat = object(10 + k, "box", {2, 2, 3}, Vec3(range, 0.02 * range * (k - 1), 0.01 * range));
      g::ShapePart wing = part("plate", {8, 2});
      wing.offset_m = Vec3(0, 5.5, 0);
      sat.parts.push_back(wing);
      wing.offset_m = Vec3(0, -5.5, 0);
      sat.parts.push_back(wing);
      objects.push_back(sat);
    }
    const int n = 1024;
    const double half_fov = 0.16;  // rad: the Earth (0.152) fills the view
    dirs.reserve(static_cast<size_t>(n) * n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        dirs.push_back(Vec3(1, std::tan(half_fov * (2.0 * (j + 0.5) / n - 1)),
                            std::tan(half_fov * (2.0 * (i + 0.5) / n - 1)))
                           .normalized());
  }
};

void BM_Cast1024(benchmark::State& state) {
  static const Scene scene;
  g::RayCaster caster;
  caster.build(scene.pointers());
  std::vector<g::Hit> hits;
  for (auto _ : state) {
    caster.cast(scene.dirs, hits, static_cast<unsigned>(state.range(0)));
    benchmark::DoNotOptimize(hits.data());
  }
  state.counters["rays/s"] =
      benchmark::Counter(static_cast<double>(scene.dirs.size()) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Cast1024)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Build(benchmark::State& state) {
  static const Scene scene;
  g::RayCaster caster;
  for (auto _ : state) caster.build(scene.pointers());
}
BENCHMARK(BM_Build)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();

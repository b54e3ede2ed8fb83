// Cost of a state save and of a restore (spec 3.4, engine/state/scd.hpp) for
// an engine with the Earth, the Moon, 16 satellites and 6 sensors: in memory
// (engine_to_json / engine_from_json, and the text dump/parse) and through
// files (save_engine / load_engine in a temporary directory).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "bench_scene.hpp"
#include "state/scd.hpp"

namespace {

std::unique_ptr<eoir::Engine> make_state_engine() {
  auto e = std::make_unique<eoir::Engine>();
  e->set_time(eoir::bench::bench_epoch());
  e->add_object(eoir::universe::ObjectKind::central_body, "Earth");
  e->add_object(eoir::universe::ObjectKind::central_body, "Moon");
  for (int i = 0; i < 16; ++i) {
    const double a = 2.0 * M_PI * i / 16.0, r = 7000e3 + 1000e3 * (i % 4);
    const double p[3] = {r * std::cos(a), r * std::sin(a), 1000e3 * (i % 3)};
    const double v[3] = {-7500 * std::sin(a), 7500 * std::cos(a), 0};
    eoir::bench::add_satellite(*e, "Sat" + std::to_string(i), i % 2 ? "box" : "sphere",
                               i % 2 ? std::vector<double>{2, 1, 1} : std::vector<double>{1.0}, 280.0 + i, p, v);
  }
  for (int i = 0; i < 6; ++i) {
    eoir::bench::SensorSetup s;
    s.pixels = 128 << (i % 3);
    s.intervals = 10 * (i + 1);
    eoir::bench::add_sensor(*e, "Sensor" + std::to_string(i), "Sat" + std::to_string(i * 2), s,
                            Eigen::Vector3d(1, 0.1 * i, 0.2));
  }
  return e;
}

std::string temp_dir() {
  static const std::string dir = [] {
    auto d = std::filesystem::temp_directory_path() / ("eoir_bench_state_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d.string();
  }();
  return dir;
}

void BM_EngineToJson(benchmark::State& state) {
  auto e = make_state_engine();
  for (auto _ : state) {
    nlohmann::json doc = eoir::state::engine_to_json(*e);
    benchmark::DoNotOptimize(doc);
  }
  state.counters["json_bytes"] = static_cast<double>(eoir::state::engine_to_json(*e).dump().size());
}

void BM_EngineFromJson(benchmark::State& state) {
  const nlohmann::json doc = eoir::state::engine_to_json(*make_state_engine());
  for (auto _ : state) {
    auto e = eoir::state::engine_from_json(doc, eoir::EngineOptions{});
    benchmark::DoNotOptimize(e.get());
  }
}

// Serialise to text and parse back (what a host doing its own I/O pays).
void BM_JsonDumpParse(benchmark::State& state) {
  const nlohmann::json doc = eoir::state::engine_to_json(*make_state_engine());
  for (auto _ : state) {
    const std::string text = doc.dump(2);
    nlohmann::json back = eoir::state::parse_document(text, "bench");
    benchmark::DoNotOptimize(back);
  }
}

void BM_SaveEngine(benchmark::State& state) {
  auto e = make_state_engine();
  const std::string path = temp_dir() + "/save.scd";
  for (auto _ : state) eoir::state::save_engine(*e, path);
  state.counters["file_bytes"] = static_cast<double>(std::filesystem::file_size(path));
  std::filesystem::remove(path);
}

void BM_LoadEngine(benchmark::State& state) {
  const std::string path = temp_dir() + "/load.scd";
  eoir::state::save_engine(*make_state_engine(), path);
  for (auto _ : state) {
    auto e = eoir::state::load_engine(path, eoir::EngineOptions{});
    benchmark::DoNotOptimize(e.get());
  }
  std::filesystem::remove(path);
}

// A restore followed by the first render of the smallest sensor (static
// metrics recomputed after the restore): what "resume" costs a host.
void BM_LoadEngineAndRender(benchmark::State& state) {
  const std::string path = temp_dir() + "/load_render.scd";
  eoir::state::save_engine(*make_state_engine(), path);
  for (auto _ : state) {
    auto e = eoir::state::load_engine(path, eoir::EngineOptions{});
    const auto& f = e->render("Sensor0");
    benchmark::DoNotOptimize(f.sensor.electrons.data());
  }
  std::filesystem::remove(path);
}

}  // namespace

BENCHMARK(BM_EngineToJson)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EngineFromJson)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_JsonDumpParse)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SaveEngine)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LoadEngine)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LoadEngineAndRender)->Unit(benchmark::kMillisecond)->UseRealTime();

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::filesystem::remove_all(temp_dir());
  return 0;
}

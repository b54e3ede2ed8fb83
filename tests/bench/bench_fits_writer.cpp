// Memory of the FITS writer (issue 23 item 2: FITS written as the frame
// streams). BM_WriteFitsImage writes an n x n float32 image from doubles
// and reports, besides the time, how far the process's peak resident set
// (getrusage ru_maxrss) rose above its level with the pixels already in
// memory: the writer's own memory. The previous writer assembled the whole
// file in memory (+n^2 x 4 bytes); the streamed one holds cfitsio's buffers
// and a row. Cases run in increasing size, so each one's pixels lift the
// peak above the previous case's before it is measured.
#include <benchmark/benchmark.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

#include "fits_writer.hpp"

namespace {

double peak_rss_MiB() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

void BM_WriteFitsImage(benchmark::State& state) {
  const auto n = static_cast<std::int64_t>(state.range(0));
  std::vector<double> pixels(static_cast<std::size_t>(n * n));
  for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = static_cast<double>(i % 1000) * 0.5;
  const std::string path = "/tmp/eoir_bench_fits_writer_" + std::to_string(::getpid()) + ".fits";
  eoir::imageio::FitsHeader header;
  header.set_string("BUNIT", "electrons");
  const double before = peak_rss_MiB();
  for (auto _ : state) eoir::imageio::write_fits_image(path, pixels.data(), n, n, header);
  std::remove(path.c_str());
  state.counters["peak_rss_rise_MiB"] = peak_rss_MiB() - before;
  state.counters["file_MiB"] = static_cast<double>(n * n) * 4.0 / 1048576.0;
  state.SetBytesProcessed(state.iterations() * n * n * 4);
}
BENCHMARK(BM_WriteFitsImage)->Arg(1024)->Arg(4096)->Arg(8192)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace

BENCHMARK_MAIN();

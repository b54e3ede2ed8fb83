// The surface maps' levels (universe/surface_map.hpp): rows decoded on first
// use into one block of address space per level, by whichever thread asks
// first; corrupt row tables refused with the file named.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

#include "core/error.hpp"
#include "universe/surface_map.hpp"

namespace {
namespace fs = std::filesystem;
using eoir::universe::RasterLevel;

// A width x height run-length-encoded level (EOIRRLE1: magic, width, height,
// height + 1 row offsets, then (value, count low, count high) runs) whose
// cell (i, j) is cell(i, j); returns its sidecar's path.
template <class Cell>
std::string write_rle_level(const fs::path& dir, std::uint32_t width, std::uint32_t height, Cell cell,
                            bool offsets_out_of_order = false, bool constant_rows = false) {
  fs::create_directories(dir);
  std::vector<std::vector<std::uint8_t>> rows(height);
  for (std::uint32_t i = 0; i < height; ++i)
    for (std::uint32_t j = 0; j < width;) {
      const std::uint8_t v = cell(i, j);
      std::uint32_t n = constant_rows ? std::min<std::uint32_t>(65535, width - j) : 1;
      while (j + n < width && n < 65535 && cell(i, j + n) == v) ++n;
      rows[i].insert(rows[i].end(), {v, static_cast<std::uint8_t>(n & 0xff), static_cast<std::uint8_t>(n >> 8)});
      j += n;
    }
  std::vector<std::uint64_t> offsets{16 + 8 * (std::uint64_t{height} + 1)};
  for (const auto& r : rows) offsets.push_back(offsets.back() + r.size());
  if (offsets_out_of_order && height >= 2) std::swap(offsets[0], offsets[1]);
  std::ofstream f(dir / "level.rle", std::ios::binary);
  const std::uint32_t dims[2] = {width, height};
  f.write("EOIRRLE1", 8);
  f.write(reinterpret_cast<const char*>(dims), 8);
  f.write(reinterpret_cast<const char*>(offsets.data()), static_cast<std::streamsize>(8 * offsets.size()));
  for (const auto& r : rows) f.write(reinterpret_cast<const char*>(r.data()), static_cast<std::streamsize>(r.size()));
  f.close();
  std::ofstream s(dir / "level.json");
  s << R"({"format": "eoir-raster", "registration": "cell", "encoding": "uint8-rle", "file": "level.rle",)"
    << " \"width\": " << width << ", \"height\": " << height << R"(, "lon_west_deg": -180.0, "lat_north_deg": 90.0,)"
    << " \"cell_deg\": " << 180.0 / height << "}";
  return (dir / "level.json").string();
}

std::uint8_t pattern(std::uint32_t i, std::uint32_t j) { return static_cast<std::uint8_t>((i * 7 + j / 3) % 251); }

fs::path temp_dir(const char* name) {
  return fs::temp_directory_path() / ("eoir_surface_map_test_" + std::to_string(::getpid()) + "_" + name);
}

// Every cell read back, by two threads at once that start from opposite ends
// (so that both decode rows and ask for rows the other is decoding).
TEST(SurfaceMap, RowsDecodedByConcurrentThreadsReadEveryCell) {
  const fs::path dir = temp_dir("concurrent");
  constexpr std::uint32_t kWidth = 720, kHeight = 360;
  const auto level = RasterLevel::load(write_rle_level(dir, kWidth, kHeight, pattern));
  const double cell = 180.0 / kHeight;
  std::vector<int> wrong(2, 0);
  const auto read_all = [&](int t) {
    for (std::uint32_t k = 0; k < kHeight; ++k) {
      const std::uint32_t i = t == 0 ? k : kHeight - 1 - k;
      for (std::uint32_t j = 0; j < kWidth; j += 7)
        if (level->at(90.0 - (i + 0.5) * cell, -180.0 + (j + 0.5) * cell) != pattern(i, j)) ++wrong[t];
    }
  };
  std::thread other(read_all, 1);
  read_all(0);
  other.join();
  EXPECT_EQ(wrong[0], 0);
  EXPECT_EQ(wrong[1], 0);
  fs::remove_all(dir);
}

// A row table out of order is a corrupt file, named (it would have read
// rows of negative length).
TEST(SurfaceMap, RowOffsetsOutOfOrderAreACorruptFile) {
  const fs::path dir = temp_dir("corrupt");
  const std::string sidecar = write_rle_level(dir, 64, 32, pattern, true);
  try {
    RasterLevel::load(sidecar);
    FAIL() << "loaded a level whose row offsets are out of order";
  } catch (const eoir::Error& e) {
    EXPECT_EQ(e.status(), eoir::Status::corrupt_file);
    EXPECT_NE(std::string(e.what()).find("level.rle"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("row offsets"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

double resident_mib() {
  std::ifstream statm("/proc/self/statm");
  double pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * static_cast<double>(::sysconf(_SC_PAGESIZE)) / (1 << 20);
}

// A level's block is address space, not memory: a 1,000,000 x 50,000 map
// (50 GB of cells) loads and reads cells of three rows at the cost of those
// rows (a huge page each at most).
TEST(SurfaceMap, AHugeLevelCostsOnlyTheRowsRead) {
  const fs::path dir = temp_dir("huge");
  constexpr std::uint32_t kWidth = 1000000, kHeight = 50000;
  const std::string sidecar = write_rle_level(
      dir, kWidth, kHeight, [](std::uint32_t i, std::uint32_t) { return static_cast<std::uint8_t>(i % 200); }, false,
      true);
  const double before_mib = resident_mib();
  const auto level = RasterLevel::load(sidecar);
  const double cell = 180.0 / kHeight;
  for (std::uint32_t i : {0u, 12345u, 49999u}) EXPECT_EQ(level->at(90.0 - (i + 0.5) * cell, 10.0), i % 200);
  EXPECT_LT(resident_mib() - before_mib, 64.0);
  fs::remove_all(dir);
}

}  // namespace

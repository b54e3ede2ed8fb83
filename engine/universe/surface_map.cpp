#include "universe/surface_map.hpp"

#include <sys/mman.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "core/error.hpp"
#include "core/read_file.hpp"
#include "universe/json_document.hpp"

namespace eoir::universe {
namespace {
using nlohmann::json;

// floor(x) as an index, for |x| within the int64 range (std::floor is a
// library call per lookup on the baseline x86-64 target).
std::int64_t floor_index(double x) {
  const auto i = static_cast<std::int64_t>(x);  // toward zero
  return static_cast<double>(i) > x ? i - 1 : i;
}

[[noreturn]] void corrupt(const std::string& where, const std::string& what) {
  throw Error(Status::corrupt_file, where + ": " + what);
}

json read_json(const std::string& path) {
  return parse_json_document(read_file(path, std::size_t{1} << 20, "map sidecar files"), path);
}

// The kernel's huge page on x86-64 (2 MiB): a level's block starts on one.
constexpr std::size_t kHugePageBytes = std::size_t{1} << 21;
// Levels up to this size are advised to use huge pages (the Earth's L0 and
// L1, 1-58 MB). Larger ones (L2, 933 MB) keep 4 KiB pages: a scattered read
// (patch centres over the globe) would commit a huge page per row read.
constexpr std::size_t kHugePageLevelMaxBytes = std::size_t{256} << 20;
}  // namespace

RasterLevel::~RasterLevel() {
  if (mapping_) ::munmap(mapping_, mapped_bytes_);
}

std::unique_ptr<RasterLevel> RasterLevel::load(const std::string& sidecar) {
  const json j = read_json(sidecar);
  std::unique_ptr<RasterLevel> r(new RasterLevel);
  try {
    if (j.at("format").get<std::string>() != "eoir-raster") corrupt(sidecar + ": format", "must be eoir-raster");
    if (j.at("registration").get<std::string>() != "cell") corrupt(sidecar + ": registration", "must be cell");
    // (integers only: a float such as 1e112 has no int64 to convert to)
    const auto integer = [&](const char* key) {
      if (!j.at(key).is_number_integer()) corrupt(sidecar + ": " + key, "must be an integer");
      return j.at(key).get<std::int64_t>();
    };
    r->width_ = integer("width");
    r->height_ = integer("height");
    r->lon_west_deg_ = j.at("lon_west_deg").get<double>();
    r->lat_north_deg_ = j.at("lat_north_deg").get<double>();
    r->cell_deg_ = j.at("cell_deg").get<double>();
    r->cells_per_degree_ = j.contains("cells_per_degree") ? integer("cells_per_degree") : 0;
    r->value_scale_ = j.value("value_scale", 1.0);
    r->value_offset_ = j.value("value_offset", 0.0);
    const std::string encoding = j.at("encoding").get<std::string>();
    if (encoding != "uint8" && encoding != "uint8-rle") corrupt(sidecar + ": encoding", "must be uint8 or uint8-rle");
    r->rle_ = encoding == "uint8-rle";
    r->data_path_ = (std::filesystem::path(sidecar).parent_path() / j.at("file").get<std::string>()).string();
  } catch (const json::exception& e) {
    corrupt(sidecar, std::string("missing or mistyped field: ") + e.what());
  }
  if (r->width_ <= 0 || r->height_ <= 0 || r->width_ > 1000000 || r->height_ > 1000000 || !(r->cell_deg_ > 0))
    corrupt(sidecar, "width, height and cell_deg must be positive");
  // Integer cells per degree where the map has them (exact registration).
  r->per_degree_ = r->cells_per_degree_ > 0 ? static_cast<double>(r->cells_per_degree_) : 1.0 / r->cell_deg_;
  r->global_ = std::fabs(static_cast<double>(r->width_) / r->per_degree_ - 360.0) < 1e-9;
  struct stat st {};  // rows are read on demand: the raster must be a regular file
  if (::stat(r->data_path_.c_str(), &st) == 0) require_regular_file(r->data_path_, st.st_mode);
  std::ifstream data(r->data_path_, std::ios::binary);
  if (!data) throw Error(Status::io, "map: cannot read '" + r->data_path_ + "'");
  data.seekg(0, std::ios::end);
  const auto size = static_cast<std::uint64_t>(data.tellg());
  if (r->rle_) {
    char magic[8];
    std::uint32_t dims[2];
    data.seekg(0);
    data.read(magic, 8);
    data.read(reinterpret_cast<char*>(dims), 8);
    if (!data || std::memcmp(magic, "EOIRRLE1", 8) != 0 || dims[0] != r->width_ || dims[1] != r->height_)
      corrupt(r->data_path_, "not an EOIRRLE1 file of the sidecar's size");
    r->offsets_.resize(static_cast<std::size_t>(r->height_ + 1));
    data.read(reinterpret_cast<char*>(r->offsets_.data()), static_cast<std::streamsize>(8 * r->offsets_.size()));
    if (!data || r->offsets_.back() != size) corrupt(r->data_path_, "truncated row table");
    if (r->offsets_.front() < 16 + 8 * r->offsets_.size() ||
        !std::is_sorted(r->offsets_.begin(), r->offsets_.end()))
      corrupt(r->data_path_, "row offsets out of order");
  } else if (size != static_cast<std::uint64_t>(r->width_ * r->height_)) {
    corrupt(r->data_path_, "size is not width x height bytes");
  }
  // Address space for every cell (pages are committed as rows are written:
  // MAP_NORESERVE), backed by huge pages up to kHugePageLevelMaxBytes, by
  // 4 KiB pages past it (also where the kernel uses huge pages unasked).
  const std::size_t bytes = static_cast<std::size_t>(r->width_) * static_cast<std::size_t>(r->height_);
  r->mapped_bytes_ = bytes + kHugePageBytes;
  void* m = ::mmap(nullptr, r->mapped_bytes_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  if (m == MAP_FAILED)
    throw Error(Status::limit_exceeded, sidecar + ": width x height (" + std::to_string(bytes) +
                                            " bytes) exceeds the address space the system grants");
  r->mapping_ = m;
  const auto start = (reinterpret_cast<std::uintptr_t>(m) + kHugePageBytes - 1) & ~(kHugePageBytes - 1);
  r->cells_ = reinterpret_cast<std::uint8_t*>(start);
#if defined(MADV_HUGEPAGE) && defined(MADV_NOHUGEPAGE)
  ::madvise(r->cells_, (bytes + kHugePageBytes - 1) & ~(kHugePageBytes - 1),
            bytes <= kHugePageLevelMaxBytes ? MADV_HUGEPAGE : MADV_NOHUGEPAGE);  // (advice only)
#endif
  r->rows_ = std::make_unique<std::atomic<const std::uint8_t*>[]>(static_cast<std::size_t>(r->height_));
  r->claimed_ = std::make_unique<std::atomic<bool>[]>(static_cast<std::size_t>(r->height_));
  for (std::int64_t i = 0; i < r->height_; ++i) {
    r->rows_[static_cast<std::size_t>(i)].store(nullptr);
    r->claimed_[static_cast<std::size_t>(i)].store(false);
  }
  return r;
}

const std::uint8_t* RasterLevel::decode_row(std::int64_t i) const {
  const auto k = static_cast<std::size_t>(i);
  std::uint8_t* into = cells_ + k * static_cast<std::size_t>(width_);
  // One thread decodes a row; the others wait for it (a failed decode
  // releases its claim).
  for (;;) {
    if (const std::uint8_t* ready = rows_[k].load(std::memory_order_acquire)) return ready;
    if (!claimed_[k].exchange(true, std::memory_order_acq_rel)) {
      try {
        read_row(i, into);
      } catch (...) {
        claimed_[k].store(false, std::memory_order_release);
        throw;
      }
      rows_[k].store(into, std::memory_order_release);
      return into;
    }
    std::this_thread::yield();
  }
}

void RasterLevel::read_row(std::int64_t i, std::uint8_t* into) const {
  const auto width = static_cast<std::size_t>(width_);
  std::fill_n(into, width, std::uint8_t{0});  // (cells a short file leaves out read 0)
  std::ifstream f(data_path_, std::ios::binary);
  if (rle_) {
    const auto begin = offsets_[static_cast<std::size_t>(i)], end = offsets_[static_cast<std::size_t>(i + 1)];
    std::vector<std::uint8_t> runs(end - begin);
    f.seekg(static_cast<std::streamoff>(begin));
    f.read(reinterpret_cast<char*>(runs.data()), static_cast<std::streamsize>(runs.size()));
    std::size_t x = 0;
    for (std::size_t k = 0; k + 2 < runs.size() && x < width; k += 3) {
      const std::size_t n = std::min<std::size_t>(runs[k + 1] | (runs[k + 2] << 8), width - x);
      std::fill_n(into + x, n, runs[k]);
      x += n;
    }
  } else {
    f.seekg(static_cast<std::streamoff>(i * width_));
    f.read(reinterpret_cast<char*>(into), static_cast<std::streamsize>(width_));
  }
}

void RasterLevel::cell(double latitude_deg, double longitude_deg, std::int64_t& i, std::int64_t& j) const {
  // (Truncation toward zero, not floor: the index is clamped to [0, n) and
  // the two differ only below 0; the wrapped longitude is never negative.)
  i = static_cast<std::int64_t>((lat_north_deg_ - latitude_deg) * per_degree_);
  i = std::clamp<std::int64_t>(i, 0, height_ - 1);
  double lon = longitude_deg - lon_west_deg_;  // wrapped into [0, 360): fmod only off [-360, 360)
  if (lon < -360.0 || lon >= 360.0) lon = std::fmod(lon, 360.0);
  if (lon < 0) lon += 360.0;
  j = static_cast<std::int64_t>(lon * per_degree_);
  j = std::clamp<std::int64_t>(j, 0, width_ - 1);
}

bool RasterLevel::same_grid(const RasterLevel& other) const {
  return width_ == other.width_ && height_ == other.height_ && cells_per_degree_ == other.cells_per_degree_ &&
         lon_west_deg_ == other.lon_west_deg_ && lat_north_deg_ == other.lat_north_deg_ && cell_deg_ == other.cell_deg_;
}

double RasterLevel::interpolated(double latitude_deg, double longitude_deg) const {
  // Position in cells from the centre of cell (0, 0): x in [-0.5, width - 0.5).
  const double last_row = static_cast<double>(height_ - 1);
  const double y = std::clamp((lat_north_deg_ - latitude_deg) * per_degree_ - 0.5, 0.0, last_row);
  double lon = longitude_deg - lon_west_deg_;
  if (lon < -360.0 || lon >= 360.0) lon = std::fmod(lon, 360.0);
  if (lon < 0) lon += 360.0;
  const double x = lon * per_degree_ - 0.5;
  const auto i0 = std::min(static_cast<std::int64_t>(y), height_ - 1), i1 = std::min(i0 + 1, height_ - 1);
  const auto j = floor_index(x);
  const auto column = [&](std::int64_t k) {  // (k in [-1, width])
    if (global_) return k < 0 ? k + width_ : k >= width_ ? k - width_ : k;
    return std::clamp<std::int64_t>(k, 0, width_ - 1);
  };
  const std::int64_t j0 = column(j), j1 = column(j + 1);
  const double u = x - static_cast<double>(j), v = y - static_cast<double>(i0);
  const std::uint8_t* r0 = row(i0);
  const std::uint8_t* r1 = row(i1);
  const double top = (1 - u) * r0[j0] + u * r0[j1], bottom = (1 - u) * r1[j0] + u * r1[j1];
  return value_offset_ + value_scale_ * ((1 - v) * top + v * bottom);
}

std::shared_ptr<const SurfaceMap> SurfaceMap::load(const std::vector<std::string>& sidecars) {
  auto map = std::make_shared<SurfaceMap>();
  for (const auto& s : sidecars) map->levels_.push_back(RasterLevel::load(s));
  if (map->levels_.empty()) throw Error(Status::corrupt_file, "map: no levels");
  return map;
}

const RasterLevel& SurfaceMap::level_for(double gsd_m, double radius_m) const {
  const double deg_per_m = 180.0 / (3.14159265358979323846 * radius_m);
  for (const auto& level : levels_)
    if (level->cell_deg() <= gsd_m * deg_per_m) return *level;
  return *levels_.back();
}

}  // namespace eoir::universe

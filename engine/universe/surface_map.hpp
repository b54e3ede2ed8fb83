// Bitmaps over a central body's surface (spec 4.2.3): the Earth's land/water
// mask and land-cover classes (IGBP 1-17, tundra 18; data/earth/README.md),
// the Moon's and Mars' normal albedo (data/moon/README.md). Each map is a
// pyramid of levels sharing one registration (cell: rows north to south from
// lat_north, columns east from lon_west); the level used is the coarsest whose
// cell is not larger than the ground sample distance. Rows of the fine
// levels are decoded on first use (thread-safe) into one block of address
// space per level, backed by the kernel's huge pages where it has them for
// levels up to 256 MB (the Earth's L1: a frame's samples read scattered rows,
// and 4 KiB pages cost a page walk per sample, a nested one in a virtual
// machine); larger levels keep 4 KiB pages, committed only where read.
#pragma once
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace eoir::universe {

// One level: a uint8 raster (raw or run-length encoded, eoir-raster format 1).
class RasterLevel {
 public:
  // Reads the JSON sidecar (throws io / corrupt_file naming the file and field).
  static std::unique_ptr<RasterLevel> load(const std::string& sidecar_path);
  ~RasterLevel();
  // The row and column of the cell holding (lat, lon) (deg; longitude any
  // value, wrapped), for reading several levels of one grid at one point.
  struct Cell {
    std::int64_t row = 0, column = 0;
  };
  Cell cell_of(double latitude_deg, double longitude_deg) const {
    Cell c;
    cell(latitude_deg, longitude_deg, c.row, c.column);
    return c;
  }
  // True if `other` has this level's cells (size and registration).
  bool same_grid(const RasterLevel& other) const;
  // The cell holding (lat, lon).
  std::uint8_t at(double latitude_deg, double longitude_deg) const { return at(cell_of(latitude_deg, longitude_deg)); }
  std::uint8_t at(Cell c) const { return row(c.row)[c.column]; }
  // The physical value (value_offset + value_scale x cell) interpolated
  // bilinearly between the four cell centres around (lat, lon) (longitude
  // wrapped on a global map, latitude held at the first and last rows).
  double interpolated(double latitude_deg, double longitude_deg) const;
  // Asks the memory for the cell `at` would read (where its row is decoded):
  // a caller about to read many scattered cells fetches them together.
  void prefetch(double latitude_deg, double longitude_deg) const { prefetch(cell_of(latitude_deg, longitude_deg)); }
  void prefetch(Cell c) const {
    if (const std::uint8_t* r = rows_[static_cast<std::size_t>(c.row)].load(std::memory_order_acquire))
      __builtin_prefetch(r + c.column);
  }
  double cell_deg() const { return cell_deg_; }
  double value_scale() const { return value_scale_; }
  double value_offset() const { return value_offset_; }

 private:
  RasterLevel() = default;
  // width_ cells: the decoded row, decoding it on first use.
  const std::uint8_t* row(std::int64_t i) const {
    if (const std::uint8_t* cached = rows_[static_cast<std::size_t>(i)].load(std::memory_order_acquire)) return cached;
    return decode_row(i);
  }
  const std::uint8_t* decode_row(std::int64_t i) const;
  // Reads row i into its place in cells_.
  void read_row(std::int64_t i, std::uint8_t* into) const;
  // The row and column of the cell holding (lat, lon).
  void cell(double latitude_deg, double longitude_deg, std::int64_t& i, std::int64_t& j) const;
  std::string data_path_;
  bool rle_ = false;
  std::int64_t width_ = 0, height_ = 0, cells_per_degree_ = 0;
  double lon_west_deg_ = -180, lat_north_deg_ = 90, cell_deg_ = 1;
  double per_degree_ = 1;  // cells per degree: cells_per_degree_ where given, else 1 / cell_deg_
  bool global_ = false;    // the columns go round the globe (interpolation wraps)
  double value_scale_ = 1, value_offset_ = 0;
  std::vector<std::uint64_t> offsets_;  // rle: height + 1 row offsets
  // width x height cells, reserved at load, pages committed as rows are decoded.
  void* mapping_ = nullptr;
  std::size_t mapped_bytes_ = 0;
  std::uint8_t* cells_ = nullptr;  // (mapping_ rounded up to a huge page)
  // Row i's cells once decoded (null before); claimed_[i]: a thread decodes it.
  mutable std::unique_ptr<std::atomic<const std::uint8_t*>[]> rows_;
  mutable std::unique_ptr<std::atomic<bool>[]> claimed_;
};

class SurfaceMap {
 public:
  // Levels from coarse to fine (sidecar paths).
  static std::shared_ptr<const SurfaceMap> load(const std::vector<std::string>& sidecars);
  // The coarsest level whose cell is not larger than gsd_m on a body of
  // radius radius_m (the finest if none).
  const RasterLevel& level_for(double gsd_m, double radius_m) const;
  const RasterLevel& finest() const { return *levels_.back(); }

 private:
  std::vector<std::unique_ptr<RasterLevel>> levels_;
};

// A central body's maps in the data folder (empty pointers where there are
// none): the Earth's land mask and land cover, the brightness of its land
// relative to its class and its cloud fraction (data/earth/README.md), the
// Moon's and Mars' albedo.
struct BodyMaps {
  std::shared_ptr<const SurfaceMap> land_mask;
  std::shared_ptr<const SurfaceMap> land_cover;
  std::shared_ptr<const SurfaceMap> land_brightness;
  std::shared_ptr<const SurfaceMap> clouds;
  std::shared_ptr<const SurfaceMap> albedo;
};

}  // namespace eoir::universe

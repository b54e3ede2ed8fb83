// Spec 6.1.3 (V_Test3, bitmap registration) in scene mode bitmap:
//  1. A sensor over Los Angeles pointed at the Point Fermin lighthouse
//     (33.705 N, 118.294 W; scenarios/validation/v_test3.json) picks, at the
//     centre of its field, a point within one bitmap cell (30", 0.93 km) of
//     the lighthouse; and the image registers the land-cover bitmap there:
//     GSHHG puts the lighthouse just seaward of its shoreline, so the samples
//     in the lighthouse's cell are water and those in the cell north of it
//     land (data/earth/README.md).
//  2. At the mouth of the Amazon (v_test3_amazon.json), where the spec's own
//     engine showed the bitmap 2.5 km off in longitude, every land/water
//     transition of the image lies within one cell of the GSHHG shoreline,
//     read here independently from the Debian gmt-gshhg files through GMT
//     (`gmt coast -Dh -W -M`, the same high-resolution shoreline the land
//     mask was made from), not from the engine's converted raster.
// Water and land are told apart in 0.8-0.9 um by day: IGBP 17 water has an
// SRF of 0.02 there, every land class 0.3 or more (the scenario's gray-body
// 0.3 stands for the classes without a material yet).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include "validation_support.hpp"

namespace v = eoir::validation;
using eoir::test::ScenarioHost;

namespace {

constexpr double kCellDeg = 1.0 / 120.0;            // the finest level's cell (30")
constexpr double kCellKm = kCellDeg * v::kDeg * 6378.137;  // 0.927 km on the equator

struct LatLon {
  double lat, lon;
};

long cell_row(double lat) { return static_cast<long>(std::floor((90.0 - lat) * 120.0)); }
long cell_col(double lon) { return static_cast<long>(std::floor((lon + 180.0) * 120.0)); }

// Great-circle-free local distance (km) between nearby points.
double km(const LatLon& a, const LatLon& b) {
  const double k = v::kDeg * 6371.0;
  return std::hypot((a.lat - b.lat) * k, (a.lon - b.lon) * k * std::cos(0.5 * (a.lat + b.lat) * v::kDeg));
}

// Distance (km) from p to the segment ab, in a local plane about p.
double km_to_segment(const LatLon& p, const LatLon& a, const LatLon& b) {
  const double k = v::kDeg * 6371.0, c = std::cos(p.lat * v::kDeg);
  const double ax = (a.lon - p.lon) * k * c, ay = (a.lat - p.lat) * k;
  const double bx = (b.lon - p.lon) * k * c, by = (b.lat - p.lat) * k;
  const double dx = bx - ax, dy = by - ay, L2 = dx * dx + dy * dy;
  const double t = L2 > 0 ? std::clamp(-(ax * dx + ay * dy) / L2, 0.0, 1.0) : 0.0;
  return std::hypot(ax + t * dx, ay + t * dy);
}

// GSHHG high-resolution shorelines (all levels) in a box, as polylines.
std::vector<std::vector<LatLon>> gshhg_shorelines(double west, double east, double south, double north) {
  // GMT writes gmt.history into GMT_TMPDIR (else the working directory): a
  // temporary folder, removed afterwards.
  const std::string tmp = (std::filesystem::temp_directory_path() / "eoir_gmt_XXXXXX").string();
  std::vector<char> dir(tmp.begin(), tmp.end());
  dir.push_back('\0');
  if (!mkdtemp(dir.data())) throw std::runtime_error("mkdtemp " + tmp);
  struct Remove {
    std::string path;
    ~Remove() {
      std::error_code ec;
      std::filesystem::remove_all(path, ec);
    }
  } remove{dir.data()};
  char cmd[1024];
  std::snprintf(cmd, sizeof cmd, "GMT_TMPDIR='%s' \"%s\" coast -R%.6f/%.6f/%.6f/%.6f -Dh -W -M 2>/dev/null", dir.data(),
                EOIR_GMT_EXECUTABLE, west, east, south, north);
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd, "r"), pclose);
  if (!pipe) throw std::runtime_error(std::string("cannot run ") + cmd);
  std::vector<std::vector<LatLon>> lines;
  char buf[256];
  while (std::fgets(buf, sizeof buf, pipe.get())) {
    if (buf[0] == '>') {
      lines.emplace_back();
      continue;
    }
    double lon = 0, lat = 0;
    if (std::sscanf(buf, "%lf %lf", &lon, &lat) != 2) continue;
    if (lines.empty()) lines.emplace_back();
    lines.back().push_back({lat, lon});
  }
  return lines;
}

double km_to_shore(const LatLon& p, const std::vector<std::vector<LatLon>>& lines) {
  double best = 1e9;
  for (const auto& l : lines) {
    if (l.size() == 1) best = std::min(best, km(p, l[0]));
    for (std::size_t i = 0; i + 1 < l.size(); ++i) best = std::min(best, km_to_segment(p, l[i], l[i + 1]));
  }
  return best;
}

// Water if the sample is darker than a quarter of the brightest (land) sample.
struct Classified {
  eoir::test::Image image;
  double threshold = 0;
  bool water(int x, int y) const { return image.at(x, y) < threshold; }
};

Classified render_classified(ScenarioHost& host) {
  host.render();
  Classified c;
  c.image = host.image(EOIR_IMAGE_SCENE_RADIANCE);
  // Water (one material, no texture) is the image's darkest; land, whose
  // brightness varies within its class (the Blue Marble's, issue 20), is 30x
  // brighter and more in 0.8-0.9 um (vegetation's SRF ~0.3-0.5 against
  // water's 0.01): 10x the darkest sample separates them.
  c.threshold = 10.0 * *std::min_element(c.image.values.begin(), c.image.values.end());
  EXPECT_GT(c.threshold, 0.0) << "a sample sees no Earth";
  return c;
}

bool have_gmt() { return std::string(EOIR_GMT_EXECUTABLE).size() > 0; }

}  // namespace

TEST(Spec_6_1_3, PointFerminCentreSampleAndItsBitmapCells) {
  const LatLon fermin{33.705, -118.294};
  ScenarioHost host("v_test3.json");
  const Classified img = render_classified(host);
  const int n = img.image.width;
  ASSERT_EQ(n, 512);
  const auto centre = host.pick(n / 2, n / 2);
  ASSERT_TRUE(centre.hit);
  ASSERT_EQ(centre.object, "Earth");
  std::printf("centre sample: %.5f N %.5f E (lighthouse %.3f N %.3f E), %.3f km apart\n", centre.lat_deg,
              centre.lon_deg, fermin.lat, fermin.lon, km({centre.lat_deg, centre.lon_deg}, fermin));
  EXPECT_NEAR(centre.lat_deg, fermin.lat, kCellDeg);
  EXPECT_NEAR(centre.lon_deg, fermin.lon, kCellDeg);
  // The spec's own detail dialog: -118.293, 33.705 (within 0.001 deg).
  EXPECT_NEAR(centre.lat_deg, 33.705, 0.001);
  EXPECT_NEAR(centre.lon_deg, -118.293, 0.0015);

  // The samples in the lighthouse's cell are water, those in the cell north
  // of it land (samples 48 m apart: each cell holds about 19 x 16).
  const long i0 = cell_row(fermin.lat), j0 = cell_col(fermin.lon);
  int in_cell = 0, in_cell_water = 0, north = 0, north_land = 0;
  for (int y = n / 2 - 60; y <= n / 2 + 60; y += 2)
    for (int x = n / 2 - 60; x <= n / 2 + 60; x += 2) {
      const auto p = host.pick(x, y);
      if (!p.hit) continue;
      const long i = cell_row(p.lat_deg), j = cell_col(p.lon_deg);
      if (i == i0 && j == j0) {
        ++in_cell;
        in_cell_water += img.water(x, y);
      } else if (i == i0 - 1 && j == j0) {
        ++north;
        north_land += !img.water(x, y);
      }
    }
  std::printf("lighthouse cell: %d of %d samples water; cell north: %d of %d land\n", in_cell_water, in_cell,
              north_land, north);
  ASSERT_GT(in_cell, 20);
  ASSERT_GT(north, 20);
  EXPECT_EQ(in_cell_water, in_cell);
  EXPECT_EQ(north_land, north);
}

TEST(Spec_6_1_3, AmazonMouthCoastRegisteredWithinOneCellOfGshhg) {
  // GMT (Debian gmt, gmt-gshhg-high) is installed by .ci/setup and makes the
  // Earth bitmaps: missing, it is a failed install step, not a reason to skip.
  ASSERT_TRUE(have_gmt()) << "GMT not found at configure time: install the Debian packages gmt and gmt-gshhg-high "
                             "(.ci/setup)";
  ScenarioHost host("v_test3_amazon.json");
  const Classified img = render_classified(host);
  const int n = img.image.width;
  // Transitions between neighbouring samples along rows and columns; the
  // boundary lies between their two picked points.
  std::vector<LatLon> boundary;
  double west = 1e9, east = -1e9, south = 1e9, north = -1e9;
  int water = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      water += img.water(x, y);
      for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
        if (x + dx >= n || y + dy >= n || img.water(x, y) == img.water(x + dx, y + dy)) continue;
        const auto a = host.pick(x, y), b = host.pick(x + dx, y + dy);
        ASSERT_TRUE(a.hit && b.hit);
        const LatLon m{0.5 * (a.lat_deg + b.lat_deg), 0.5 * (a.lon_deg + b.lon_deg)};
        boundary.push_back(m);
        west = std::min(west, m.lon);
        east = std::max(east, m.lon);
        south = std::min(south, m.lat);
        north = std::max(north, m.lat);
      }
    }
  const double water_fraction = static_cast<double>(water) / (n * n);
  {
    const auto c = host.pick(n / 2, n / 2), e = host.pick(n - 1, n / 2), w = host.pick(0, n / 2);
    std::printf("centre %.4f %.4f L %.4g; right edge %.4f %.4f L %.4g; left edge %.4f %.4f L %.4g; water below %.4g\n",
                c.lat_deg, c.lon_deg, img.image.at(n / 2, n / 2), e.lat_deg, e.lon_deg, img.image.at(n - 1, n / 2),
                w.lat_deg, w.lon_deg, img.image.at(0, n / 2), img.threshold);
  }
  std::printf("water %.1f %% of the samples, %zu land/water transitions\n", 100 * water_fraction, boundary.size());
  ASSERT_GT(water_fraction, 0.1);
  ASSERT_LT(water_fraction, 0.9);
  ASSERT_GT(boundary.size(), 100u);

  const auto shore = gshhg_shorelines(west - 0.05, east + 0.05, south - 0.05, north + 0.05);
  ASSERT_FALSE(shore.empty()) << "no GSHHG shoreline read";
  std::vector<double> d;
  for (const LatLon& m : boundary) d.push_back(km_to_shore(m, shore));
  std::sort(d.begin(), d.end());
  const double median = d[d.size() / 2], p95 = d[d.size() * 95 / 100], worst = d.back();
  std::printf("distance of the transitions to the GSHHG shoreline: median %.3f km, 95 %% %.3f km, max %.3f km "
              "(cell %.3f km)\n", median, p95, worst, kCellKm);
  // A cell is water or land by its centre (GMT grdlandmask -r), so the
  // raster's boundary runs between a land and a water cell centre, at most a
  // cell diagonal from the shore; the sample pair adds half a 0.3 km sample.
  EXPECT_LT(median, 0.5 * kCellKm);
  EXPECT_LT(p95, kCellKm);
  EXPECT_LT(worst, std::sqrt(2.0) * kCellKm + 0.5 * 0.3);

  // The check sees the spec's defect: the same transitions moved 2.5 km in
  // longitude are mostly more than a cell from the shore.
  std::vector<double> shifted;
  for (const LatLon& m : boundary)
    shifted.push_back(km_to_shore({m.lat, m.lon + 2.5 / (v::kDeg * 6371.0 * std::cos(m.lat * v::kDeg))}, shore));
  std::sort(shifted.begin(), shifted.end());
  std::printf("the same, moved 2.5 km east: median %.3f km\n", shifted[shifted.size() / 2]);
  EXPECT_GT(shifted[shifted.size() / 2], kCellKm);
}

#include "machine_floor.hpp"

#include <embree3/rtcore.h>
#include <fftw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <mutex>
#include <thread>
#include <tuple>
#include <vector>

namespace eoir::bench {
namespace {

using clk = std::chrono::steady_clock;
double ms_between(clk::time_point a, clk::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

template <class F>
void on_threads(unsigned threads, F f) {
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < threads; ++t) pool.emplace_back(f, t);
  for (auto& t : pool) t.join();
}

double packet_cast_ms(int n, unsigned threads) {
  RTCDevice device = rtcNewDevice(nullptr);
  RTCScene scene = rtcNewScene(device);
  RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  const int nu = 512, nv = 256;  // ~262k triangles
  auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), (nu + 1) * (nv + 1)));
  auto* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                             3 * sizeof(unsigned), 2 * nu * nv));
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const double th = M_PI * j / nv, ph = 2 * M_PI * i / nu;
      float* v = vb + 3 * (j * (nu + 1) + i);
      v[0] = static_cast<float>(std::sin(th) * std::cos(ph));
      v[1] = static_cast<float>(std::sin(th) * std::sin(ph));
      v[2] = static_cast<float>(5.0 + std::cos(th));
    }
  for (int j = 0, t = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i, t += 2) {
      const unsigned a = static_cast<unsigned>(j * (nu + 1) + i), b = a + 1, c = a + nu + 1, d = c + 1;
      const unsigned tri[6] = {a, c, b, b, c, d};
      std::copy(tri, tri + 6, ib + 3 * t);
    }
  rtcCommitGeometry(g);
  rtcAttachGeometry(scene, g);
  rtcReleaseGeometry(g);
  rtcCommitScene(scene);
  const float half = static_cast<float>(std::tan(0.25));  // ~28.6 deg field
  std::vector<float> out(static_cast<std::size_t>(n) * n);
  auto cast16 = [&](unsigned tid) {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    for (int by = static_cast<int>(tid) * 4; by < n; by += 4 * static_cast<int>(threads))
      for (int bx = 0; bx < n; bx += 4) {
        RTCRayHit16 rh;
        int valid[16];
        for (int k = 0; k < 16; ++k) {
          const int x = bx + k % 4, y = by + k / 4;
          valid[k] = -1;
          rh.ray.org_x[k] = rh.ray.org_y[k] = rh.ray.org_z[k] = 0;
          rh.ray.dir_x[k] = (2.0f * (static_cast<float>(x) + 0.5f) / static_cast<float>(n) - 1) * half;
          rh.ray.dir_y[k] = (2.0f * (static_cast<float>(y) + 0.5f) / static_cast<float>(n) - 1) * half;
          rh.ray.dir_z[k] = 1;
          rh.ray.tnear[k] = 0;
          rh.ray.tfar[k] = 1e30f;
          rh.ray.mask[k] = 0xFFFFFFFFu;
          rh.ray.flags[k] = 0;
          rh.ray.time[k] = 0;
          rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
        }
        rtcIntersect16(valid, scene, &ctx, &rh);
        for (int k = 0; k < 16; ++k)
          out[static_cast<std::size_t>(by + k / 4) * n + static_cast<std::size_t>(bx + k % 4)] = rh.ray.tfar[k];
      }
  };
  on_threads(threads, cast16);  // warm up
  double best = 1e30;
  for (int r = 0; r < 5; ++r) {
    const auto a = clk::now();
    on_threads(threads, cast16);
    best = std::min(best, ms_between(a, clk::now()));
  }
  rtcReleaseScene(scene);
  rtcReleaseDevice(device);
  return best;
}

double fft_ms(int m, unsigned threads) {
  static std::once_flag init;
  std::call_once(init, [] { fftw_init_threads(); });
  fftw_plan_with_nthreads(static_cast<int>(threads));
  const std::size_t real_count = static_cast<std::size_t>(m) * m, complex_count = static_cast<std::size_t>(m) * (m / 2 + 1);
  double* re = fftw_alloc_real(real_count);
  fftw_complex* cx = fftw_alloc_complex(complex_count);
  fftw_plan fw = fftw_plan_dft_r2c_2d(m, m, re, cx, FFTW_MEASURE);
  fftw_plan bw = fftw_plan_dft_c2r_2d(m, m, cx, re, FFTW_MEASURE);
  for (std::size_t i = 0; i < real_count; ++i) re[i] = static_cast<double>(i * 2654435761u % 1000) * 1e-3;
  double best = 1e30;
  for (int r = 0; r < 5; ++r) {
    const auto a = clk::now();
    fftw_execute(fw);
    for (std::size_t i = 0; i < complex_count; ++i) {
      cx[i][0] *= 0.5;
      cx[i][1] *= 0.5;
    }
    fftw_execute(bw);
    best = std::min(best, ms_between(a, clk::now()));
  }
  fftw_destroy_plan(fw);
  fftw_destroy_plan(bw);
  fftw_free(re);
  fftw_free(cx);
  return best;
}

}  // namespace

const MachineFloor& machine_floor(int samples, int fft_n, unsigned threads) {
  static std::mutex mutex;
  static std::map<std::tuple<int, int, unsigned>, MachineFloor> cache;
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  std::lock_guard<std::mutex> lock(mutex);
  const auto key = std::make_tuple(samples, fft_n, threads);
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  MachineFloor f;
  f.samples = samples;
  f.fft_n = fft_n;
  f.threads = threads;
  f.packet_cast_ms = packet_cast_ms(samples, threads);
  f.fft_ms = fft_ms(fft_n, threads);
  return cache[key] = f;
}

const MachineFloor& frame_floor(long pixels, unsigned threads) {
  const int samples = static_cast<int>(4 * pixels);
  return machine_floor(samples, 2 * samples, threads);
}

}  // namespace eoir::bench

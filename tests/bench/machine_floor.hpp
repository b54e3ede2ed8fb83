// What this machine can do for one frame (the floor), measured in the
// benchmark's own process: Embree 3 casting an N^2 sample grid in coherent
// 4x4 packets (rtcIntersect16) against a ~262k-triangle sphere filling ~40 %
// of the view, and one FFTW real-to-complex plus complex-to-real transform of
// M^2 (plan made once with FFTW_MEASURE, not counted); the best of several
// repetitions.
#pragma once

namespace eoir::bench {

struct MachineFloor {
  int samples = 0, fft_n = 0;
  unsigned threads = 0;
  double packet_cast_ms = 0;  // rtcIntersect16, samples^2 rays
  double fft_ms = 0;          // r2c + c2r of fft_n^2
  double floor_ms() const { return packet_cast_ms + fft_ms; }
};

// samples: scene samples per side; fft_n: FFT size per side; threads 0 = all
// cores. Cached per (samples, fft_n, threads) within the process.
const MachineFloor& machine_floor(int samples, int fft_n, unsigned threads = 0);

// The floor of a frame of `pixels` per side at 4 x 4 samples per pixel: the
// scene FFT at twice the sample grid (guard band and padding), as the issue's
// 256^2 example (1024^2 samples, 2048^2 FFT).
const MachineFloor& frame_floor(long pixels, unsigned threads = 0);

}  // namespace eoir::bench

#!/usr/bin/env bash
# Runs every benchmark of the engine and writes tests/bench/results/: one
# Google Benchmark JSON file per run, SUMMARY.md and PNG charts (summarise.py).
# Builds nothing: build first (cmake --build <build dir>).
#
#   tests/bench/run_benchmarks.sh [build dir]     (default: build)
#
# bench_frame runs once per frame case, each in its own process, so that the
# peak RSS it reports (getrusage) belongs to that case alone. The engine's FFT
# plans are measured and kept as FFTW wisdom in $EOIR_FFTW_WISDOM (default
# <build dir>/fftw_wisdom; core/fftw_plans.hpp), as the floor's are measured:
# the first run on a machine spends about a minute more planning. Total run
# time on a 2-core machine: about 5 minutes.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="${1:-build}"
case "$build" in /*) ;; *) build="$root/$build" ;; esac
results="$here/results"
export EOIR_FFTW_WISDOM="${EOIR_FFTW_WISDOM:-$build/fftw_wisdom}"
python="${PYTHON:-/usr/bin/python3}"

for exe in tests/bench/bench_static_metrics tests/bench/bench_frame tests/bench/bench_state \
           tests/bench/bench_band tests/bench/bench_targets tests/bench/bench_point_sources tests/bench/bench_detector \
           tests/geometry/bench_ray_caster tests/bench/bench_eclipse tests/bench/bench_brdf \
           tests/bench/bench_many_objects tests/bench/bench_frame_size tests/bench/bench_motion_substeps; do
  [ -x "$build/$exe" ] || { echo "missing $build/$exe: build first" >&2; exit 1; }
done
mkdir -p "$results"
rm -f "$results"/*.json

# Machine and load, for SUMMARY.md.
{
  echo "date=$(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "nproc=$(nproc)"
  echo "cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')"
  echo "mem=$(free -g | awk '/^Mem:/ {print $2 " GiB"}')"
  echo "uptime_before=$(uptime)"
  echo "commit=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)$(git -C "$root" diff --quiet -- . ':!tests/bench/results' 2>/dev/null || echo ' (+ uncommitted changes)')"
  echo "fftw_wisdom=$EOIR_FFTW_WISDOM"
  echo "build_type=$(grep -m1 '^CMAKE_BUILD_TYPE' "$build/CMakeCache.txt" | cut -d= -f2)"
  echo "compiler=$(grep -m1 '^CMAKE_CXX_COMPILER:' "$build/CMakeCache.txt" | cut -d= -f2) $(grep -h -m1 'CMAKE_CXX_COMPILER_VERSION' "$build/CMakeFiles/"*/CMakeCXXCompiler.cmake 2>/dev/null | head -1 | cut -d'"' -f2)"
} > "$results/machine.txt"

run() {  # run <name> <exe> [args...]
  local name="$1" exe="$2"; shift 2
  echo "== $name" >&2
  "$build/$exe" --benchmark_out="$results/$name.json" --benchmark_out_format=json "$@" >&2
}

run bench_static_metrics tests/bench/bench_static_metrics --benchmark_min_time=0.2
run bench_band tests/bench/bench_band --benchmark_min_time=0.05
run bench_state tests/bench/bench_state --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
run bench_targets tests/bench/bench_targets --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
run bench_point_sources tests/bench/bench_point_sources --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
run bench_detector tests/bench/bench_detector --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
run bench_motion_substeps tests/bench/bench_motion_substeps --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
run bench_ray_caster tests/geometry/bench_ray_caster --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
for px in 128 256 512 1024; do
  for n in 10 100; do
    if [ "$px" = 1024 ]; then reps=1; min=0.01; else reps=3; min=0.5; fi
    run "bench_frame_${px}_${n}" tests/bench/bench_frame --benchmark_filter="^BM_Frame/$px/$n/" \
      --benchmark_min_time=$min --benchmark_repetitions=$reps --benchmark_report_aggregates_only=$([ $reps -gt 1 ] && echo true || echo false)
  done
done
run bench_frame_fidelity tests/bench/bench_frame --benchmark_filter='^BM_Frame(Spectral|PatchSize)/' \
  --benchmark_min_time=0.3
run bench_frame_threads tests/bench/bench_frame --benchmark_filter='^BM_FrameThreads/' --benchmark_min_time=0.5
run bench_frame_sunlight tests/bench/bench_frame --benchmark_filter='^BM_FrameSunlight/' --benchmark_min_time=0.3
run bench_frame_atmosphere tests/bench/bench_frame --benchmark_filter='^BM_FrameAtmosphere/' --benchmark_min_time=2
run bench_frame_mesh tests/bench/bench_frame --benchmark_filter='^BM_FrameMeshTarget' --benchmark_min_time=2
run bench_eclipse tests/bench/bench_eclipse --benchmark_min_time=0.1
run bench_brdf tests/bench/bench_brdf --benchmark_min_time=0.1
run bench_many_objects tests/bench/bench_many_objects
# Frame size: each size in its own process (its peak RSS alone), then the
# 1024^2 and 4096^2 frames in one process for the time-per-pixel ratio.
for px in 256 512 1024 2048 4096 8192; do
  run "bench_frame_size_${px}" tests/bench/bench_frame_size --benchmark_filter="^BM_FrameSize/${px}/0/"
done
run bench_frame_size_ratio tests/bench/bench_frame_size --benchmark_filter='^BM_FrameSize/(1024/[01]|4096/0)/'

echo "uptime_after=$(uptime)" >> "$results/machine.txt"
"$python" "$here/summarise.py" "$results"
echo "wrote $results/SUMMARY.md" >&2

#!/bin/sh
# The engine's layers are enforced by the build: each layer compiles against
# an include folder holding only the layers it may use (engine/CMakeLists.txt).
# For every pair of layers this compiles `#include "<other>/<header>"` with
# the first layer's include folder and checks that exactly the allowed
# includes compile: later layers (and scene <-> sensor) must not.
# usage: check_layers.sh CXX VIEWS_DIR INCLUDE_FLAGS...
set -u
cxx=$1; views=$2; shift 2
header() {
  case $1 in
    core) echo core/limits.hpp ;;
    universe) echo universe/sensor_parameters.hpp ;;
    geometry) echo geometry/sample_grid.hpp ;;
    radiometry) echo radiometry/radiance_image.hpp ;;
    atmosphere) echo atmosphere/us_standard_1976.hpp ;;
    scene) echo scene/thermal_field.hpp ;;
    sensor) echo sensor/spatial_grid.hpp ;;
    metrics) echo metrics/static_providers.hpp ;;
  esac
}
allowed() {  # may layer $1 include layer $2?
  case "$1:$2" in
    core:core) return 0 ;;
    universe:core|universe:universe) return 0 ;;
    geometry:core|geometry:universe|geometry:geometry) return 0 ;;
    radiometry:core|radiometry:universe|radiometry:geometry|radiometry:radiometry) return 0 ;;
    atmosphere:core|atmosphere:universe|atmosphere:geometry|atmosphere:radiometry|atmosphere:atmosphere) return 0 ;;
    scene:core|scene:universe|scene:geometry|scene:radiometry|scene:atmosphere|scene:scene) return 0 ;;
    sensor:core|sensor:universe|sensor:geometry|sensor:radiometry|sensor:sensor) return 0 ;;
    metrics:*) return 0 ;;
  esac
  return 1
}
layers="core universe geometry radiometry atmosphere scene sensor metrics"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
status=0
for from in $layers; do
  for to in $layers; do
    printf '#include "%s"\nint main() { return 0; }\n' "$(header "$to")" > "$tmp/t.cpp"
    if "$cxx" -std=c++17 -fsyntax-only "-I$views/$from" "$@" "$tmp/t.cpp" > "$tmp/out" 2>&1; then compiled=1; else compiled=0; fi
    if allowed "$from" "$to"; then
      [ $compiled = 1 ] || { echo "FAIL: $from cannot include $to:"; head -5 "$tmp/out"; status=1; }
    else
      [ $compiled = 0 ] || { echo "FAIL: $from includes $to against the pipeline order"; status=1; }
    fi
  done
done
[ $status = 0 ] && echo "layers: every include against the direction fails to compile; every allowed one compiles"
exit $status

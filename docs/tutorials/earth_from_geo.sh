#!/bin/sh
# Tutorial "The Earth from GEO, visible and thermal": renders the first time
# step of the bundled demo's two full-disc imagers (Sensor1, 0.45-0.75 um in
# bitmap mode; WideLWIR, 8-12 um) into OUT (default:
# docs/tutorials/results/earth_from_geo):
#   sh docs/tutorials/earth_from_geo.sh [OUT]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out=${1:-$here/results/earth_from_geo}
eoir=${EOIR_CLI:-$here/../../build/bin/eoir}
"$eoir" run "$here/../../scenarios/demo/default.json" --out "$out" --quiet \
  --sensor Sensor1 --sensor WideLWIR --stop 2010-08-25T18:00:00Z
test -f "$out/summary.json"
test -f "$out/Sensor1_0000_sensor.png"
test -f "$out/WideLWIR_0000_sensor.png"

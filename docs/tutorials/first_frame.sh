#!/bin/sh
# Tutorial "Your first frame": renders first_frame.json with the eoir CLI into
# OUT (default: docs/tutorials/results/first_frame). Run from anywhere:
#   sh docs/tutorials/first_frame.sh [OUT]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out=${1:-$here/results/first_frame}
eoir=${EOIR_CLI:-$here/../../build/bin/eoir}
"$eoir" validate "$here/first_frame.json"
"$eoir" run "$here/first_frame.json" --out "$out" --quiet
test -f "$out/summary.json"          # written last: the run is complete
test -f "$out/Camera_0000_sensor.png"

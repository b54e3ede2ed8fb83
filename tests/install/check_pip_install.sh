#!/bin/sh
# The Python package installs offline with Debian's tooling and works from
# where it was installed:
#  1. pip install --no-build-isolation --no-index (into a --target folder);
#  2. python3 -m build --no-isolation --wheel, and the wheel installs too;
#  3. the installed package (not the source tree) loads a scenario through
#     libeoir_host and renders a frame.
# usage: check_pip_install.sh PYTHON SOURCE_DIR ENGINE_LIBRARY WORK_DIR
set -eu
py=$1; src=$2; lib=$3; work=$4
rm -rf "$work"; mkdir -p "$work"
fail() { echo "check_pip_install: FAIL: $*" >&2; exit 1; }
cp -r "$src/bindings/python" "$work/src"       # builds leave build/ and *.egg-info behind
rm -rf "$work/src/build" "$work/src"/*.egg-info

"$py" -m pip install --no-build-isolation --no-index --no-deps --target "$work/site" "$work/src" \
  >"$work/pip.log" 2>&1 || { cat "$work/pip.log"; fail "pip install"; }
echo "check_pip_install: pip install --no-build-isolation --no-index: ok"
"$py" -m build --no-isolation --wheel --outdir "$work/dist" "$work/src" >"$work/build.log" 2>&1 \
  || { cat "$work/build.log"; fail "python3 -m build"; }
wheel=$(ls "$work"/dist/eoir-*-py3-none-any.whl) || fail "no wheel"
"$py" -m pip install --no-index --no-deps --target "$work/site-wheel" "$wheel" >>"$work/pip.log" 2>&1 \
  || { cat "$work/pip.log"; fail "pip install $wheel"; }
echo "check_pip_install: $(basename "$wheel"): ok"

for site in "$work/site" "$work/site-wheel"; do
  (cd "$work" && EOIR_LIBRARY="$lib" PYTHONPATH="$site" "$py" - "$site" "$src" <<'PY'
import os, sys
import eoir
site, src = sys.argv[1:3]
assert os.path.realpath(eoir.__file__).startswith(os.path.realpath(site)), eoir.__file__
with eoir.Scenario.load(os.path.join(src, "scenarios/demo/default.json")) as sc:
    times = sc.times()
    sc.set_time(times[-1])
    sc.engine.render("Sensor1")
    image = sc.engine.image("Sensor1", "sensor_mean")
    assert image.shape == (256, 256) and times[-1] == "2010-08-25T18:05:00Z", (image.shape, times)
print(f"check_pip_install: eoir {eoir.__version__} from {site}: {len(times)} times, frame {image.shape}")
PY
  ) || fail "the package installed in $site"
done
echo "check_pip_install: ok"

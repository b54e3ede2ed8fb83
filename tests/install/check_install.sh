#!/bin/sh
# Installs the build tree into a fresh prefix and uses it as a user would:
#  1. `cmake --install BUILD --prefix P` puts every file in its place;
#  2. a C program builds against P with find_package(eoir) and runs;
#  3. the same program builds with `pkg-config --cflags --libs eoir` and runs;
#  4. the installed CLI finds the installed library and scenarios by itself
#     (no EOIR_LIBRARY, EOIR_SCENARIO_DIR), and validates a scenario.
# usage: check_install.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -eu
build=$1; src=$2; work=$3
prefix=$work/prefix
rm -rf "$work"; mkdir -p "$work"
unset EOIR_LIBRARY EOIR_SCENARIO_DIR
fail() { echo "check_install: FAIL: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$prefix" >"$work/install.log" 2>&1 || { cat "$work/install.log"; fail "cmake --install"; }
libdir=$(sed -n 's/^libdir=\${prefix}\///p' "$build/eoir.pc")
[ -n "$libdir" ] || fail "no libdir in $build/eoir.pc"
for f in bin/eoir "$libdir/libeoir.so.1" "$libdir/libeoir.so" include/eoir/eoir.h include/eoir/eoir_version.h \
         "$libdir/cmake/eoir/eoirConfig.cmake" "$libdir/cmake/eoir/eoirConfigVersion.cmake" \
         "$libdir/cmake/eoir/eoirTargets.cmake" "$libdir/pkgconfig/eoir.pc" \
         share/eoir/schemas/scenario.schema.json share/eoir/scenarios/demo/default.json \
         "$libdir/libeoir_host.so.1" include/eoir/eoir_host.h share/eoir/data share/doc/eoir/LICENSE; do
  [ -e "$prefix/$f" ] || fail "missing $prefix/$f"
done
echo "check_install: installed files present under $prefix"

# 2. CMake package.
cmake -S "$src/tests/install/consumer" -B "$work/cmake-build" -DCMAKE_PREFIX_PATH="$prefix" \
      -DCMAKE_BUILD_TYPE=Release >"$work/cmake.log" 2>&1 || { cat "$work/cmake.log"; fail "find_package(eoir)"; }
cmake --build "$work/cmake-build" >>"$work/cmake.log" 2>&1 || { cat "$work/cmake.log"; fail "build with CMake"; }
out=$("$work/cmake-build/consumer") || fail "consumer built with CMake does not run"
echo "check_install: cmake: $out"
echo "$out" | grep -q "ensquared energy 0.9683" || fail "unexpected output '$out'"
# It must have linked the installed library, not the build tree's.
ldd "$work/cmake-build/consumer" | grep -q "$prefix/$libdir/libeoir.so.1" || fail "CMake consumer does not use $prefix"

# 3. pkg-config.
export PKG_CONFIG_PATH="$prefix/$libdir/pkgconfig"
flags=$(pkg-config --cflags --libs eoir) || fail "pkg-config eoir"
# shellcheck disable=SC2086
cc -std=c99 -Wall -Wextra -pedantic -Werror "$src/tests/install/consumer/main.c" -o "$work/consumer-pc" $flags \
  || fail "build with pkg-config ($flags)"
out=$(LD_LIBRARY_PATH="$prefix/$libdir" "$work/consumer-pc") || fail "consumer built with pkg-config does not run"
echo "check_install: pkg-config ($flags): $out"
echo "$out" | grep -q "ensquared energy 0.9683" || fail "unexpected output '$out'"

# 4. The installed CLI.
ver=$("$prefix/bin/eoir" --version) || fail "installed eoir --version"
echo "$ver" | grep -q "engine 1\..*($prefix/$libdir/libeoir.so.1)" || fail "installed eoir loads '$ver'"
"$prefix/bin/eoir" validate "$prefix/share/eoir/scenarios/demo/default.json" || fail "installed eoir validate"
"$prefix/bin/eoir" | grep -q "$prefix/share/eoir/scenarios/demo/default.json" || fail "installed eoir default scenario"
echo "check_install: installed CLI uses $prefix"
echo "check_install: ok"

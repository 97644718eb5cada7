#!/bin/sh
# Configures (Ninja), builds and runs the firmware host tests with ctest.
# Quiet on success except ctest's summary; on failure prints the build log or
# the failing tests' output and exits non-zero.
# Needs: cmake, ninja-build, g++, libgtest-dev, nlohmann-json3-dev,
# libmbedtls-dev, and for the size check gcc-arm-none-eabi,
# libstdc++-arm-none-eabi-newlib and libnewlib-arm-none-eabi; all are checked
# first (scripts/require.sh), and a missing one is named with its package.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
. "$here/scripts/require.sh"
require_host_build
require_arm_build
require_end firmware
build=${CUBE_BUILD_DIR:-$here/build}
jobs=${CUBE_JOBS:-2}
log=$(mktemp)
trap 'rm -f "$log"' EXIT

if ! cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >"$log" 2>&1; then
  cat "$log" >&2
  echo "firmware: cmake configure failed" >&2
  exit 1
fi
if ! cmake --build "$build" -j "$jobs" >"$log" 2>&1; then
  cat "$log" >&2
  echo "firmware: build failed" >&2
  exit 1
fi
cd "$build"
if ctest -j "$jobs" --output-on-failure >"$log" 2>&1; then
  # The summary: "100% tests passed, 0 tests failed out of N" and the time.
  grep -E "tests passed|Total Test time" "$log"
else
  cat "$log"
  exit 1
fi

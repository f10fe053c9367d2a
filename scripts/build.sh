#!/usr/bin/env bash
# Configures and builds SpectralSeg (tool, examples, tests, benchmarks) in ./build.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
JOBS=${JOBS:-$(nproc)}
# Ninja where it is installed (scripts/setup.sh installs it) for a new build
# folder: unlike Makefiles, it compiles a program's sources while the
# libraries it links are still compiling, so both cores stay busy. An
# existing folder keeps the generator it was made with.
GENERATOR=()
if [ ! -f "$BUILD_DIR/CMakeCache.txt" ] && command -v ninja >/dev/null; then GENERATOR=(-G Ninja); fi
cmake -S . -B "$BUILD_DIR" "${GENERATOR[@]}" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$BUILD_DIR" -j "$JOBS"

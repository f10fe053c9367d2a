#!/usr/bin/env bash
# Checks SpectralSeg against CGAL 6 (the CGAL of Debian 13 and current
# distributions) in ./build-cgal6, without gmpxx (CGAL_WITH_GMPXX=OFF: the
# configuration that brings in the fewest Boost headers, where a missing
# include shows): every public header compiled on its own and the tool's
# sources compiled header-only, every method instantiated (the
# header_self_containment test, front end only), and the README's project
# built against an installation and run (install_consumer).
# The tool is not configured (SPECTRALSEG_BUILD_TOOLS=OFF) nor its
# command-line tests run, to keep CI within its time; the whole suite runs
# against Debian 12's CGAL 5.5 in scripts/test.sh. To run it against CGAL 6,
# configure a build with -DCGAL_DIR=<CGAL 6>/lib/cmake/CGAL and no other
# option, then `cmake --build` and `ctest` there.
#
# CGAL 6 is looked for in ../shared/cgal-6.0.1 (header-only release) or in
# SPECTRALSEG_CGAL6_DIR (a prefix with lib/cmake/CGAL).
set -euo pipefail
cd "$(dirname "$0")/.."
CGAL6=${SPECTRALSEG_CGAL6_DIR:-../shared/cgal-6.0.1}
if [ ! -f "$CGAL6/lib/cmake/CGAL/CGALConfig.cmake" ]; then
  echo "test_cgal6: no CGAL release at $CGAL6 (set SPECTRALSEG_CGAL6_DIR to a CGAL 6 prefix): skipped" >&2
  exit 0
fi
CGAL6=$(cd "$CGAL6" && pwd)
BUILD_DIR=${BUILD_DIR:-build-cgal6}
GENERATOR=()   # Ninja for a new folder, as in scripts/build.sh
if [ ! -f "$BUILD_DIR/CMakeCache.txt" ] && command -v ninja >/dev/null; then GENERATOR=(-G Ninja); fi
found=$(cmake -S . -B "$BUILD_DIR" "${GENERATOR[@]}" -DCMAKE_BUILD_TYPE=Release -DCGAL_DIR="$CGAL6/lib/cmake/CGAL" -DCGAL_WITH_GMPXX=OFF \
  -DSPECTRALSEG_BUILD_BENCHMARKS=OFF -DSPECTRALSEG_BUILD_EXAMPLES=OFF -DSPECTRALSEG_BUILD_PYTHON=OFF \
  -DSPECTRALSEG_BUILD_DOCS=OFF -DSPECTRALSEG_SEPARATE_COMPILATION=OFF -DSPECTRALSEG_BUILD_TOOLS=OFF | grep "SpectralSeg: CGAL" || true)
echo "$found"
if ! grep -q "SpectralSeg: CGAL 6\." <<<"$found"; then
  echo "test_cgal6: the build did not find CGAL 6 at $CGAL6" >&2
  exit 1
fi
# The install test (a build of its own, mostly on one core) beside the
# header check (two compilers). A failure stops the script: the test still
# running goes with it.
trap 'kill $(jobs -p) 2>/dev/null || true' EXIT
(cd "$BUILD_DIR" && ctest --output-on-failure -R '^install_consumer$') &
tests=$!
(cd "$BUILD_DIR" && ctest --output-on-failure -R '^header_self_containment$')
wait "$tests"

#!/usr/bin/env bash
# Builds the tool and the unit tests with AddressSanitizer and
# UndefinedBehaviorSanitizer (gcc, SPECTRALSEG_SANITIZE=ON) in build-asan/
# and runs the unit tests and the command-line tests under them
# (doc/hardening.md). Any sanitizer report fails the run. About 30 minutes
# of compilation on 2 cores, 10 of tests; not part of CI (scripts/test.sh).
#   bash scripts/sanitize.sh              build and test
#   JOBS=1 bash scripts/sanitize.sh       compile on one core (while fuzzing)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=build-asan
JOBS=${JOBS:-$(nproc)}
# -O1 (and NDEBUG, as the release build): sanitized code at -O2 with CGAL takes twice as long to compile
nice -n 15 cmake -S . -B $BUILD -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DSPECTRALSEG_SANITIZE=ON \
  -DSPECTRALSEG_BUILD_EXAMPLES=OFF -DSPECTRALSEG_BUILD_BENCHMARKS=OFF -DSPECTRALSEG_BUILD_PYTHON=OFF \
  -DCMAKE_DISABLE_FIND_PACKAGE_OpenMesh=ON >/dev/null
# `all` is then the tool and the unit tests, compiled in parallel (named
# targets would be built one after the other)
nice -n 15 cmake --build $BUILD -j "$JOBS"
# a report stops the program with exit code 86 (not 1, which the tool
# uses for bad input, so that a report cannot pass for an expected refusal)
export ASAN_OPTIONS=halt_on_error=1:exitcode=86:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=halt_on_error=1:exitcode=86:print_stacktrace=1
log=$BUILD/sanitize.log
status=0
(cd $BUILD && nice -n 15 ctest -V -R '^(unit_tests|cli_tests)$') >$log 2>&1 || status=$?
reports=$(grep -cE 'ERROR: AddressSanitizer|ERROR: LeakSanitizer|runtime error:' $log || true)
grep -E '^[0-9]+/[0-9]+ Test|tests passed|tests failed|^cli: |test cases' $log || true
if [ "$reports" -gt 0 ]; then
  echo "sanitize.sh: $reports sanitizer reports, see $log:"
  grep -E -A12 'ERROR: AddressSanitizer|ERROR: LeakSanitizer|runtime error:' $log | head -60
  exit 1
fi
[ $status -eq 0 ] || { echo "sanitize.sh: tests failed, see $log"; exit $status; }
echo "sanitize.sh: unit and command-line tests pass under ASan + UBSan, no report"

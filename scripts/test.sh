#!/usr/bin/env bash
# One command for a new machine: installs the dependencies, builds everything
# and runs the whole test suite (unit tests, mesh-type agreement, command-line
# checks, example and benchmark smoke runs) against Debian 12's CGAL 5.5,
# then the header, command-line and install tests against CGAL 6.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
(cd build && ctest --output-on-failure)
# the same headers against CGAL 6 (a subset of the tests: see the script)
bash scripts/test_cgal6.sh

#!/usr/bin/env bash
# One command for a new machine: installs the dependencies, builds everything
# and runs the whole test suite (unit tests, mesh-type agreement, command-line
# checks, example and benchmark smoke runs).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
cd build
ctest --output-on-failure

#!/usr/bin/env bash
# Installs every Debian 12 package SpectralSeg needs to build, test, benchmark and
# document itself. Idempotent; run as root (or with sudo available).
#   bash scripts/setup.sh           everything
#   bash scripts/setup.sh --tool    only what the spectralseg tool needs (the demo)
#   bash scripts/setup.sh --fuzz    everything, and clang with libFuzzer for scripts/fuzz.sh
#                                   (doc/hardening.md; scripts/sanitize.sh needs only gcc)
set -euo pipefail

# the tool alone (the demo): a compiler rather than build-essential (no
# dpkg-dev and its Perl), and Boost's headers through libcgal-dev (the
# Boost Graph Library is headers only here: libboost-graph-dev would add
# ICU, regex, serialization and test) -- 197 packages, 148 MB (libmaxflow-dev: 2 packages, 0.1 MB)
TOOL_PACKAGES=(
  g++ make cmake ninja-build
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev libmaxflow-dev
  libeigen3-dev libspectra-dev
  libtbb-dev libembree-dev
  libcli11-dev nlohmann-json3-dev libpng-dev
)
PACKAGES=(
  build-essential cmake ninja-build pkg-config
  libcgal-dev libgmp-dev libmpfr-dev libmaxflow-dev
  libeigen3-dev libspectra-dev
  libboost-dev libboost-program-options-dev
  libtbb-dev libembree-dev libopenmesh-dev
  catch2 libcli11-dev nlohmann-json3-dev libpng-dev
  doxygen
  python3 gnuplot-nox
  python3-open3d   # the test mesh_outputs_open3d reads the PLY/OBJ outputs back (system python3)
  pybind11-dev python3-dev python3-numpy
  python3-venv python3-pip python3-setuptools python3-wheel   # the pip install test
  blender   # the Blender add-on's headless test
  slurm-wlm munge parallel python3-kubernetes python3-yaml   # scripts/batch on real schedulers (test/batch_tests.py)
)

# Debian 12's clang is clang 14; libFuzzer (libclang_rt.fuzzer) is in its compiler-rt package
FUZZ_PACKAGES=(clang libclang-rt-14-dev)

if [ "${1:-}" = "--tool" ]; then
  PACKAGES=("${TOOL_PACKAGES[@]}")
elif [ "${1:-}" = "--fuzz" ]; then
  PACKAGES+=("${FUZZ_PACKAGES[@]}")
fi

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#PACKAGES[@]} packages already installed"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
# Debian's slurm and munge packages enable their daemons; the test starts
# its own single-node cluster, so those installed here are stopped and not
# started at boot (where systemd runs)
if [ -d /run/systemd/system ]; then
  for p in slurm-wlm munge; do
    if [[ " ${missing[*]} " == *" $p "* ]]; then
      $SUDO systemctl disable --now slurmctld slurmd munge >/dev/null 2>&1 || true
    fi
  done
fi
echo "setup: done"

#!/usr/bin/env bash
# One command for a new user: installs the dependencies, builds, and runs
# spectralseg on a mesh shipped in data/, then says where the outputs are.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
OUT=${OUT:-output}
mkdir -p "$OUT"
MESH=data/human_man.off
./build/tools/spectralseg info "$MESH"
# Part-aware distances from a face on the left hand: the concave joints show
# up as jumps under the angular metric and not under the geodesic one.
./build/tools/spectralseg distance "$MESH" --from 0 --metric geodesic \
  --field "$OUT/human_geodesic.txt" --png "$OUT/human_geodesic.png"
./build/tools/spectralseg distance "$MESH" --from 0 --metric angular \
  --field "$OUT/human_angular.txt" --png "$OUT/human_angular.png"
./build/tools/spectralseg distance "$MESH" --from 0 --metric blend --weights 0.01,0.99 \
  --field "$OUT/human_blend.txt" --png "$OUT/human_blend.png"
echo
echo "outputs written to $(cd "$OUT" && pwd):"
ls -1 "$OUT" | sed 's/^/  /'

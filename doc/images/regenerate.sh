#!/usr/bin/env bash
# Regenerates every picture of the manual and of doc/benchmarks.md with the
# tool and the benchmarks as built in ./build, from the repository root:
#   bash doc/images/regenerate.sh [--no-quality]
# --no-quality skips the quality benchmark's pictures (doc/images/quality,
# doc/quality_table.md: about 8 minutes on 2 cores, CGAL's SDF included).
# The shared meshes and psb-dev are read from ../shared/data (or $S).
set -euo pipefail
cd "$(dirname "$0")/../.."
S=${S:-../shared/data}
B=${BUILD_DIR:-build}
B=$(cd "$B" && pwd) # absolute: BUILD_DIR may be given either way
SEG=$B/tools/spectralseg
OUT=doc/images
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
quality=1
[ "${1:-}" = "--no-quality" ] && quality=0

for metric in geodesic angular part-aware; do
  name=${metric//-/_}
  $SEG -q distance data/human_man.off --from 6863 --metric $metric --field "$TMP/f.txt" --png "$OUT/human_$name.png"
done
$SEG -q distance data/human_man.off --from 6863 --metric part-aware --weights 0.01,0.99 --normalization max \
  --field "$TMP/f.txt" --png "$OUT/human_blend.png"
# the armadillo's pictures are cropped and scaled to 75% to stay under 200 KB
for metric in geodesic angular part-aware; do
  name=${metric//-/_}
  $SEG -q distance "$S/meshes/armadillo.off" --from 32127 --metric $metric --field "$TMP/f.txt" --png "$TMP/a.png"
  python3 doc/images/tools/crop_views.py "$TMP/a.png" "$OUT/armadillo_$name.png" 3 0.75
done
$SEG -q segment data/human_man.off --k 6 --labels "$TMP/h.seg" --png "$OUT/human_kway_k6.png"
$SEG -q segment data/human_man.off --k 6 --sampling exact --labels "$TMP/h.seg" --png "$OUT/human_kway_k6_exact.png"
# psb-dev model 1 lies along z in its file: views that stand it upright
for k in 6 15; do
  $SEG -q segment "$S/psb-dev/off/1.off" --k $k --labels "$TMP/1.seg"
  $SEG -q render "$S/psb-dev/off/1.off" "$TMP/1.seg" --png "$TMP/v.png" \
    --view 0,-1,0,0,0,1 --view -1,0,0,0,0,1 --view 0,1,0,0,0,1
  python3 doc/images/tools/crop_views.py "$TMP/v.png" "$OUT/psb1_kway_k$k.png"
done
# the top-down method before (as published) and after (the default), on a human, a
# hand, an animal, a chair and a machine part: all parts as published; depth 1, 2
# and all parts now (cropped, half size)
for m in human:data/human_man.off hand:$S/meshes/hand_closed.off camel:data/camel.off \
         chair101:$S/psb-dev/off/101.off mech321:$S/psb-dev/off/321.off; do
  name=${m%%:*}; mesh=${m#*:}
  $SEG -q segment "$mesh" --k auto --auto-method salient-cuts-thesis --labels "$TMP/t.seg" --png "$TMP/t.png"
  python3 doc/images/tools/crop_views.py "$TMP/t.png" "$OUT/ch6_${name}_thesis.png" 3 0.5
  for d in 1 2 all; do
    depth=(); [ $d = all ] || depth=(--depth $d)
    $SEG -q segment "$mesh" --k auto --auto-method salient-cuts "${depth[@]}" --labels "$TMP/i.seg" --png "$TMP/i.png"
    python3 doc/images/tools/crop_views.py "$TMP/i.png" "$OUT/ch6_${name}_depth$d.png" 3 0.5
  done
done
# the salient cuts' hierarchy at depths 1 to 3, and all its parts
for d in 1 2 3; do
  $SEG -q segment data/human_man.off --k auto --auto-method salient-cuts --depth $d --labels "$TMP/s.seg" \
    --png "$OUT/human_salient_depth$d.png"
done
$SEG -q segment data/human_man.off --k auto --auto-method salient-cuts --labels "$TMP/s.seg" \
  --png "$OUT/human_salient_all.png"
# the default --k auto on the README's mesh
$SEG -q segment data/human_man.off --k auto --labels "$TMP/a.seg" --png "$OUT/human_auto.png"
$B/examples/part_aware_sampling data/human_man.off 8 "$OUT/human_sampling.png"
# the Blender add-on's picture, rendered by Blender (Cycles) after the add-on
# segmented the mesh (doc/blender.md); skipped without Debian's blender
if command -v blender > /dev/null; then
  cmake -DBLENDER="$(command -v blender)" -DSPECTRALSEG="$SEG" -DMODULE_DIR="$B/python" -DSOURCE="$PWD" \
    -DMESH="$PWD/data/human_man.off" -DWORK="$TMP/blender" -DRENDER="$PWD/$OUT/blender_human_auto.png" \
    -P test/blender/blender_addon.cmake > "$TMP/blender.log"
else
  echo "blender not found: $OUT/blender_human_auto.png not regenerated"
fi
if [ $quality = 1 ]; then
  rm -f "$OUT"/quality/*.png
  $B/benchmark/bench_psb_quality "$S/psb-dev" --methods kway,contrast,auto,salient,sdf \
    --markdown doc/quality_table.md --png-dir "$OUT/quality" > "$TMP/quality.log"
  grep '^png:' "$TMP/quality.log"
  # the same table at the top of doc/benchmarks.md
  python3 doc/images/tools/sync_quality_table.py doc/quality_table.md doc/benchmarks.md
fi
echo "pictures written to $OUT"

#!/usr/bin/env bash
# Compile time and peak memory of single translation units, each compiled
# alone with the exact command CMake uses (from compile_commands.json).
#
# usage: benchmark/compile_time/measure.sh [BUILD_DIR=build] [SOURCE ...]
#   default sources: the README example, CGAL's SDF segmentation, and the
#   Python module when it is configured. The build directory must be
#   configured with -DCMAKE_EXPORT_COMPILE_COMMANDS=ON.
#   SPECTRALSEG_INCLUDE_DIR=DIR compiles against the headers in DIR instead
#   of the source tree's include/ (e.g. an older commit's, checked out with
#   `git worktree add /tmp/before COMMIT`: DIR=/tmp/before/include).
# Prints one table row per source: wall seconds, user+system CPU seconds,
# peak resident memory (GNU time's "Maximum resident set size").
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${1:-build}
shift || true
DB="$BUILD/compile_commands.json"
if [ ! -f "$DB" ]; then
  echo "no $DB: configure with -DCMAKE_EXPORT_COMPILE_COMMANDS=ON" >&2
  exit 1
fi
SOURCES=("$@")
if [ ${#SOURCES[@]} -eq 0 ]; then
  SOURCES=(benchmark/compile_time/readme_example.cpp benchmark/compile_time/cgal_sdf.cpp)
  [ -f python/spectralseg_module.cpp ] && SOURCES+=(python/spectralseg_module.cpp)
fi
echo "| translation unit | wall (s) | CPU (s) | peak memory (MB) |"
echo "|---|---:|---:|---:|"
for src in "${SOURCES[@]}"; do
  abs=$(realpath "$src")
  # the entry of this source: its directory and command
  read -r dir cmd < <(/usr/bin/python3 - "$DB" "$abs" <<'PY'
import json, sys
for e in json.load(open(sys.argv[1])):
    if e["file"] == sys.argv[2]:
        print(e["directory"], e.get("command") or " ".join(e["arguments"]))
        break
PY
  ) || true
  if [ -z "${cmd:-}" ]; then
    echo "| $src | not in $DB (is its target configured?) | | |"
    continue
  fi
  out=$(mktemp -d)
  # same command, object file redirected to a scratch directory
  cmd=$(sed -E "s# -o [^ ]+# -o $out/tu.o#" <<<"$cmd")
  if [ -n "${SPECTRALSEG_INCLUDE_DIR:-}" ]; then
    cmd=${cmd//-I$PWD\/include /-I$(realpath "$SPECTRALSEG_INCLUDE_DIR") }
  fi
  (cd "$dir" && /usr/bin/time -v sh -c "$cmd" 2>"$out/time" >/dev/null) || { cat "$out/time" >&2; exit 1; }
  awk -v src="$src" -F': ' '
    /Elapsed \(wall clock\)/ { n = split($2, p, ":"); wall = (n == 3 ? p[1] * 3600 + p[2] * 60 + p[3] : p[1] * 60 + p[2]) }
    /User time/ { user = $2 } /System time/ { sys = $2 }
    /Maximum resident set size/ { mem = $2 / 1024 }
    END { printf "| %s | %.1f | %.1f | %.0f |\n", src, wall, user + sys, mem }' "$out/time"
  rm -rf "$out"
done

#!/usr/bin/env bash
# spectralseg batch split into shards run by GNU parallel, on this machine
# or over ssh on several, then the shards' summaries merged.
#
#   scripts/batch/gnu_parallel.sh SHARDS OUT [batch arguments...]
#   SSHLOGINFILE=nodes.txt scripts/batch/gnu_parallel.sh 16 results -r /data/meshes --k auto
#
# Environment:
#   SSHLOGINFILE  machines to run the shards on (GNU parallel's --sshloginfile
#                 format, e.g. "4/node1" for 4 shards at once on node1; ":"
#                 is this machine). OUT, the meshes and this folder must be at
#                 the same path on every machine (a shared file system), and
#                 spectralseg on their PATH (or $SPECTRALSEG, an absolute path).
#   PARALLEL_JOBS shards at once per machine without SSHLOGINFILE (default 1;
#                 on a single machine, `batch --jobs` alone does the same job).
#   SPECTRALSEG   the tool (default: spectralseg from the PATH).
# A shard that fails stops nothing: the others go on, and the merge says
# which shard is missing. Exit status: that of batch-merge (0 if every mesh
# was segmented, 1 otherwise). Running the same command again reruns only
# what is not finished.
set -euo pipefail
SPECTRALSEG=${SPECTRALSEG:-spectralseg}
if [ $# -lt 2 ]; then
  echo "usage: $0 SHARDS OUT [spectralseg batch arguments...]" >&2
  exit 2
fi
shards=$1
out=$2
shift 2
case "$shards" in '' | *[!0-9]* | 0)
  echo "$0: SHARDS must be a positive whole number (got '$shards')" >&2
  exit 2
  ;;
esac
command -v parallel >/dev/null || {
  echo "$0: GNU parallel is not installed (Debian: apt-get install parallel)" >&2
  exit 1
}
mkdir -p "$out"
options=(--quote --halt never --line-buffer --tagstring "shard {}/$shards")
if [ -n "${SSHLOGINFILE:-}" ]; then
  options+=(--sshloginfile "$SSHLOGINFILE" --workdir "$PWD")
else
  options+=(--jobs "${PARALLEL_JOBS:-1}")
fi
# a shard with a failed mesh exits with 1: recorded in its summary, not fatal here
parallel "${options[@]}" "$SPECTRALSEG" batch --shard "{}/$shards" --out "$out" "$@" \
  ::: $(seq 0 $((shards - 1))) || true
exec "$SPECTRALSEG" batch-merge "$out"

#!/usr/bin/env bash
# spectralseg batch as a Slurm job array: one array task per shard, then one
# job that merges the shards' summaries (it runs when every task has ended,
# whether or not some meshes failed).
#
# Submit it from a login node (it calls sbatch itself):
#
#   scripts/batch/slurm_array.sh SHARDS OUT [batch arguments...]
#   scripts/batch/slurm_array.sh 20 results/psb -r /data/psb/off --k auto --jobs 2
#
# OUT and the meshes must be on a file system that every node sees; the
# spectralseg found on the PATH of the nodes is run (or $SPECTRALSEG: give an
# absolute path). Each task runs `batch --shard I/SHARDS --out OUT` with the
# arguments given and --threads set to the CPUs Slurm gave it (add --jobs J
# to segment J meshes at once within a task). Resources of a task: the
# #SBATCH lines below, or sbatch options in $SBATCH_OPTIONS (e.g.
# "--partition=short --mem=16G"); at most $ARRAY_LIMIT tasks at once if set.
# A task exits with 1 if one of its meshes failed (shown by sacct; the error
# is in the summary). Submitting the same command again reruns only what is
# not finished.
#
#SBATCH --job-name=spectralseg-batch
#SBATCH --cpus-per-task=4
#SBATCH --mem=8G
#SBATCH --time=12:00:00
#SBATCH --output=spectralseg-batch-%A_%a.out
set -euo pipefail
SPECTRALSEG=${SPECTRALSEG:-spectralseg}

usage() {
  echo "usage: $0 SHARDS OUT [spectralseg batch arguments...]" >&2
  exit 2
}
[ $# -ge 2 ] || usage
shards=$1
out=$2
shift 2
case "$shards" in '' | *[!0-9]* | 0) usage ;; esac

if [ -n "${SPECTRALSEG_BATCH_MERGE:-}" ]; then
  # the merge job
  exec "$SPECTRALSEG" batch-merge "$out"
elif [ -n "${SLURM_ARRAY_TASK_ID:-}" ]; then
  # one array task: one shard
  exec "$SPECTRALSEG" batch --shard "$SLURM_ARRAY_TASK_ID/$shards" --out "$out" \
    --threads "${SLURM_CPUS_PER_TASK:-0}" "$@"
else
  # submission: the array, then the merge once every task has ended
  mkdir -p "$out"
  # shellcheck disable=SC2086 # $SBATCH_OPTIONS holds several options
  array=$(sbatch --parsable --array="0-$((shards - 1))${ARRAY_LIMIT:+%$ARRAY_LIMIT}" ${SBATCH_OPTIONS:-} \
    "$0" "$shards" "$out" "$@")
  array=${array%%;*}
  # shellcheck disable=SC2086
  merge=$(sbatch --parsable --dependency="afterany:$array" --job-name=spectralseg-merge --cpus-per-task=1 \
    --mem=1G --time=00:30:00 --output=spectralseg-merge-%j.out --export=ALL,SPECTRALSEG_BATCH_MERGE=1 \
    ${SBATCH_OPTIONS:-} "$0" "$shards" "$out")
  merge=${merge%%;*}
  echo "submitted: array job $array ($shards shards), merge job $merge"
  echo "summary when done: $out/summary.csv"
fi

#!/usr/bin/env bash
# Builds the libFuzzer targets of the readers (clang, ASan + UBSan) in
# build-fuzz/ and runs them (doc/hardening.md). Needs `bash scripts/setup.sh --fuzz`.
#   bash scripts/fuzz.sh                     every target for 10 minutes, 2 at a time
#   bash scripts/fuzz.sh --time 60 fuzz_off  one target for a minute
#   bash scripts/fuzz.sh --replay            only run the seeds and regressions once (a few seconds)
# Options: --time SECONDS per target, --jobs N targets at a time (default 2),
# --build-jobs N compile jobs (default 2). Runs under `nice -n 15`. A target's
# corpus grows in build-fuzz/corpus/<target>, its log is build-fuzz/logs/<target>.log,
# and an input that fails is written to build-fuzz/findings/<target>/: copy it
# to fuzz/regressions/<target>/ once fixed, so that it is replayed from then on.
set -euo pipefail
cd "$(dirname "$0")/.."
TIME=600
JOBS=2
BUILD_JOBS=2
REPLAY=0
TARGETS=()
ALL=(fuzz_off fuzz_obj fuzz_ply_ascii fuzz_ply_binary fuzz_stl_ascii fuzz_stl_binary fuzz_labels)
while [ $# -gt 0 ]; do
  case "$1" in
    --time) TIME=$2; shift 2 ;;
    --jobs) JOBS=$2; shift 2 ;;
    --build-jobs) BUILD_JOBS=$2; shift 2 ;;
    --replay) REPLAY=1; shift ;;
    fuzz_*) TARGETS+=("$1"); shift ;;
    *) echo "fuzz.sh: unknown argument '$1' (targets: ${ALL[*]})" >&2; exit 2 ;;
  esac
done
[ ${#TARGETS[@]} -gt 0 ] || TARGETS=("${ALL[@]}")
command -v clang++ >/dev/null || { echo "fuzz.sh: clang++ not found: run 'bash scripts/setup.sh --fuzz'" >&2; exit 1; }

BUILD=build-fuzz
CXX=clang++ nice -n 15 cmake -S . -B $BUILD -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSPECTRALSEG_BUILD_FUZZERS=ON \
  -DSPECTRALSEG_BUILD_TOOLS=OFF -DSPECTRALSEG_BUILD_TESTS=OFF -DSPECTRALSEG_BUILD_EXAMPLES=OFF \
  -DSPECTRALSEG_BUILD_BENCHMARKS=OFF -DSPECTRALSEG_BUILD_PYTHON=OFF \
  -DSPECTRALSEG_SEPARATE_COMPILATION=OFF >/dev/null   # header-only: all the code a target runs is instrumented
# every target: `all`, compiled in parallel (CMake's Makefiles build named targets one after the other)
if [ ${#TARGETS[@]} -eq ${#ALL[@]} ]; then
  nice -n 15 cmake --build $BUILD -j "$BUILD_JOBS"
else
  nice -n 15 cmake --build $BUILD -j "$BUILD_JOBS" --target "${TARGETS[@]}"
fi

if [ $REPLAY = 1 ]; then
  regex="^fuzz_replay_($(IFS='|'; echo "${TARGETS[*]}"))\$"
  (cd $BUILD && ctest --output-on-failure -R "$regex")
  exit
fi

dictionary() {
  case "$1" in
    fuzz_off) echo fuzz/dict/off.dict ;;
    fuzz_obj) echo fuzz/dict/obj.dict ;;
    fuzz_ply_*) echo fuzz/dict/ply.dict ;;
    fuzz_stl_ascii) echo fuzz/dict/stl.dict ;;
  esac
}

run() {
  local t=$1 dict
  mkdir -p $BUILD/corpus/$t $BUILD/findings/$t $BUILD/logs
  dict=$(dictionary "$t")
  local seeds=(fuzz/corpus/$t)
  [ -d fuzz/regressions/$t ] && seeds+=(fuzz/regressions/$t)
  nice -n 15 $BUILD/fuzz/$t -max_total_time="$TIME" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix=$BUILD/findings/$t/ ${dict:+-dict=$dict} $BUILD/corpus/$t "${seeds[@]}" \
    >$BUILD/logs/$t.log 2>&1 || true
}

running=0
for t in "${TARGETS[@]}"; do
  run "$t" &
  running=$((running + 1))
  if [ $running -ge "$JOBS" ]; then wait -n; running=$((running - 1)); fi
done
wait

status=0
printf '| target | executions | exec/s | coverage (edges) | features | corpus | findings |\n|---|---:|---:|---:|---:|---:|---|\n'
for t in "${TARGETS[@]}"; do
  log=$BUILD/logs/$t.log
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
  last=$(grep -E '^#[0-9]+' "$log" | grep -E 'cov: ' | tail -1)
  cov=$(sed -n 's/.*cov: \([0-9]*\).*/\1/p' <<<"$last")
  ft=$(sed -n 's/.*ft: \([0-9]*\).*/\1/p' <<<"$last")
  corpus=$(sed -n 's/.*corp: \([0-9]*\/[0-9a-zA-Z]*\).*/\1/p' <<<"$last")
  findings=$(ls $BUILD/findings/$t | wc -l)
  [ "$findings" -eq 0 ] || status=1
  printf '| %s | %s | %s | %s | %s | %s | %s |\n' "$t" "${execs:-?}" "${speed:-?}" "${cov:-?}" "${ft:-?}" "${corpus:-?}" \
    "$([ "$findings" -eq 0 ] && echo none || echo "$findings in $BUILD/findings/$t")"
done
exit $status

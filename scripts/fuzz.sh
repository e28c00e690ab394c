#!/usr/bin/env bash
# Runs the libFuzzer target of findEssentialMatIter and recoverPose (fuzz/fuzz_essential.cpp) for a
# fixed time with a fixed seed, starting from the seeds in fuzz/corpus/ and the kept crash inputs
# in fuzz/regression/. Builds the sanitizer tree first if needed (see sanitize.sh; the target is
# built there with ASan + UBSan). New corpus entries go to the build tree, not the repository; a
# crash input is written as ${build_dir}/fuzz-crash-*, and the script fails: copy it to
# fuzz/regression/ once fixed, so that fuzz_regression_replay replays it from then on.
#   FUZZ_SECONDS (default 60), FUZZ_SEED (default 1), SANITIZE_BUILD_DIR (default build-sanitize).
# The last line printed is "fuzz: N executions in S s, 0 crashes" (or the failure).
# Licensed under the Apache License, Version 2.0.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
root=$(pwd)
build_dir=${SANITIZE_BUILD_DIR:-build-sanitize}
seconds=${FUZZ_SECONDS:-60}
seed=${FUZZ_SEED:-1}

if [[ ! -x "$build_dir/fuzz/essential_fuzz" ]]; then
    scripts/sanitize.sh -R '^$' >/dev/null # builds the tree, runs no test
fi

export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
corpus="$build_dir/fuzz-corpus"
mkdir -p "$corpus"
log="$build_dir/fuzz.log"
# -rss_limit_mb: OpenCV's allocations on a 1000-point input stay far below; -timeout: one input
# taking more than 10 s is a hang (the target caps iterations, see fuzz_essential.cpp).
status=0
"$build_dir/fuzz/essential_fuzz" "$corpus" "$root/fuzz/corpus" "$root/fuzz/regression" \
    -seed="$seed" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
    -print_final_stats=1 -artifact_prefix="$build_dir/fuzz-" >"$log" 2>&1 || status=$?
executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n1)
if [[ $status -ne 0 ]]; then
    tail -n 40 "$log" >&2
    echo "fuzz: FAILED after ${executions:-?} executions (exit $status); input: $(ls "$build_dir"/fuzz-crash-* "$build_dir"/fuzz-timeout-* "$build_dir"/fuzz-leak-* "$build_dir"/fuzz-oom-* 2>/dev/null | head -n1)"
    exit 1
fi
echo "fuzz: ${executions:-0} executions in ${seconds} s (seed ${seed}), 0 crashes"

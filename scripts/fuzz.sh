#!/usr/bin/env bash
# Runs the libFuzzer targets (fuzz/fuzz_<target>.cpp: input_layer, solvers, engines, colmap) of the
# sanitizer tree (ASan + UBSan, see sanitize.sh; built first if needed), each for a fixed time or a
# fixed number of runs with a fixed seed, starting from its seeds in fuzz/corpus/<target>/ and its
# kept failures in fuzz/regression/<target>/. New corpus entries go to
# ${build_dir}/fuzz-corpus/<target>/; a failing input is written as
# ${build_dir}/fuzz-<target>-crash-* (or -timeout-, -leak-, -oom-) and the script fails: copy it to
# fuzz/regression/<target>/ once fixed, so that ctest replays it from then on.
#
#   scripts/fuzz.sh [target ...]          default: every target
#   FUZZ_SECONDS=20   time per target (default 20; scripts/test.sh, so CI, runs the default)
#   FUZZ_RUNS=N       stop each target after N executions instead (a long run: FUZZ_RUNS=1000000)
#   FUZZ_SEED=1       libFuzzer's -seed
#   FUZZ_JOBS=1       parallel fuzzing processes per target (libFuzzer -fork; a long run on 2 cores)
#   FUZZ_FAST=1       use the fast tree build-fuzz-fast instead (built here if missing): UBSan only,
#                     optimised, for long runs (4 to 10 times the executions per second of the -O1
#                     ASan + UBSan tree; memory errors are what the ASan runs are for)
#
# One line per target: "fuzz <target>: N executions in S s (R/s), cov E edges, 0 crashes"; the last
# line is "fuzz: T targets, 0 crashes" (or the failure).
# Licensed under the Apache License, Version 2.0.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
root=$(pwd)
build_dir=${SANITIZE_BUILD_DIR:-build-sanitize}
[[ "${FUZZ_FAST:-0}" == 0 ]] || build_dir=${FUZZ_FAST_BUILD_DIR:-build-fuzz-fast}
seconds=${FUZZ_SECONDS:-20}
runs=${FUZZ_RUNS:-}
seed=${FUZZ_SEED:-1}
jobs=${FUZZ_JOBS:-1}
targets=("$@")
[[ ${#targets[@]} -gt 0 ]] || targets=(input_layer solvers engines colmap)

missing=0
for t in "${targets[@]}"; do
    [[ -f "$root/fuzz/fuzz_$t.cpp" ]] || { echo "fuzz.sh: no target '$t' (fuzz/fuzz_$t.cpp)" >&2; exit 2; }
    [[ -x "$build_dir/fuzz/essential_fuzz_$t" ]] || missing=1
done
if [[ $missing -ne 0 && "${FUZZ_FAST:-0}" != 0 ]]; then
    scripts/bootstrap.sh
    ubsan="-fsanitize=undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
    CC=clang CXX=clang++ LDFLAGS="$ubsan" \
        CXXFLAGS="-g $ubsan -fsanitize=fuzzer-no-link -fno-sanitize-coverage=trace-cmp" \
        cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DESSENTIAL_BUILD_FUZZ=ON \
        -DESSENTIAL_BUILD_PERF=OFF -DESSENTIAL_BUILD_BENCH=OFF -DESSENTIAL_OPENCV_OWN_TESTS=OFF \
        -DESSENTIAL_BUILD_PYTHON=OFF >/dev/null # samples on: the colmap target needs the COLMAP sample's library
    cmake --build "$build_dir" -j"${JOBS:-$(nproc)}" $(printf -- '--target essential_fuzz_%s ' "${targets[@]}")
elif [[ $missing -ne 0 ]]; then
    scripts/sanitize.sh -R '^$' >/dev/null # builds the tree, runs no test
fi

export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
# -rss_limit_mb: the targets' inputs stay far below; -timeout: one input taking more than 60 s is a
# hang (every target caps its iterations and time budgets). libFuzzer's timeout is wall time: 10 s
# failed a CI run with a legitimate engine input (the OpenCV-time sample budget
# under ASan), so the margin is wide; a real hang does not end.
limit=(-max_total_time="$seconds")
[[ -z "$runs" ]] || limit=(-runs="$runs")
[[ "$jobs" -le 1 ]] || limit+=(-fork="$jobs")
for t in "${targets[@]}"; do
    corpus="$build_dir/fuzz-corpus/$t"
    mkdir -p "$corpus"
    log="$build_dir/fuzz-$t.log"
    dict=()
    [[ ! -f "$root/fuzz/$t.dict" ]] || dict=(-dict="$root/fuzz/$t.dict")
    # The colmap target's inputs are SQLite files (its seeds: 14 KB); the others' are choices.
    max_len=4096
    [[ "$t" != colmap ]] || max_len=16384
    status=0
    start=$(date +%s.%N)
    "$build_dir/fuzz/essential_fuzz_$t" "$corpus" "$root/fuzz/corpus/$t" "$root/fuzz/regression/$t" \
        -seed="$seed" "${limit[@]}" "${dict[@]}" -timeout=60 -rss_limit_mb=2048 -max_len="$max_len" \
        -print_final_stats=1 -artifact_prefix="$build_dir/fuzz-$t-" >"$log" 2>&1 || status=$?
    elapsed=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN {print b - a}')
    executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | awk '{s += $1} END {print s + 0}')
    # With -fork the workers' stats are not summed in one line: take the last "#N" progress line.
    if [[ "$jobs" -gt 1 ]]; then
        executions=$(grep -oE '^#[0-9]+' "$log" | tail -n1 | tr -d '#')
    fi
    edges=$(grep -oE 'cov: [0-9]+' "$log" | tail -n1 | sed 's/cov: //')
    if [[ $status -ne 0 ]]; then
        tail -n 40 "$log" >&2
        echo "fuzz $t: FAILED after ${executions:-?} executions (exit $status); input: $(ls "$build_dir"/fuzz-"$t"-{crash,timeout,leak,oom}-* 2>/dev/null | head -n1)"
        exit 1
    fi
    rate=$(awk -v n="${executions:-0}" -v s="$elapsed" 'BEGIN {printf "%d", n / s}')
    echo "fuzz $t: ${executions:-0} executions in $(printf '%.0f' "$elapsed") s (${rate}/s), cov ${edges:-?} edges, 0 crashes (seed $seed)"
done
echo "fuzz: ${#targets[@]} targets, 0 crashes"

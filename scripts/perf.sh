#!/usr/bin/env bash
# Runs the perf suite (build/perf/essential_perf, Google Benchmark) and writes its tables into
# docs/PERFORMANCE.md (between the perf-tables markers) with scripts/perf_tables.py.
# Licensed under the Apache License, Version 2.0.
#
#   scripts/perf.sh                 # everything: kernels and whole estimates, 3 repetitions
#   PROBLEMS=100 REPETITIONS=3 FILTER='Estimate/.*/N:500' scripts/perf.sh
#
# Environment: BUILD_DIR (default build), PROBLEMS (scenes per estimate run, default 100),
# REPETITIONS (default 3; interleaved at random across benchmarks), FILTER (benchmark regex,
# default all), OUT (JSON results, default $BUILD_DIR/perf_results.json), DOC (default
# docs/PERFORMANCE.md; DOC=- prints the tables instead). Run at normal priority: timings under
# nice are not comparable. The estimates take about 10 minutes with the defaults on 2 cores.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

build_dir=${BUILD_DIR:-build}
binary="$build_dir/perf/essential_perf"
out=${OUT:-$build_dir/perf_results.json}
doc=${DOC:-docs/PERFORMANCE.md}
if [[ ! -x "$binary" ]]; then
  echo "no $binary: build first (scripts/build.sh)" >&2
  exit 1
fi

"$binary" --problems="${PROBLEMS:-100}" \
  --benchmark_filter="${FILTER:-.}" \
  --benchmark_repetitions="${REPETITIONS:-3}" \
  --benchmark_enable_random_interleaving=true \
  --benchmark_out="$out" --benchmark_out_format=json

echo
echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores"
if [[ "$doc" == "-" ]]; then
  /usr/bin/python3 scripts/perf_tables.py "$out"
else
  /usr/bin/python3 scripts/perf_tables.py "$out" --doc "$doc"
  echo "tables written to $doc"
fi

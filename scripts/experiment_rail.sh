#!/usr/bin/env bash
# The paper's real-data experiment on the rail sequences (docs/experiments/rail.md): matches each
# frame pair once (cached), runs gn, lm, nister, robust and gn+nister in preemptive RANSAC at a
# sweep of time budgets and cv::findEssentialMat as a reference, on two match sets (best 20% of
# the matches, and a random 20%), then writes the per-estimate CSV (gzip), the summary CSVs and the
# figures in the layout of the paper's results figure.
#
#   scripts/experiment_rail.sh [--quick] [--data DIR] [--out DIR] [--bin PROGRAM] [--cache DIR]
#
#   --data DIR   folder with horizontal/ and optic/ (default ../shared/data/rail-a next to the
#                repository; --quick: the bundled data/rail, horizontal frames 0 and 10 only)
#   --out DIR    writes DIR/results/rail_*.csv[.gz] and DIR/figures/rail_*.png (default docs)
#   --bin P      the essential_paper_rail program (default ${BUILD_DIR:-build}/bench/...; built
#                by scripts/build.sh when missing)
#   --cache DIR  match cache (default ${BUILD_DIR:-build}/rail_match_cache); delete it after
#                changing the front end
#
# The two sequences run as two processes in parallel (one per core). Needs python3-matplotlib.
# Licensed under the Apache License, Version 2.0.
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${BUILD_DIR:-build}
[[ "$build_dir" = /* ]] || build_dir="$repo/$build_dir"
quick=0
data=""
out="$repo/docs"
bin="$build_dir/bench/essential_paper_rail"
cache="$build_dir/rail_match_cache"
while [[ $# -gt 0 ]]; do
    case "$1" in
    --quick) quick=1; shift ;;
    --data) data=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --bin) bin=$2; shift 2 ;;
    --cache) cache=$2; shift 2 ;;
    -h | --help) sed -n '2,19p' "${BASH_SOURCE[0]}"; exit 0 ;;
    *) echo "experiment_rail.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    esac
done

if [[ ! -x "$bin" ]]; then
    (cd "$repo" && BUILD_DIR="$build_dir" scripts/build.sh)
fi

if [[ $quick -eq 1 ]]; then
    # The bundled pair (frames 0 and 10 of horizontal), every solver, three budgets.
    data=${data:-$repo/data/rail}
    sequences=(horizontal)
    args=(--offsets 10 --pairs-per-offset 1 --budgets-ms 2,10,100)
else
    data=${data:-$repo/../shared/data/rail-a}
    sequences=(horizontal optic)
    args=() # the program's defaults: 16 offsets 1..60, 4 pairs each, budgets 2..1000 ms
fi
for s in "${sequences[@]}"; do
    if [[ ! -f "$data/$s/camera.txt" ]]; then
        echo "experiment_rail.sh: no sequence '$s' in '$data' (expected $data/$s/camera.txt)" >&2
        exit 1
    fi
done

mkdir -p "$out/results" "$out/figures" "$cache"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
start=$(date +%s)
pids=()
for s in "${sequences[@]}"; do
    "$bin" --data "$data" --sequences "$s" --csv "$work/$s.csv" --cache "$cache" "${args[@]}" \
        >"$work/$s.log" 2>"$work/$s.err" &
    pids+=($!)
done
status=0
for i in "${!pids[@]}"; do
    if ! wait "${pids[$i]}"; then
        echo "experiment_rail.sh: ${sequences[$i]} failed:" >&2
        tail -n 3 "$work/${sequences[$i]}.err" >&2
        status=1
    fi
done
[[ $status -eq 0 ]] || exit 1
cat "$work"/*.log
elapsed=$(($(date +%s) - start))

# One per-estimate CSV: the header once, then every sequence's rows.
first=1
for s in "${sequences[@]}"; do
    if [[ $first -eq 1 ]]; then cat "$work/$s.csv"; first=0; else tail -n +2 "$work/$s.csv"; fi
done | gzip -9n >"$out/results/rail_estimates.csv.gz"

# A Python that has matplotlib: $PYTHON, python3 on the PATH, or Debian's (python3-matplotlib).
python=""
for candidate in ${PYTHON:-} python3 /usr/bin/python3; do
    if "$candidate" -c 'import matplotlib' 2>/dev/null; then python=$candidate; break; fi
done
if [[ -z "$python" ]]; then
    echo "experiment_rail.sh: no python3 with matplotlib (Debian: apt-get install python3-matplotlib)" >&2
    exit 1
fi
"$python" "$repo/scripts/plot_rail.py" "$out/results/rail_estimates.csv.gz" \
    --results "$out/results" --figures "$out/figures"

{
    echo "command: scripts/experiment_rail.sh$([[ $quick -eq 1 ]] && echo ' --quick')"
    echo "data: $data"
    echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
    echo "wall time: ${elapsed} s (estimation and matching; plotting not included)"
    echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
    lscpu | grep -E '^(Model name|CPU\(s\)|Thread|Core|Socket|CPU max MHz|L2|L3)' || true
} >"$out/results/rail_run.txt"
echo "experiment_rail.sh: done in ${elapsed} s; see $out/results/rail_run.txt"

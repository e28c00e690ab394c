#!/usr/bin/env bash
# The paper's synthetic experiments (docs/EXPERIMENTS.md): runs essential_paper_synthetic, then
# plots its CSVs with scripts/plot_paper_synthetic.py.
#
#   scripts/experiment_synthetic.sh [--quick] [--part A|B|all] [--csv DIR] [--figures DIR]
#                                   [--bin PATH] [-- more options of essential_paper_synthetic]
#
# Defaults: CSVs to docs/results, figures to docs/figures, the program from ${BUILD_DIR:-build}
# (built by scripts/build.sh if missing). --quick runs the smoke-test size (seconds).
# Licensed under the Apache License, Version 2.0.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

csv=docs/results
figures=docs/figures
part=all
bin=""
quick=()
extra=()
while [[ $# -gt 0 ]]; do
    case "$1" in
        --quick) quick=(--quick); shift ;;
        --part) part=$2; shift 2 ;;
        --csv) csv=$2; shift 2 ;;
        --figures) figures=$2; shift 2 ;;
        --bin) bin=$2; shift 2 ;;
        --) shift; extra=("$@"); break ;;
        *) echo "experiment_synthetic.sh: unknown option $1" >&2; exit 2 ;;
    esac
done

if [[ -z "$bin" ]]; then
    bin=${BUILD_DIR:-build}/bench/essential_paper_synthetic
    [[ -x "$bin" ]] || scripts/build.sh >&2
fi
mkdir -p "$csv" "$figures"
"$bin" --part "$part" --out "$csv" "${quick[@]}" "${extra[@]}"
# Debian's interpreter: matplotlib comes from the python3-matplotlib package.
/usr/bin/python3 scripts/plot_paper_synthetic.py --csv "$csv" --figures "$figures"

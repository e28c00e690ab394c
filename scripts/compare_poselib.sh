#!/usr/bin/env bash
# The accuracy comparison with PoseLib of docs/ACCURACY.md: every configuration of the table, one
# process per configuration, methods in a random order per problem, thread CPU time.
#
#   scripts/compare_poselib.sh [BUILD_DIR] [PROBLEMS]
#
# Needs a build configured with -DPoseLib_DIR (scripts/build_poselib.sh) and the target
# essential_compare_poselib built. To measure an older library with the same program, put its
# directory first in LD_LIBRARY_PATH (the bench uses the public API only).
set -euo pipefail
build=${1:-build}
problems=${2:-200}
bench="$build/bench/essential_compare_poselib"
[[ -x "$bench" ]] || {
  echo "no $bench: configure with -DPoseLib_DIR=... and build essential_compare_poselib" >&2
  exit 2
}
for n in 500 1000; do
  echo "## paper camera, N = $n"
  "$bench" --n "$n" --problems "$problems" --ratios 0.9,0.7,0.5
  "$bench" --n "$n" --problems "$problems" --ratios 0.3,0.25 --max-iters 10000
done
for threshold in 1 3.33; do
  echo "## wide camera, N = 500, threshold $threshold px"
  "$bench" --camera wide --threshold "$threshold" --problems "$problems" --ratios 0.9,0.7,0.5
  "$bench" --camera wide --threshold "$threshold" --problems "$problems" --ratios 0.3,0.25 \
    --max-iters 10000
done

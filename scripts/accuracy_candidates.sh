#!/usr/bin/env bash
# The analysis table of docs/ACCURACY.md: candidate final stages on the same search winners
# (bench/accuracy_candidates.cpp), paper camera at 90/70/50% and 25% (maxIters 10000) inliers, the
# wide camera with a 1 px and a 3.33 px threshold.
#
#   scripts/accuracy_candidates.sh [BUILD_DIR] [PROBLEMS]
set -euo pipefail
build=${1:-build}
problems=${2:-300}
bench="$build/bench/essential_accuracy_candidates"
only="search winner;before:;all points, Cauchy 0.5 thr, 100 it;all points, Cauchy 1 thr, 100 it"
only+=";inliers, Cauchy 0.5 thr, 20 it;inliers, Cauchy 1 thr, 100 it, tol;inliers, least squares"
only+=";(PoseLib's);within 2 thr, Cauchy 1.00 thr, 1 round;within 2 thr in front, Cauchy 1.00 thr, 1"
only+=";final: est. sigma, band max(2 thr, 4 s), scale max(thr, 2 s);Cauchy then Tukey 4.685 s"
only+=";Tukey 4.685 s, 1 round;library default;oracle selection: true inliers, Cauchy 1 thr"
only+=";oracle: true"
"$bench" --problems "$problems" --ratios 0.9,0.7,0.5 --only "$only"
"$bench" --problems "$problems" --ratios 0.25 --max-iters 10000 --only "$only"
"$bench" --problems "$problems" --ratios 0.9,0.5 --camera wide --threshold 1 --only "$only"
"$bench" --problems "$problems" --ratios 0.9,0.5 --camera wide --threshold 3.33 --only "$only"

#!/usr/bin/env bash
# Right-rates on hard pairs (bench/hard_pairs.cpp): OpenCV's cv::findEssentialMat (RANSAC and USAC
# flags), the module's drop-in overload and named EssentialParams configurations on synthetic
# scenes with a dominant plane, repeated structure or clustered inliers (5-25% inliers) and on
# real pairs (rail-a with all or a random 20% of the matches, the Aloe stereo pair with ORB).
#
#   scripts/hard_pairs.sh [essential_hard_pairs options...]
#
# Builds essential_hard_pairs in ${BUILD_DIR:-build} when missing, then runs it from the
# repository's top with the given options (see `scripts/hard_pairs.sh --help`). Unless given,
# --data is the first of ../shared/data and ../../shared/data (next to the repository or to its
# worktree folder) that exists, and --cache is ${BUILD_DIR:-build}/hard_match_cache.
# Example:
#   scripts/hard_pairs.sh --sets synth-plane,rail-all --shuffles 3 \
#       --methods 'cv_ransac,dropin,prosac=ours:sampler=prosac' --csv hard.csv --md hard.md
# Licensed under the Apache License, Version 2.0.
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${BUILD_DIR:-build}
[[ "$build_dir" = /* ]] || build_dir="$repo/$build_dir"
bin="$build_dir/bench/essential_hard_pairs"

if [[ ! -x "$bin" ]]; then
    if [[ ! -f "$build_dir/CMakeCache.txt" ]]; then
        cmake -S "$repo" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DESSENTIAL_BUILD_PERF=OFF
    fi
    cmake --build "$build_dir" -j2 --target essential_hard_pairs
fi

args=("$@")
has() { for a in "${args[@]}"; do [[ "$a" == "$1" || "$a" == "$1="* ]] && return 0; done; return 1; }
if ! has --data; then
    for candidate in "$repo/../shared/data" "$repo/../../shared/data"; do
        if [[ -d "$candidate" ]]; then args+=(--data "$(cd "$candidate" && pwd)"); break; fi
    done
fi
has --cache || args+=(--cache "$build_dir/hard_match_cache")

cd "$repo"
exec "$bin" "${args[@]}"

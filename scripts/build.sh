#!/usr/bin/env bash
# Bootstraps the build dependencies, then configures and builds a Release tree in
# ${BUILD_DIR:-build} (relative to the repository root) with -j$(nproc) (override with JOBS).
# Extra arguments are passed to the CMake configure step, e.g. -DESSENTIAL_BUILD_PERF=OFF.
#
# BUILD_SET chooses what is built:
#   all  (default) every target: the library, samples, tests, perf, benches, Python module;
#        bootstrap.sh installs every package they need.
#   demo the library and essential_pair only (scripts/demo.sh): bootstrap.sh demo installs
#        OpenCV, Eigen and the JSON header, and a tree configured here for the first time leaves
#        the tests, perf, benches and Python module out. A later `BUILD_SET=all` run (test.sh)
#        turns them on in the same tree, reusing what the demo compiled.
# Licensed under the Apache License, Version 2.0.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

build_dir=${BUILD_DIR:-build}
set_name=${BUILD_SET:-all}
parts=(TESTS PERF BENCH PYTHON)
configure=(-DCMAKE_BUILD_TYPE=Release -DESSENTIAL_BUILD_SAMPLES=ON)
targets=()
case "$set_name" in
all)
    for part in "${parts[@]}"; do configure+=("-DESSENTIAL_BUILD_$part=ON"); done
    ;;
demo)
    # An existing tree keeps its options: the demo only needs its one target built.
    if [[ ! -f "$build_dir/CMakeCache.txt" ]]; then
        for part in "${parts[@]}"; do configure+=("-DESSENTIAL_BUILD_$part=OFF"); done
    fi
    targets=(--target essential_pair)
    ;;
*)
    echo "build.sh: unknown BUILD_SET '$set_name' (all or demo)" >&2
    exit 2
    ;;
esac

scripts/bootstrap.sh "$set_name"

cmake -S . -B "$build_dir" "${configure[@]}" "$@"
cmake --build "$build_dir" --config Release -j"${JOBS:-$(nproc)}" "${targets[@]}"

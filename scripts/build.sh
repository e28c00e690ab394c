#!/usr/bin/env bash
# Bootstraps the build dependencies, then configures and builds a Release tree in
# ${BUILD_DIR:-build} (relative to the repository root) with -j$(nproc) (override with JOBS).
# Extra arguments are passed to the CMake configure step, e.g. -DESSENTIAL_BUILD_PERF=OFF.
# Licensed under the Apache License, Version 2.0.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

scripts/bootstrap.sh

build_dir=${BUILD_DIR:-build}
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build "$build_dir" --config Release -j"${JOBS:-$(nproc)}"

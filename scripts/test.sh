#!/usr/bin/env bash
# Builds the Release tree (see build.sh) and runs every ctest entry in it; exits with ctest's
# status. Extra arguments go to ctest, e.g. scripts/test.sh -R install_and_consume
# Licensed under the Apache License, Version 2.0.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

scripts/build.sh

build_dir=${BUILD_DIR:-build}
cd "$build_dir"
exec ctest --output-on-failure -C Release "$@"

#!/usr/bin/env bash
# Builds the library and essential_pair only (BUILD_SET=demo, see build.sh; the tests, benches and
# the rest are scripts/test.sh's) and runs it on the bundled Leuven pair: prints the matches, E, R,
# t, the inliers and the time of each stage, next to OpenCV's findEssentialMat + recoverPose on the
# same matches. Extra arguments go to essential_pair,
# e.g. scripts/demo.sh --solver lm --threshold-px 0.5
# Licensed under the Apache License, Version 2.0.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

BUILD_SET=demo scripts/build.sh

build_dir=${BUILD_DIR:-build}
echo
# About 35% of the Leuven matches are inliers: with OpenCV's default cap of 1000 iterations neither
# estimator reaches 0.999 confidence there, and both return whatever their random draws found (see
# the README). The demo gives both the same cap of 10000, enough for the confidence; pass
# --max-iterations 1000 to see the default behaviour.
exec "$build_dir/bin/essential_pair" data/pairs/leuvenA.jpg data/pairs/leuvenB.jpg \
    --camera-file data/pairs/leuven.camera --max-iterations 10000 "$@"

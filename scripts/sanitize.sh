#!/usr/bin/env bash
# Builds the module, its tests, the CLIs and the libFuzzer target with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer in ${SANITIZE_BUILD_DIR:-build-sanitize}, then runs the ctest suite
# there (every entry, or those matching the arguments, e.g. scripts/sanitize.sh -R BadInput).
# Any sanitizer report stops the process with a non-zero status, so ctest counts it as a failure.
# OpenCV itself is the uninstrumented system library; see docs/ROBUSTNESS.md for what that means.
# Licensed under the Apache License, Version 2.0.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
scripts/bootstrap.sh

build_dir=${SANITIZE_BUILD_DIR:-build-sanitize}
# -O2: at -O1 Eigen's fixed-size code stays a call tree of small functions, each instrumented, so
# that an execution of a fuzz target touched thousands of coverage counters: perf on the
# input-layer target (35 s) put 47% of its time in libFuzzer's per-counter bookkeeping
# (InputCorpus::UpdateFeatureFrequency) and 36% in the target itself; -O2 inlines that code away
# (docs/ROBUSTNESS.md, "Fuzzing" has the rates before and after). The sanitizers' checks are
# inserted before optimisation, so they stay. fuzzer-no-link adds the
# coverage hooks libFuzzer needs to the library, so the same tree serves scripts/fuzz.sh. Without
# its comparison tracing (trace-cmp) in the library: on the solvers' numeric loops the tracing hooks
# took 47% of the solver fuzz target's time (perf, 3 000 runs), and the targets' decoders, where
# comparisons with input bytes do matter, keep it (they are built with -fsanitize=fuzzer).
sanitize_flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
# CXXFLAGS and LDFLAGS (not only CMake options) so that the consumer project that the ctest entry
# install_and_consume configures inherits them too.
export CC=clang CXX=clang++
export CXXFLAGS="-O2 -g ${sanitize_flags} -fsanitize=fuzzer-no-link -fno-sanitize-coverage=trace-cmp"
export LDFLAGS="${sanitize_flags}"
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"

# OpenCV's own tests (test/opencv_calib3d) are left out: they run in the Release tree; here they
# would compile OpenCV's test framework again, and the sanitizers would judge OpenCV's code.
# A tree configured with other flags (an older version of this script) is configured again: CMake
# reads CXXFLAGS only when it creates its cache.
if [[ ! -f "$build_dir/CMakeCache.txt" ]] ||
    ! grep -qxF "CMAKE_CXX_FLAGS:STRING=${CXXFLAGS}" "$build_dir/CMakeCache.txt"; then
    cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Debug -DESSENTIAL_BUILD_FUZZ=ON \
        -DCMAKE_CXX_FLAGS="${CXXFLAGS}" \
        -DESSENTIAL_BUILD_PERF=OFF -DESSENTIAL_BUILD_BENCH=OFF -DESSENTIAL_OPENCV_OWN_TESTS=OFF \
        -DESSENTIAL_BUILD_PYTHON=OFF >/dev/null
fi
cmake --build "$build_dir" -j"${JOBS:-$(nproc)}"

cd "$build_dir"
exec ctest --output-on-failure "$@"

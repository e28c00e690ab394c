#!/usr/bin/env bash
# Installs the Debian packages needed to build, test and run opencv_essential, if any is missing.
# Quiet and quick when everything is present; runs apt-get update only when something is missing.
#
#   scripts/bootstrap.sh        # everything: the tests, perf, benches, Python, COLMAP, sanitizers
#   scripts/bootstrap.sh demo   # only what the library and essential_pair need (scripts/demo.sh)
#
# Licensed under the Apache License, Version 2.0.
set -euo pipefail

set_name=${1:-all}
# The library (OpenCV, Eigen) and the command-line programs (their JSON output).
demo_packages=(cmake g++ make libopencv-dev libeigen3-dev nlohmann-json3-dev)
packages=("${demo_packages[@]}" python3 libgtest-dev libbenchmark-dev
    python3-matplotlib   # the experiments' plots (docs/EXPERIMENTS.md)
    xz-utils patch       # OpenCV's own tests from Debian's source package (docs/OPENCV_TESTS.md)
    clang libclang-rt-dev # clang and its sanitizer / libFuzzer runtimes: sanitize.sh, fuzz.sh
    python3-dev pybind11-dev python3-numpy python3-opencv python3-pytest # the Python module (python/)
    python3-dask python3-distributed python3-tqdm # its batch example on a cluster, progress bar
    colmap libsqlite3-dev # essential_colmap on COLMAP's database, its tests (docs/COLMAP.md)
    ninja-build zlib1g-dev liblapack-dev) # OpenCV 4.6 built with the module in-tree (build_in_opencv.sh)

case "$set_name" in
all) ;;
demo) packages=("${demo_packages[@]}") ;;
*)
    echo "bootstrap.sh: unknown package set '$set_name' (all or demo)" >&2
    exit 2
    ;;
esac

missing=()
for pkg in "${packages[@]}"; do
    status=$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)
    if [[ "$status" != *"install ok installed"* ]]; then
        missing+=("$pkg")
    fi
done

if [[ ${#missing[@]} -eq 0 ]]; then
    exit 0
fi

if [[ $(id -u) -eq 0 ]]; then
    as_root=()
elif command -v sudo >/dev/null 2>&1; then
    as_root=(sudo)
else
    echo "bootstrap.sh: missing packages (${missing[*]}) and not root, no sudo available" >&2
    exit 1
fi

echo "bootstrap.sh: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends \
    "${missing[@]}"

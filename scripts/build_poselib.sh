#!/usr/bin/env bash
# Builds PoseLib (https://github.com/PoseLib/PoseLib, BSD-3-Clause) from its public repository into
# a cache folder outside this source tree, for the accuracy comparison bench
# (bench/compare_poselib.cpp, docs/ACCURACY.md). PoseLib is not a Debian package and is never
# vendored here; nothing in the default build or test command needs it.
#
#   scripts/build_poselib.sh [SOURCE] [PREFIX]
#
#   SOURCE  a git URL or a local git repository / source folder
#           (default https://github.com/PoseLib/PoseLib.git)
#   PREFIX  install prefix (default ${XDG_CACHE_HOME:-~/.cache}/opencv_essential/poselib)
#   POSELIB_REF  commit or tag to build (default: the source's HEAD)
#
# Then configure this project with
#   cmake -S . -B build -DPoseLib_DIR=PREFIX/lib/cmake/PoseLib
# and build the target essential_compare_poselib.
#
# The source is cloned and built in a temporary folder, removed at exit. PoseLib's own compile
# flags are kept (-O3, no -march=native: the same portable x86-64 target as this module's default
# build, whose AVX2 clones PoseLib does not have; see docs/ACCURACY.md).
set -euo pipefail

source=${1:-https://github.com/PoseLib/PoseLib.git}
prefix=${2:-${XDG_CACHE_HOME:-$HOME/.cache}/opencv_essential/poselib}
jobs=${JOBS:-2}

work=$(mktemp -d "${TMPDIR:-/tmp}/poselib-build.XXXXXX")
trap 'rm -rf "$work"' EXIT

if [[ -d "$source" && ! -d "$source/.git" && -f "$source/CMakeLists.txt" ]]; then
  cp -r "$source" "$work/src" # a plain source folder
else
  git clone --quiet "$source" "$work/src" # a URL, a work tree or a bare repository
fi
if [[ -n "${POSELIB_REF:-}" ]]; then
  git -C "$work/src" checkout --quiet "$POSELIB_REF"
fi
if [[ -d "$work/src/.git" ]]; then
  echo "PoseLib $(cat "$work/src/VERSION.txt" 2>/dev/null || echo '?')," \
    "commit $(git -C "$work/src" rev-parse HEAD)"
fi

cmake -S "$work/src" -B "$work/build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_INSTALL_PREFIX="$prefix" -DBUILD_SHARED_LIBS=OFF -DCMAKE_POSITION_INDEPENDENT_CODE=ON \
  -DWITH_BENCHMARK=OFF -DBUILD_TESTS=OFF -DPYTHON_PACKAGE=OFF >"$work/configure.log"
cmake --build "$work/build" -j"$jobs" >"$work/build.log" || {
  tail -30 "$work/build.log"
  exit 1
}
cmake --install "$work/build" >/dev/null
echo "installed to $prefix; configure with -DPoseLib_DIR=$prefix/lib/cmake/PoseLib"

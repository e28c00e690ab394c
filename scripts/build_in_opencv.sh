#!/usr/bin/env bash
# Builds OpenCV 4.6 from Debian's source package with this repository's module as an extra module
# (OPENCV_EXTRA_MODULES_PATH=<repo>/modules), as an opencv_contrib user would, and only what the
# module's in-tree checks need: opencv_test_essential, opencv_perf_essential and the Python
# bindings cv2 (with cv2.essential).
#
#   scripts/build_in_opencv.sh            # prints the build directory on its last line
#
# The OpenCV source (scripts/fetch_opencv_source.sh --full) and the build directory live in a cache
# outside the clone, ${ESSENTIAL_OPENCV_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/opencv_essential}/,
# so a second run only re-configures and rebuilds what changed. One build directory serves every
# clone: a clone at another path re-points OPENCV_EXTRA_MODULES_PATH and rebuilds only the module's
# targets (OpenCV's own objects do not depend on it). A lock serialises concurrent runs.
#
# The configuration is OpenCV's default (C++11 for modules, the module's own targets raise it,
# modules/essential/cmake/in_opencv.cmake) with what costs build time and is not needed switched
# off: no image codecs beyond OpenCV's built-in ones, no video or GUI back ends, no OpenCL, no
# extra SIMD dispatch variants (CPU_DISPATCH empty; the baseline, SSE3 on x86-64, stays), no
# apps, docs, examples or Java. Nothing is downloaded at configure time: Debian's source has no
# 3rdparty/ (hence WITH_QUIRC=OFF and system zlib), and IPP, ADE and protobuf are off.
# JOBS (default 2) sets the build's parallelism. Licensed under the Apache License, Version 2.0.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
repo=$(pwd)

cache=${ESSENTIAL_OPENCV_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/opencv_essential}
src="$cache/opencv-4.6-src"
build="$cache/opencv-4.6-intree-build"
mkdir -p "$cache"

# One run at a time per cache (the source and build directories are shared).
exec 9>"$cache/opencv-4.6-intree.lock"
flock 9

OPENCV_SOURCE_CACHE=${OPENCV_SOURCE_CACHE:-$cache/opencv-source} \
    scripts/fetch_opencv_source.sh --full "$src"

python=/usr/bin/python3
cmake_args=(
    -G Ninja
    -DCMAKE_BUILD_TYPE=Release
    -DOPENCV_EXTRA_MODULES_PATH="$repo/modules"
    -DBUILD_LIST=core,imgproc,imgcodecs,videoio,calib3d,features2d,flann,ts,python3,python_tests,essential
    -DBUILD_TESTS=ON -DBUILD_PERF_TESTS=ON
    -DBUILD_opencv_apps=OFF -DBUILD_DOCS=OFF -DBUILD_EXAMPLES=OFF -DBUILD_JAVA=OFF
    -DBUILD_opencv_python2=OFF -DBUILD_opencv_python3=ON
    -DPYTHON3_EXECUTABLE="$python" -DPYTHON_DEFAULT_EXECUTABLE="$python"
    -DCPU_DISPATCH= -DENABLE_PRECOMPILED_HEADERS=OFF
    -DWITH_EIGEN=ON -DWITH_IPP=OFF -DWITH_QUIRC=OFF -DWITH_ADE=OFF -DWITH_PROTOBUF=OFF
    -DWITH_ITT=OFF -DWITH_OPENCL=OFF -DWITH_VA=OFF -DWITH_VA_INTEL=OFF
    -DWITH_TBB=OFF -DWITH_OPENMP=OFF -DWITH_CUDA=OFF -DWITH_VTK=OFF -DWITH_GTK=OFF -DWITH_QT=OFF
    -DWITH_FFMPEG=OFF -DWITH_GSTREAMER=OFF -DWITH_V4L=OFF -DWITH_1394=OFF -DWITH_OPENEXR=OFF
    -DWITH_PNG=OFF -DWITH_JPEG=OFF -DWITH_TIFF=OFF -DWITH_WEBP=OFF -DWITH_OPENJPEG=OFF
    -DWITH_JASPER=OFF -DWITH_GDAL=OFF -DWITH_GDCM=OFF -DWITH_IMGCODEC_HDR=OFF
    -DWITH_IMGCODEC_SUNRASTER=OFF -DWITH_IMGCODEC_PFM=OFF
    -DBUILD_ZLIB=OFF -DOPENCV_GENERATE_PKGCONFIG=OFF
)

start=$SECONDS
echo "build_in_opencv.sh: configuring $build (OpenCV source $src)" >&2
cmake -S "$src" -B "$build" "${cmake_args[@]}" >"$build.configure.log" 2>&1 || {
    tail -n 40 "$build.configure.log" >&2
    echo "build_in_opencv.sh: configure failed (log: $build.configure.log)" >&2
    exit 1
}
targets=(opencv_test_essential opencv_perf_essential opencv_python3)
for target in "${targets[@]}"; do
    grep -q "^build $target:\|^build bin/$target:\| $target: phony" "$build/build.ninja" ||
        { echo "build_in_opencv.sh: configure made no target $target (log: $build.configure.log)" >&2; exit 1; }
done
echo "build_in_opencv.sh: configured in $((SECONDS - start)) s; building ${targets[*]}" >&2
cmake --build "$build" -j"${JOBS:-2}" --target "${targets[@]}" >&2
echo "build_in_opencv.sh: done in $((SECONDS - start)) s" >&2
echo "$build"

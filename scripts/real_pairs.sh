#!/usr/bin/env bash
# The real-data pose benchmark of docs/REAL_PAIRS.md, one command: builds PoseLib into the cache
# when it is not there (scripts/build_poselib.sh), lays out the public multi-view scenes when they
# are not there (scripts/fetch_real_pairs.sh), builds the benchmark against PoseLib in its own tree,
# and runs it with both front ends (OpenCV's SIFT with Lowe's ratio test, and the sample FAST-9 one)
# on the real scenes, the rail-a renders at wide offsets (when RAIL is given or found) and the hard
# synthetic scenes. Nothing it fetches enters the repository.
#
#   scripts/real_pairs.sh [OUT_DIR]         (default docs/results)
#
# Environment:
#   BUILD_DIR       the benchmark's build tree (default build-real)
#   REAL_DATA       the scenes (default ${XDG_CACHE_HOME:-~/.cache}/opencv_essential/real)
#   REAL_SOURCES    passed to fetch_real_pairs.sh as --source arguments (e.g. a local mirror)
#   POSELIB_SOURCE  PoseLib's git URL or a local repository (default its public repository)
#   RAIL            rail-a folder (default ../shared/data/rail-a when it exists; else no rail set)
#   HARD            synthetic problems per hard set and ratio (default 10)
#   EXTRA           more arguments for essential_real_pairs (e.g. --methods ...)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

out=${1:-docs/results}
build=${BUILD_DIR:-build-real}
cache=${XDG_CACHE_HOME:-$HOME/.cache}/opencv_essential
data=${REAL_DATA:-$cache/real}
hard=${HARD:-10}
rail=${RAIL:-}
[[ -z "$rail" && -d ../shared/data/rail-a ]] && rail=../shared/data/rail-a

scripts/bootstrap.sh
if [[ ! -f "$cache/poselib/lib/cmake/PoseLib/PoseLibConfig.cmake" ]]; then
  echo "== PoseLib is not in $cache/poselib: building it"
  scripts/build_poselib.sh ${POSELIB_SOURCE:+"$POSELIB_SOURCE"}
fi
if ! compgen -G "$data/*/cameras.txt" >/dev/null; then
  echo "== no scenes in $data: laying them out"
  # shellcheck disable=SC2086
  scripts/fetch_real_pairs.sh ${REAL_SOURCES:-} --max-side 1536 "$data"
fi

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DESSENTIAL_BUILD_TESTS=OFF \
  -DESSENTIAL_BUILD_PERF=OFF -DESSENTIAL_BUILD_PYTHON=OFF \
  -DPoseLib_DIR="$cache/poselib/lib/cmake/PoseLib" >/dev/null
cmake --build "$build" --target essential_real_pairs -j"${JOBS:-$(nproc)}" >/dev/null

mkdir -p "$out"
bench="$build/bench/essential_real_pairs"
rail_args=()
[[ -n "$rail" ]] && rail_args=(--rail "$rail")
for fe in sift fast; do
  echo "== front end $fe"
  # shellcheck disable=SC2086
  "$bench" --data "$data" "${rail_args[@]}" --hard "$hard" --front-end "$fe" \
    --cache "$build/real_match_cache" --csv "$out/real_pairs_$fe.csv" --md "$out/real_pairs_$fe.md" \
    ${EXTRA:-} >/dev/null
  gzip -f "$out/real_pairs_$fe.csv" # per-pair rows, kept compressed beside the tables
  echo "   $out/real_pairs_$fe.md"
done

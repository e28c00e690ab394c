#!/usr/bin/env bash
# Time and inlier rate of the sample front end's matchers (essential_pair --matcher brute-force,
# grid, flann) on the bundled Leuven pair, the real pairs of /work/shared/data/pairs and the
# bundled rail pair: per pair and matcher the median over REPEATS runs (default 3) of the
# detection + description time of both images and of the matching time, the number of matches,
# cv::essential's and OpenCV's inlier ratio (inliers / matches) and the translation direction
# (cv::essential). Prints a Markdown table (docs/FRONTEND.md, "Faster matching").
# The aloe and books pairs come without intrinsics: a focal length of the image width and the
# principal point at the centre are assumed (aloe is rectified, so its true t is +-x whatever the
# focal length); every matcher gets the same camera.
# usage: scripts/frontend_matchers.sh [PAIRS_DIR]   (BUILD_DIR, REPEATS from the environment)
# Licensed under the Apache License, Version 2.0.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
program=${BUILD_DIR:-build}/bin/essential_pair
shared=${1:-/work/shared/data/pairs}
repeats=${REPEATS:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "1282 1282 640.5 554.5 1282 1110" > "$work/aloe.camera"
echo "612 612 305.5 229 612 459" > "$work/books.camera"

pairs=(
  "leuven|data/pairs/leuvenA.jpg data/pairs/leuvenB.jpg --camera-file data/pairs/leuven.camera"
  "aloe|$shared/aloeL.jpg $shared/aloeR.jpg --camera-file $work/aloe.camera"
  "books|$shared/left.jpg $shared/right.jpg --camera-file $work/books.camera"
  "rail 0-10|data/rail/horizontal/000.jpg data/rail/horizontal/010.jpg --camera-file data/rail/horizontal/camera.txt"
)
echo "| pair | matcher | corners (image 1, 2) | matches | detect+describe ms (both) | matching ms | inlier ratio | OpenCV inlier ratio | t |"
echo "|---|---|---|---|---|---|---|---|---|"
for entry in "${pairs[@]}"; do
  name=${entry%%|*}
  read -r -a args <<< "${entry#*|}"
  for matcher in brute-force grid flann; do
    for ((r = 0; r < repeats; ++r)); do
      "$program" "${args[@]}" --max-iterations 10000 --matcher "$matcher" --json 2>/dev/null
      echo "@@"
    done > "$work/runs.txt"
    /usr/bin/python3 - "$name" "$matcher" "$work/runs.txt" <<'PY'
import json, statistics, sys
name, matcher, path = sys.argv[1:4]
runs = [json.loads(t) for t in open(path).read().split("@@") if t.strip()]
f = runs[0]["frontend"]
detect = statistics.median(r["times_ms"]["frontend"]["image1"] + r["times_ms"]["frontend"]["image2"] for r in runs)
match = statistics.median(r["times_ms"]["frontend"]["matching"] for r in runs)
ours, cv = runs[0]["essential"], runs[0]["opencv"]
t = "(%s)" % ", ".join("%.2f" % v for v in ours.get("t", []))
print("| %s | %s | %d, %d | %d | %.0f | %.0f | %.3f | %.3f | %s |" % (
    name, matcher, f["corners"][0], f["corners"][1], f["matches"], detect, match,
    ours["inlier_ratio"], cv["inlier_ratio"], t))
PY
  done
done

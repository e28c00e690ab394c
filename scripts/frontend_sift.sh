#!/usr/bin/env bash
# The SIFT front end (essential_pair --detector sift: cv::SIFT, Lowe's ratio test 0.8, every
# survivor kept) against the default FAST-9 pyramid + upright BRIEF front end (best 20% of the
# nearest-neighbour matches), on the bundled Leuven pair and the bundled rail pair (frames 0 and 10,
# true t = (-1, 0, 0) within 0.3 degrees): per pair and front end the keypoints, the matches, the
# inliers of cv::essential and its inlier ratio, the median over REPEATS runs (default 5) of the
# detection + description time of both images, of the matching time and of their sum, and the
# translation direction. Prints a Markdown table (docs/FRONTEND.md, "SIFT with a ratio test").
# usage: scripts/frontend_sift.sh   (BUILD_DIR, REPEATS from the environment)
# Licensed under the Apache License, Version 2.0.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
program=${BUILD_DIR:-build}/bin/essential_pair
repeats=${REPEATS:-5}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

pairs=(
  "leuven|data/pairs/leuvenA.jpg data/pairs/leuvenB.jpg --camera-file data/pairs/leuven.camera"
  "rail 0-10|data/rail/horizontal/000.jpg data/rail/horizontal/010.jpg --camera-file data/rail/horizontal/camera.txt"
)
frontends=(
  "fast|"
  "fast, grid|--matcher grid"
  "sift|--detector sift"
  "sift, flann|--detector sift --matcher flann"
  "sift, grid|--detector sift --matcher grid"
)
echo "| pair | front end | keypoints (image 1, 2) | matches | inliers (ratio) | detect+describe ms (both) | matching ms | front end ms | t |"
echo "|---|---|---|---|---|---|---|---|---|"
for entry in "${pairs[@]}"; do
  name=${entry%%|*}
  read -r -a args <<< "${entry#*|}"
  for frontend in "${frontends[@]}"; do
    label=${frontend%%|*}
    read -r -a options <<< "${frontend#*|}"
    for ((r = 0; r < repeats; ++r)); do
      "$program" "${args[@]}" --max-iterations 10000 --no-opencv "${options[@]}" --json 2>/dev/null
      echo "@@"
    done > "$work/runs.txt"
    /usr/bin/python3 - "$name" "$label" "$work/runs.txt" <<'PY'
import json, statistics, sys
name, label, path = sys.argv[1:4]
runs = [json.loads(t) for t in open(path).read().split("@@") if t.strip()]
f = runs[0]["frontend"]
times = [r["times_ms"]["frontend"] for r in runs]
detect = statistics.median(t["image1"] + t["image2"] for t in times)
match = statistics.median(t["matching"] for t in times)
total = statistics.median(t["total"] for t in times)
ours = runs[0]["essential"]
t = "(%s)" % ", ".join("%.3f" % v for v in ours.get("t", []))
print("| %s | %s | %d, %d | %d | %d (%.3f) | %.0f | %.0f | %.0f | %s |" % (
    name, label, f["corners"][0], f["corners"][1], f["matches"], ours["inliers"],
    ours["inlier_ratio"], detect, match, total, t))
PY
  done
done

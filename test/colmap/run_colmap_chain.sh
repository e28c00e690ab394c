#!/usr/bin/env bash
# The whole structure-from-motion chain on the bundled rail frames: COLMAP's database (made by
# make_colmap_database.sh), its two-view geometries replaced by essential_colmap's, `colmap mapper`,
# then every image must register and the poses must match the truth after a similarity alignment.
#   run_colmap_chain.sh ESSENTIAL_COLMAP DATABASE IMAGE_DIR WORK_DIR
# Exits 77 (skip) when colmap or the database is missing.
set -euo pipefail
tool=$1
database=$2
image_dir=$3
work=$4
here=$(cd "$(dirname "$0")" && pwd)
if ! command -v colmap >/dev/null 2>&1 || [[ ! -f $database ]]; then
    echo "SKIPPED: colmap is not installed or $database was not made" >&2
    exit 77
fi
rm -rf "$work"
mkdir -p "$work/sparse"
cp "$database" "$work/ours.db"
"$tool" --database "$work/ours.db"
export QT_QPA_PLATFORM=offscreen
colmap mapper --database_path "$work/ours.db" --image_path "$image_dir" \
    --output_path "$work/sparse" >"$work/mapper.log" 2>&1
frames=$(ls "$image_dir"/*.jpg | wc -l)
# Tolerances: on these five frames (0.5 units apart, 2 units of travel, 2000 SIFT features each)
# the measured errors were at most 0.042 degrees of rotation and 0.00065 units of position; the
# bounds, 0.5 degrees and 0.02 units (1% of the travel), leave a wide margin for other COLMAP
# builds' features while a wrong verification (a pair's inliers from a wrong E) breaks them.
/usr/bin/python3 "$here/../../scripts/colmap_tools.py" compare --model "ours=$work/sparse/0" \
    --truth "$image_dir/poses.txt" --json "$work/compare.json" \
    --require-registered "$frames" --max-rotation-deg 0.5 --max-position 0.02

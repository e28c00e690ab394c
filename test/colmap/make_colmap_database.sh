#!/usr/bin/env bash
# Creates a COLMAP 3.8 database the way a user would: CPU SIFT feature extraction with the known
# camera (PINHOLE, prior focal length) and exhaustive matching, on the frames of IMAGE_DIR.
#   make_colmap_database.sh IMAGE_DIR OUT.db [MAX_FEATURES]
# IMAGE_DIR holds NNN.jpg and camera.txt (3 x 3 K, pixel centres at integer coordinates, as
# OpenCV); COLMAP's pixel coordinates put the centre of the top-left pixel at (0.5, 0.5), so its
# principal point is K's plus 0.5. Exits 77 (ctest's skip code) when colmap is not installed.
set -euo pipefail
image_dir=$1
out=$2
max_features=${3:-2000}
if ! command -v colmap >/dev/null 2>&1; then
    echo "SKIPPED: colmap is not installed (scripts/bootstrap.sh installs it)" >&2
    exit 77
fi
read -r fx _ cx < <(sed -n 1p "$image_dir/camera.txt")
read -r _ fy cy < <(sed -n 2p "$image_dir/camera.txt")
params=$(awk -v fx="$fx" -v fy="$fy" -v cx="$cx" -v cy="$cy" \
    'BEGIN { printf "%.12g,%.12g,%.12g,%.12g", fx, fy, cx + 0.5, cy + 0.5 }')
rm -f "$out"
export QT_QPA_PLATFORM=offscreen
# COLMAP 3.x (Debian 12 and 13) names the GPU switches Sift*.use_gpu; 4.x (Debian unstable)
# Feature*.use_gpu. Asked of the program itself.
extract_gpu=--SiftExtraction.use_gpu
match_gpu=--SiftMatching.use_gpu
help=$(colmap feature_extractor -h 2>&1 || true)
if grep -q -- '--FeatureExtraction.use_gpu' <<<"$help"; then
    extract_gpu=--FeatureExtraction.use_gpu
    match_gpu=--FeatureMatching.use_gpu
fi
if ! colmap feature_extractor --database_path "$out" --image_path "$image_dir" \
    --ImageReader.camera_model PINHOLE --ImageReader.single_camera 1 \
    --ImageReader.camera_params "$params" \
    "$extract_gpu" 0 --SiftExtraction.max_num_features "$max_features" >"$out.log" 2>&1; then
    tail -n 20 "$out.log" >&2
    exit 1
fi
if ! colmap exhaustive_matcher --database_path "$out" "$match_gpu" 0 >>"$out.log" 2>&1; then
    tail -n 20 "$out.log" >&2
    exit 1
fi
echo "created $out (camera PINHOLE $params)"

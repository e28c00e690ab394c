#!/usr/bin/env bash
# COLMAP's geometric verification against the module's, on the same matches, and the
# reconstructions `colmap mapper` makes from each (docs/COLMAP.md).
#
#   scripts/experiment_colmap.sh [DATA_DIR]        DATA_DIR default: ../shared/data
#
# For each data set (rail-a horizontal and optic, with ground-truth poses; the Leuven pair):
#  1. COLMAP CPU feature extraction with the known camera (PINHOLE, prior focal length) and
#     exhaustive matching: base.db, with COLMAP's own two-view geometries;
#  2. verification time, REPEATS times in turn on fresh copies of base.db: ours
#     (`essential_colmap`, all threads) against COLMAP's own verification of the same raw matches
#     (`colmap matches_importer --match_type raw` on a copy whose matches and two-view geometries
#     were deleted: it imports the matches and verifies them, all threads), both as the wall time of
#     the whole process; plus the importer on an empty match list, its fixed cost;
#  3. `colmap mapper` on COLMAP's database and on ours, then scripts/colmap_tools.py compare:
#     registered images, 3D points, track length, reprojection error, and for rail-a the poses
#     against the truth after a similarity alignment, with a plot of the camera paths.
# Environment: OUT (default build/colmap_experiment), PROGRAM (default build/bin/essential_colmap),
# FRAME_STEP (every k-th rail frame, default 1: all 61), MAX_FEATURES (SIFT features per image,
# default 2000 for rail-a; the Leuven pair gets COLMAP's default, 8192), REPEATS (default 3), SETS
# (default "horizontal optic leuven").
#
# Both mappers run with --Mapper.init_max_forward_motion 1.0: COLMAP's default (0.95) refuses an
# initial pair whose motion is mostly along the optical axis, which is every pair of rail-a optic
# and the Leuven pair, so neither verification could reconstruct them otherwise. For the Leuven pair
# both also get --Mapper.init_min_tri_angle 4 (default 16): its triangulation angles are small, and
# with the default the mapper found no initial pair from either verification in some runs.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
data=$(cd "${1:-$root/../shared/data}" && pwd)
out=${OUT:-$root/build/colmap_experiment}
program=${PROGRAM:-$root/build/bin/essential_colmap}
frame_step=${FRAME_STEP:-1}
max_features=${MAX_FEATURES:-2000}
repeats=${REPEATS:-3}
sets=${SETS:-horizontal optic leuven}
tools="/usr/bin/python3 $root/scripts/colmap_tools.py"
export QT_QPA_PLATFORM=offscreen
command -v colmap >/dev/null || { echo "colmap is not installed (scripts/bootstrap.sh)" >&2; exit 1; }
[[ -x $program ]] || { echo "no $program: build the target essential_colmap" >&2; exit 1; }
mkdir -p "$out"

# wall_seconds LOG COMMAND...: runs COMMAND (output to LOG), prints its wall time in seconds; a
# failure is noted in LOG (a mapper that finds no initial pair), not fatal.
wall_seconds() {
    local log=$1
    shift
    local start end
    start=$(date +%s.%N)
    "$@" >"$log" 2>&1 || echo "(exit status $?)" >>"$log"
    end=$(date +%s.%N)
    awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f\n", b - a }'
}

# sql DB STATEMENT: runs one SQL statement (Python's sqlite3: no sqlite3 program needed), prints the
# first column of each row.
sql() {
    /usr/bin/python3 -c 'import sqlite3, sys
db = sqlite3.connect(sys.argv[1])
for row in db.execute(sys.argv[2]):
    print(row[0])
db.commit()' "$1" "$2"
}

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

run_set() {
    local name=$1 images=$2 fx=$3 fy=$4 cx=$5 cy=$6 truth=$7 features=$8
    local mapper_options=(--Mapper.init_max_forward_motion 1.0 ${9:-})
    local dir=$out/$name
    rm -rf "$dir"
    mkdir -p "$dir"
    # COLMAP's pixel coordinates put the top-left pixel's centre at (0.5, 0.5): K's principal point
    # (pixel centres at integers, as OpenCV) plus 0.5.
    local params
    params=$(awk -v fx="$fx" -v fy="$fy" -v cx="$cx" -v cy="$cy" \
        'BEGIN { printf "%.12g,%.12g,%.12g,%.12g", fx, fy, cx + 0.5, cy + 0.5 }')
    echo "== $name: $(ls "$images" | wc -l) images, camera PINHOLE $params" >&2
    local t_extract t_match
    t_extract=$(wall_seconds "$dir/extract.log" colmap feature_extractor \
        --database_path "$dir/base.db" --image_path "$images" --ImageReader.camera_model PINHOLE \
        --ImageReader.single_camera 1 --ImageReader.camera_params "$params" \
        --SiftExtraction.use_gpu 0 --SiftExtraction.max_num_features "$features")
    t_match=$(wall_seconds "$dir/match.log" colmap exhaustive_matcher \
        --database_path "$dir/base.db" --SiftMatching.use_gpu 0)
    $tools export-matches "$dir/base.db" "$dir/raw_matches.txt" >/dev/null
    : >"$dir/empty_matches.txt"
    local pairs
    pairs=$(sql "$dir/base.db" "SELECT count(*) FROM matches")

    # Verification time, ours and COLMAP's in turn.
    : >"$dir/ours_s.txt"
    : >"$dir/ours_estimate_ms.txt"
    : >"$dir/colmap_s.txt"
    : >"$dir/colmap_fixed_s.txt"
    for r in $(seq 1 "$repeats"); do
        cp "$dir/base.db" "$dir/ours_$r.db"
        wall_seconds "$dir/ours_$r.log" "$program" --database "$dir/ours_$r.db" --json \
            >>"$dir/ours_s.txt"
        /usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['estimate_ms'])" \
            "$dir/ours_$r.log" >>"$dir/ours_estimate_ms.txt"
        for kind in raw empty; do
            cp "$dir/base.db" "$dir/colmap_$kind.db"
            sql "$dir/colmap_$kind.db" "DELETE FROM matches"
            sql "$dir/colmap_$kind.db" "DELETE FROM two_view_geometries"
        done
        wall_seconds "$dir/colmap_verify_$r.log" colmap matches_importer \
            --database_path "$dir/colmap_raw.db" --match_list_path "$dir/raw_matches.txt" \
            --match_type raw --SiftMatching.use_gpu 0 >>"$dir/colmap_s.txt"
        wall_seconds "$dir/colmap_empty_$r.log" colmap matches_importer \
            --database_path "$dir/colmap_empty.db" --match_list_path "$dir/empty_matches.txt" \
            --match_type raw --SiftMatching.use_gpu 0 >>"$dir/colmap_fixed_s.txt"
    done
    local ours_s ours_ms colmap_s colmap_fixed_s
    ours_s=$(median <"$dir/ours_s.txt")
    ours_ms=$(median <"$dir/ours_estimate_ms.txt" | awk '{ printf "%.0f", $1 }')
    colmap_s=$(median <"$dir/colmap_s.txt")
    colmap_fixed_s=$(median <"$dir/colmap_fixed_s.txt")
    local inliers_ours inliers_colmap
    inliers_ours=$(sql "$dir/ours_1.db" "SELECT sum(rows) FROM two_view_geometries")
    inliers_colmap=$(sql "$dir/colmap_raw.db" "SELECT sum(rows) FROM two_view_geometries")

    # Reconstructions: COLMAP's verification (exhaustive_matcher's) and ours.
    local model
    for model in base ours_1; do
        mkdir -p "$dir/sparse_$model"
        wall_seconds "$dir/mapper_$model.log" colmap mapper --database_path "$dir/$model.db" \
            --image_path "$images" --output_path "$dir/sparse_$model" "${mapper_options[@]}" \
            >"$dir/mapper_${model}_s.txt"
    done
    local truth_args=()
    [[ -n $truth ]] && truth_args=(--truth "$truth" --plot "$dir/paths.png"
        --title "$name: camera centres after similarity alignment")
    $tools compare --model "COLMAP=$dir/sparse_base/0" --model "ours=$dir/sparse_ours_1/0" \
        --json "$dir/compare.json" "${truth_args[@]}" >"$dir/compare.md" || true

    {
        echo "## $name"
        echo
        echo "$(ls "$images" | wc -l) images, $pairs matched pairs; feature extraction ${t_extract} s, exhaustive matching ${t_match} s."
        echo
        echo "| verification of the same matches | wall time (median of $repeats) | inlier matches |"
        echo "|---|---|---|"
        echo "| COLMAP (matches_importer --match_type raw) | ${colmap_s} s (of which ${colmap_fixed_s} s with no matches) | $inliers_colmap |"
        echo "| ours (essential_colmap) | ${ours_s} s (estimation ${ours_ms} ms) | $inliers_ours |"
        echo
        cat "$dir/compare.md"
        echo
        echo "Agreement of the verifications (A: COLMAP's on the same raw matches, B: ours):"
        echo
        $tools agreement "$dir/colmap_raw.db" "$dir/ours_1.db" | sed 's/^/    /'
        echo
    } | tee "$dir/summary.md"
}

: >"$out/results.md"
for set in $sets; do
    case $set in
    horizontal | optic)
        src=$data/rail-a/$set
        images=$out/$set-images
        rm -rf "$images"
        mkdir -p "$images"
        for f in "$src"/[0-9][0-9][0-9].jpg; do
            k=$((10#$(basename "$f" .jpg)))
            ((k % frame_step == 0)) && ln -s "$f" "$images/"
        done
        read -r fx _ cx < <(sed -n 1p "$src/camera.txt")
        read -r _ fy cy < <(sed -n 2p "$src/camera.txt")
        run_set "$set" "$images" "$fx" "$fy" "$cx" "$cy" "$src/poses.txt" "$max_features" \
            >>"$out/results.md"
        ;;
    leuven)
        images=$out/leuven-images
        rm -rf "$images"
        mkdir -p "$images"
        ln -s "$data/pairs/leuvenA.jpg" "$data/pairs/leuvenB.jpg" "$images/"
        read -r fx fy cx cy _ < "$data/pairs/leuven.camera"
        run_set leuven "$images" "$fx" "$fy" "$cx" "$cy" "" 8192 "--Mapper.init_min_tri_angle 4" \
            >>"$out/results.md"
        ;;
    *)
        echo "unknown set $set" >&2
        exit 2
        ;;
    esac
done
echo "results: $out/results.md" >&2

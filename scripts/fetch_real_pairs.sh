#!/usr/bin/env bash
# Lays out public multi-view image sets with accurate ground-truth cameras, for the pose benchmark
# on real wide-baseline pairs (bench/real_dataset.hpp reads the result). Nothing it writes belongs
# in the repository: the data stay in DEST, outside the clone.
#
#   scripts/fetch_real_pairs.sh [--source SET=GIT_URL_OR_LOCAL_GIT_DIR ...] [--sets SET,...]
#                               [--max-side PX] [--force] [DEST]
#
# DEST defaults to ${XDG_CACHE_HOME:-$HOME/.cache}/opencv_essential/real. Each scene becomes
#   DEST/<scene>/images/<file>      the images (originals, or resized copies with --max-side)
#   DEST/<scene>/cameras.txt        '#' comment lines, then one line per image:
#       name width height fx fy cx cy r11 r12 r13 r21 r22 r23 r31 r32 r33 t1 t2 t3
#     name is the file name in images/; x_cam = R X_world + t (world to camera); a pixel is
#     (fx x/z + cx, fy y/z + cy), origin top-left, pixel centres at integer coordinates; no skew,
#     no distortion (both sets below are distortion-free: the script fails if a file says otherwise).
#   DEST/<scene>/SOURCE.txt         origin, commit, terms of use, the layout's options
#
# Sets (SET names for --source and --sets; default: all):
#   strecha          openMVG/SfM_quality_evaluation: Strecha et al., CVPR 2008, "On benchmarking
#                    camera calibration and multi-view stereo for high resolution imagery" (EPFL
#                    CVLab): fountain-P11, Herz-Jesus-P8, Herz-Jesus-P25, entry-P10, castle-P19,
#                    castle-P30; 3072x2048 JPEG, undistorted, cameras from LIDAR-registered
#                    calibration (*.camera: K, 3 distortion terms (zero), R camera-to-world, centre C,
#                    size; P = K [R^T | -R^T C]). castle-P19 shares 10 images, with the same
#                    relative poses, with castle-P30.
#   middlebury-temple  sreeharipremkumar/Structure-From-Motion: Middlebury multi-view stereo
#                    templeRing (Seitz et al., CVPR 2006), 47 views of a plaster temple on a ring,
#                    640x480 PNG; templeR_par.txt: name K R t with P = K [R | t]. This copy's images
#                    are turned a quarter turn (480x640, the temple upright); each is turned back to
#                    the original orientation that its camera describes (the 16 that
#                    maximm8/VisualHull's templeSparseRing also holds come out pixel-identical).
#   middlebury-dino  maximm8/VisualHull: Middlebury dinoSparseRing, 16 views of an untextured
#                    ceramic dinosaur, 640x480 PNG, dinoSR_par.txt as above.
#
# --source SET=SRC  SRC is a git URL (cloned with --depth 1 into a temporary directory) or a local
#                   git directory (bare, e.g. a mirror, or a work tree); its HEAD is read with
#                   `git archive`. Default: the public GitHub URL above. (A mirror that lacks a
#                   repository's largest files makes git archive print "invalid object" for them;
#                   the files read here are not among them, and each is checked.)
# --sets LIST       comma-separated sets to lay out.
# --max-side PX     write copies whose longer side is at most PX (cv2.resize INTER_AREA; JPEG
#                   quality 95, PNG as PNG) and scale K with them (f' = f s, c' = (c + 0.5) s - 0.5);
#                   smaller images are copied as they are. 0 (the default) keeps the originals.
# --force           lay out again scenes that are already there (replaced whole).
#
# A scene whose cameras.txt exists is skipped (each scene is built in DEST/.<scene>.partial and
# renamed into place when complete); a set none of whose scenes is missing is not fetched. Needs
# git, tar and /usr/bin/python3 (or $PYTHON) with numpy and cv2.
# Licensed under the Apache License, Version 2.0.
set -euo pipefail

me=fetch_real_pairs.sh
die() {
    echo "$me: $*" >&2
    exit 1
}
usage() { # the header comment
    sed -n '2,/^# Licensed/p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
    exit 0
}

all_sets=(strecha middlebury-temple middlebury-dino)
declare -A url=(
    [strecha]=https://github.com/openMVG/SfM_quality_evaluation.git
    [middlebury-temple]=https://github.com/sreeharipremkumar/Structure-From-Motion.git
    [middlebury-dino]=https://github.com/maximm8/VisualHull.git
)
declare -A scenes=(
    [strecha]="fountain-P11 Herz-Jesus-P8 Herz-Jesus-P25 entry-P10 castle-P19 castle-P30"
    [middlebury-temple]="templeRing"
    [middlebury-dino]="dinoSparseRing"
)
declare -A paths=(
    [strecha]=Benchmarking_Camera_Calibration_2008
    [middlebury-temple]=templeRing
    [middlebury-dino]=dinoSparseRing
)
declare -A source_of=()
add_source() {
    local spec=$1 set_name
    [[ "$spec" == ?*=?* ]] || die "--source wants SET=SRC, got '$spec'"
    set_name=${spec%%=*}
    [[ -n "${url[$set_name]+x}" ]] || die "unknown set '$set_name' (sets: ${all_sets[*]})"
    source_of[$set_name]=${spec#*=}
}
sets_csv=$(IFS=,; echo "${all_sets[*]}")
max_side=0
force=0
dest=""
while [[ $# -gt 0 ]]; do
    case "$1" in
    -h | --help) usage 0 ;;
    --source=*) add_source "${1#--source=}" ;;
    --source)
        [[ $# -ge 2 ]] || die "--source needs SET=SRC"
        add_source "$2"
        shift
        ;;
    --sets=*) sets_csv=${1#--sets=} ;;
    --sets)
        [[ $# -ge 2 ]] || die "--sets needs a list"
        sets_csv=$2
        shift
        ;;
    --max-side=*) max_side=${1#--max-side=} ;;
    --max-side)
        [[ $# -ge 2 ]] || die "--max-side needs a number of pixels"
        max_side=$2
        shift
        ;;
    --force) force=1 ;;
    -*) die "unknown option $1 (see --help)" ;;
    *)
        [[ -z "$dest" ]] || die "more than one DEST given: $dest and $1"
        dest=$1
        ;;
    esac
    shift
done
[[ "$max_side" =~ ^[0-9]+$ ]] || die "--max-side wants a whole number of pixels, got '$max_side'"
[[ "$max_side" -eq 0 || "$max_side" -ge 64 ]] || die "--max-side $max_side is too small"
dest=${dest:-${XDG_CACHE_HOME:-$HOME/.cache}/opencv_essential/real}
IFS=, read -r -a sets <<<"$sets_csv"
for s in "${sets[@]}"; do
    [[ -n "${url[$s]+x}" ]] || die "unknown set '$s' in --sets (sets: ${all_sets[*]})"
done
python=${PYTHON:-/usr/bin/python3}
"$python" -c 'import numpy, cv2' 2>/dev/null || die "$python lacks numpy or cv2"
command -v git >/dev/null || die "git is not installed"
mkdir -p "$dest"
dest=$(cd "$dest" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if [[ $max_side -eq 0 ]]; then sizing="original images"; else sizing="longer side at most $max_side px"; fi
echo "$me: laying out into $dest ($sizing)"

# The git directory to read a set from: a local bare repository or work tree as it is, a URL
# cloned (shallow, bare) into $tmp.
git_dir_of() {
    local set_name=$1 src=$2 g
    if [[ -d "$src" ]]; then
        if g=$(git --git-dir="$src" rev-parse --absolute-git-dir 2>/dev/null) ||
            g=$(git -C "$src" rev-parse --absolute-git-dir 2>/dev/null); then
            echo "$g"
            return
        fi
        die "$src is a directory but not a git repository"
    fi
    echo "$me: [$set_name] cloning $src" >&2
    git clone --quiet --bare --depth 1 "$src" "$tmp/$set_name.git" >&2 ||
        die "[$set_name] git clone $src failed (no network? give --source $set_name=LOCAL_GIT_DIR)"
    echo "$tmp/$set_name.git"
}

for s in "${sets[@]}"; do
    missing=()
    for scene in ${scenes[$s]}; do
        if [[ $force -eq 0 && -f "$dest/$scene/cameras.txt" ]]; then
            recorded=$(sed -n 's/^max_side: //p' "$dest/$scene/SOURCE.txt" 2>/dev/null || true)
            note=""
            [[ "$recorded" == "$max_side" ]] ||
                note=" (laid out with max side ${recorded:-?}, not $max_side: --force to redo)"
            echo "$me: [$s] $scene: already laid out, skipped$note"
        else
            missing+=("$scene")
        fi
    done
    [[ ${#missing[@]} -gt 0 ]] || continue
    src=${source_of[$s]:-${url[$s]}}
    g=$(git_dir_of "$s" "$src")
    commit=$(git --git-dir="$g" rev-parse HEAD) || die "[$s] $src has no HEAD commit"
    echo "$me: [$s] reading $src at $commit"
    rm -rf "${tmp:?}/$s"
    mkdir -p "$tmp/$s"
    git --git-dir="$g" archive --format=tar "$commit" -- "${paths[$s]}" | tar -x -C "$tmp/$s" ||
        die "[$s] $src at $commit lacks ${paths[$s]} (git archive failed)"
    for scene in "${missing[@]}"; do
        partial="$dest/.$scene.partial"
        rm -rf "$partial"
        "$python" - "$s" "$scene" "$tmp/$s/${paths[$s]}" "$partial" "$max_side" "$src" \
            "${url[$s]}" "$commit" <<'PY' || die "[$s] $scene: layout failed"
import os, shutil, sys
import numpy as np
import cv2

set_name, scene, root, out, max_side, src, public_url, commit = sys.argv[1:]
max_side = int(max_side)
me = "fetch_real_pairs.sh"

def fail(msg):
    sys.exit(f"{me}: [{set_name}] {scene}: {msg}")

def numbers(path, tokens):
    try:
        return [float(v) for v in tokens]
    except ValueError:
        fail(f"{path}: a field is not a number")

def rotation(R, what):
    R = np.asarray(R, float).reshape(3, 3)
    if np.abs(R.T @ R - np.eye(3)).max() > 1e-4 or np.linalg.det(R) < 0:
        fail(f"{what}: R is not a rotation")
    U, _, Vt = np.linalg.svd(R)  # the nearest rotation, so that the file's R is orthonormal
    return U @ Vt

views = []  # (file, K, R world-to-camera, t, size from the source or None)
if set_name == "strecha":
    images = os.path.join(root, scene, "images")
    cams = os.path.join(root, scene, "gt_dense_cameras")
    if not os.path.isdir(images) or not os.path.isdir(cams):
        fail(f"no {scene}/images or {scene}/gt_dense_cameras in the source")
    for f in sorted(os.listdir(cams)):
        if not f.endswith(".camera"):
            continue
        path = os.path.join(cams, f)
        v = numbers(path, open(path).read().split())
        if len(v) != 26:
            fail(f"{path}: {len(v)} numbers, expected 26 (K, distortion, R, C, width height)")
        K = np.array(v[0:9]).reshape(3, 3)
        if any(v[9:12]):
            fail(f"{path}: non-zero distortion {v[9:12]}; only undistorted images are supported")
        Rc = rotation(v[12:21], path)  # camera to world
        C = np.array(v[21:24])
        views.append((f[: -len(".camera")], K, Rc.T, -Rc.T @ C, (int(v[24]), int(v[25]))))
    terms = ("No licence file in the repository. Its Readme.txt credits C. Strecha, W. von Hansen,\n"
             "L. Van Gool, P. Fua, U. Thoennessen, \"On Benchmarking Camera Calibration and\n"
             "Multi-View Stereo for High Resolution Imagery\", CVPR 2008, and the EPFL CVLab page\n"
             "http://cvlabwww.epfl.ch/data/multiview/ (the original distribution; openMVG's copy\n"
             "re-encodes its PNGs as JPEG). Use for research and cite the paper.")
    distortion = "the *.camera files give zero distortion: the images are undistorted"
else:
    prefix = {"middlebury-temple": "templeR", "middlebury-dino": "dinoSR"}[set_name]
    path = os.path.join(root, prefix + "_par.txt")
    if not os.path.isfile(path):
        fail(f"no {os.path.basename(path)} in the source")
    lines = [l.split() for l in open(path) if l.strip()]
    count = int(lines[0][0]) if len(lines[0]) == 1 else None
    lines = lines[1:] if count is not None else lines
    if count is not None and count != len(lines):
        fail(f"{path} announces {count} images and lists {len(lines)}")
    for tok in lines:
        if len(tok) != 22:
            fail(f"{path}: a line has {len(tok)} fields, expected 22 (name K R t)")
        v = numbers(path, tok[1:])
        views.append((tok[0], np.array(v[0:9]).reshape(3, 3), rotation(v[9:18], tok[0]),
                      np.array(v[18:21]), None))
    images = root
    terms = ("No licence file in the repository; its README.txt is Middlebury's: created by Steve\n"
             "Seitz, James Diebel, Daniel Scharstein, Brian Curless and Rick Szeliski, from\n"
             "https://vision.middlebury.edu/mview/data/. Cite S. M. Seitz, B. Curless, J. Diebel,\n"
             "D. Scharstein, R. Szeliski, \"A Comparison and Evaluation of Multi-View Stereo\n"
             "Reconstruction Algorithms\", CVPR 2006. Use for research.")
    distortion = "the source's camera model is K [R | t], without distortion"

if len(views) < 2:
    fail("fewer than two cameras in the source")
os.makedirs(os.path.join(out, "images"))
rows = []
sizes = set()
rotated = []
for name, K, R, t, size in views:
    if abs(K[0, 1]) > 1e-9 or np.abs(K[2] - [0, 0, 1]).max() > 1e-9 or abs(K[1, 0]) > 1e-9:
        fail(f"{name}: K has skew or is not upper triangular with K33 = 1")
    src_img = os.path.join(images, name)
    if not os.path.isfile(src_img):
        fail(f"{name}: no image file {src_img}")
    img = cv2.imread(src_img, cv2.IMREAD_UNCHANGED)
    if img is None:
        fail(f"{src_img}: cv2 cannot read it")
    h, w = img.shape[:2]
    turned = set_name.startswith("middlebury") and (w, h) == (480, 640)
    if turned:
        # Middlebury's images are 640x480, a quarter of them upside down (README.txt); this copy
        # turned each a quarter turn so that the object stands upright, world +y up. Turn it back
        # to where the camera puts world +y: image direction (R01, R11), +x or -x.
        up = R[0:2, 1]
        if abs(up[0]) < 0.9:
            fail(f"{name}: portrait copy, and the camera puts world +y at {up}, not along x")
        clockwise = up[0] > 0
        img = cv2.rotate(img, cv2.ROTATE_90_CLOCKWISE if clockwise else cv2.ROTATE_90_COUNTERCLOCKWISE)
        h, w = img.shape[:2]
        rotated.append("clockwise" if clockwise else "counter-clockwise")
    if size is not None and size != (w, h):
        fail(f"{name}: the camera file says {size[0]}x{size[1]}, the image is {w}x{h}")
    fx, fy, cx, cy = K[0, 0], K[1, 1], K[0, 2], K[1, 2]
    dst = os.path.join(out, "images", name)
    if max_side and max(w, h) > max_side:
        s = max_side / max(w, h)
        w2, h2 = round(w * s), round(h * s)
        sx, sy = w2 / w, h2 / h
        small = cv2.resize(img, (w2, h2), interpolation=cv2.INTER_AREA)
        params = [cv2.IMWRITE_JPEG_QUALITY, 95] if name.lower().endswith((".jpg", ".jpeg")) else []
        if not cv2.imwrite(dst, small, params):
            fail(f"cannot write {dst}")
        fx, fy, cx, cy = fx * sx, fy * sy, (cx + 0.5) * sx - 0.5, (cy + 0.5) * sy - 0.5
        w, h = w2, h2
    elif turned:
        if not cv2.imwrite(dst, img):
            fail(f"cannot write {dst}")
    else:
        shutil.copyfile(src_img, dst)
    sizes.add((w, h))
    fields = [name, str(w), str(h)] + ["%.10g" % x for x in (fx, fy, cx, cy)]
    fields += ["%.12g" % x for x in R.reshape(-1)] + ["%.12g" % x for x in t]
    rows.append(" ".join(fields))
    print(f"{me}: [{set_name}] {scene}: {name} {w}x{h}", flush=True)

resized = "originals" if not max_side else f"resized to a longer side of at most {max_side} px"
with open(os.path.join(out, "cameras.txt"), "w") as f:
    f.write(f"# opencv_essential real scene {scene} (set {set_name}), {len(rows)} images, "
            f"{resized}\n"
            "# name width height fx fy cx cy r11 r12 r13 r21 r22 r23 r31 r32 r33 t1 t2 t3\n"
            "# x_cam = R X_world + t; pixel = (fx x/z + cx, fy y/z + cy), origin top-left, pixel\n"
            "# centres at integer coordinates; no skew, no distortion (" + distortion + ")\n")
    f.write("\n".join(rows) + "\n")
with open(os.path.join(out, "SOURCE.txt"), "w") as f:
    f.write(f"scene: {scene}\nset: {set_name}\nrepository: {public_url}\nread from: {src}\n"
            f"commit: {commit}\nimages: {len(rows)}\n"
            f"sizes: {', '.join(f'{w}x{h}' for w, h in sorted(sizes))}\nmax_side: {max_side}\n"
            f"distortion: {distortion}\n")
    if rotated:
        cw = rotated.count("clockwise")
        f.write(f"turned: the source's {len(rotated)} images are 480x640, turned so that the object\n"
                "stands upright; each was turned back (losslessly) to the 640x480 original that the\n"
                f"camera describes, world +y along image +x or -x: {cw} clockwise,\n"
                f"{len(rotated) - cw} counter-clockwise\n")
    f.write(f"terms:\n{terms}\n")
PY
        rm -rf "${dest:?}/$scene"
        mv "$partial" "$dest/$scene"
        echo "$me: [$s] $scene: $(grep -vc '^#' "$dest/$scene/cameras.txt") images laid out in" \
            "$dest/$scene"
    done
done
echo "$me: done"

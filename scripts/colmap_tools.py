#!/usr/bin/python3
# This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
"""Helpers of the COLMAP experiment (scripts/experiment_colmap.sh) and of the ctest chain
(test/colmap): export a database's raw matches for `colmap matches_importer --match_type raw`, and
compare sparse reconstructions (registered images, points, track length, reprojection error from
`colmap model_analyzer`; camera poses against rail-a ground truth after a similarity alignment),
optionally plotting the camera paths.

  colmap_tools.py export-matches DB.db OUT.txt
  colmap_tools.py agreement A.db B.db
  colmap_tools.py compare --model NAME=SPARSE_DIR [--model ...] [--truth poses.txt]
                  [--json OUT.json] [--plot OUT.png] [--title T]
                  [--require-registered N] [--max-rotation-deg D] [--max-position P]

`compare` exits 1 when a --require-*/--max-* bound is broken (the ctest chain uses them), 0 otherwise.
"""
import argparse
import json
import os
import re
import sqlite3
import subprocess
import sys
import tempfile

import numpy as np

MAX_IMAGE_ID = 2147483647


def export_matches(db_path, out_path):
    """Writes COLMAP's raw match list: a line 'name1 name2', one line 'i j' per match, a blank
    line; every pair of the matches table with at least one match."""
    db = sqlite3.connect(db_path)
    names = dict(db.execute("SELECT image_id, name FROM images"))
    pairs = 0
    with open(out_path, "w") as out:
        for pair_id, rows, cols, data in db.execute(
                "SELECT pair_id, rows, cols, data FROM matches ORDER BY pair_id"):
            if not rows:
                continue
            matches = np.frombuffer(data, np.uint32).reshape(rows, cols)
            out.write("%s %s\n" % (names[pair_id // MAX_IMAGE_ID], names[pair_id % MAX_IMAGE_ID]))
            out.write("\n".join("%d %d" % (a, b) for a, b in matches))
            out.write("\n\n")
            pairs += 1
    print("exported %d pairs to %s" % (pairs, out_path))


CONFIG_NAMES = {1: "DEGENERATE", 2: "CALIBRATED", 3: "UNCALIBRATED", 4: "PLANAR", 5: "PANORAMIC",
                6: "PLANAR_OR_PANORAMIC", 7: "WATERMARK", 8: "MULTIPLE"}


def agreement(db_a, db_b):
    """How two verifications of the same matches agree: configs of each, and per pair the overlap
    of the inlier sets (common / larger set)."""
    def load(path):
        db = sqlite3.connect(path)
        return {pid: (config, set(map(tuple, np.frombuffer(data, np.uint32).reshape(rows, 2)))
                      if rows else set())
                for pid, rows, data, config in db.execute(
                    "SELECT pair_id, rows, data, config FROM two_view_geometries")}
    a, b = load(db_a), load(db_b)
    for name, rows in (("A", a), ("B", b)):
        counts = {}
        for config, _ in rows.values():
            counts[CONFIG_NAMES.get(config, config)] = counts.get(CONFIG_NAMES.get(config, config),
                                                                  0) + 1
        print("%s %s: %s; %d inlier matches" % (name, (db_a, db_b)[name == "B"], counts,
                                               sum(len(m) for _, m in rows.values())))
    common = sorted(set(a) & set(b))
    overlap = np.array([len(a[p][1] & b[p][1]) / max(1, len(a[p][1]), len(b[p][1]))
                        for p in common])
    print("%d pairs in both; inlier overlap: median %.4f, 5th percentile %.4f, minimum %.4f; "
          "pairs above 0.95: %d" % (len(common), np.median(overlap), np.percentile(overlap, 5),
                                    overlap.min(), int(np.sum(overlap > 0.95))))


def quaternion_to_matrix(q):
    w, x, y, z = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def read_model(sparse_dir):
    """Statistics (model_analyzer) and poses {frame name: (R world-to-camera, centre)}."""
    analyzer = subprocess.run(["colmap", "model_analyzer", "--path", sparse_dir],
                              capture_output=True, text=True, check=True)
    text = analyzer.stdout + analyzer.stderr
    stats = {}
    for key, label in [("registered", "Registered images"), ("points", "Points"),
                       ("observations", "Observations"), ("track_length", "Mean track length"),
                       ("reprojection_px", "Mean reprojection error")]:
        m = re.search(label + r":\s*([0-9.eE+-]+)", text)
        stats[key] = float(m.group(1)) if m else None
    poses = {}
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run(["colmap", "model_converter", "--input_path", sparse_dir, "--output_path",
                        tmp, "--output_type", "TXT"], capture_output=True, check=True)
        with open(os.path.join(tmp, "images.txt")) as f:
            lines = [l for l in f if not l.startswith("#")]
        for line in lines[0::2]:  # image lines alternate with their 2D point lines
            v = line.split()
            if len(v) < 10:
                continue
            R = quaternion_to_matrix(np.array([float(x) for x in v[1:5]]))
            t = np.array([float(x) for x in v[5:8]])
            poses[v[9]] = (R, -R.T @ t)
    return stats, poses


def read_truth(path):
    """rail-a poses.txt: 'k r00..r22 Cx Cy Cz' per frame -> {k: (R world-to-camera, centre)}."""
    truth = {}
    for line in open(path):
        v = line.split()
        if len(v) == 13:
            truth[int(v[0])] = (np.array([float(x) for x in v[1:10]]).reshape(3, 3),
                                np.array([float(x) for x in v[10:13]]))
    return truth


def project_to_rotation(M):
    U, _, Vt = np.linalg.svd(M)
    D = np.diag([1, 1, np.sign(np.linalg.det(U @ Vt))])
    return U @ D @ Vt


def rotation_angle_deg(R):
    return np.degrees(np.arccos(np.clip((np.trace(R) - 1) / 2, -1, 1)))


def align_to_truth(poses, truth):
    """Similarity X_true = s A X_est + b. rail-a's centres lie on a line, which fixes a similarity
    only up to a rotation about the line, so A is the rotation that best maps the estimated camera
    orientations onto the true ones (chordal mean of R_true_i^T R_est_i), then s and b are the
    least-squares fit of the centres given A. Returns per-frame rotation errors (degrees) and
    position errors (scene units), and the aligned centres."""
    frames = sorted(k for k in (int(os.path.splitext(n)[0]) for n in poses) if k in truth)
    names = {int(os.path.splitext(n)[0]): n for n in poses}
    # R_est = R_true A  (world_est -> camera = world_true -> camera after world_est -> world_true)
    A = project_to_rotation(sum(truth[k][0].T @ poses[names[k]][0] for k in frames))
    est = np.array([A @ poses[names[k]][1] for k in frames])
    tru = np.array([truth[k][1] for k in frames])
    ec, tc = est - est.mean(0), tru - tru.mean(0)
    s = float(np.sum(ec * tc) / np.sum(ec * ec))
    aligned = s * ec + tru.mean(0)
    position = np.linalg.norm(aligned - tru, axis=1)
    rotation = np.array([rotation_angle_deg(truth[k][0] @ A @ poses[names[k]][0].T)
                         for k in frames])
    return frames, rotation, position, aligned


def relative_pose(poses):
    """R, unit t of the second image (by name) from the first: X2 = R X1 + t."""
    (R1, C1), (R2, C2) = (poses[n] for n in sorted(poses)[:2])
    t = -R2 @ (C2 - C1)
    return R2 @ R1.T, t / np.linalg.norm(t)


def plot_paths(truth, paths, out_png, title):
    """Camera centres after alignment, as offsets from the true centre of the same frame: along
    the rail, and across it in two perpendicular directions (truth: the zero line), against the
    distance travelled along the rail."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    frames = sorted(truth)
    start = truth[frames[0]][1]
    rail = truth[frames[-1]][1] - start
    rail /= np.linalg.norm(rail)
    # Two directions across the rail: world z (or x) made orthogonal to it, then their cross product.
    up = np.array([0.0, 0.0, 1.0]) if abs(rail[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
    across1 = up - rail * (up @ rail)
    across1 /= np.linalg.norm(across1)
    across2 = np.cross(rail, across1)
    axes = [(rail, "along the rail"), (across1, "across the rail (up)"),
            (across2, "across the rail (sideways)")]
    fig, ax = plt.subplots(1, 3, figsize=(14, 4))
    travel = [(truth[k][1] - start) @ rail for k in frames]
    for j, (direction, label) in enumerate(axes):
        ax[j].plot(travel, np.zeros(len(travel)), "k-", lw=3, alpha=0.3, label="truth")
        for (name, (est_frames, aligned)), style in zip(paths.items(), ["o", "x", "+", "s"]):
            along = [(truth[k][1] - start) @ rail for k in est_frames]
            offsets = [(c - truth[k][1]) @ direction for k, c in zip(est_frames, aligned)]
            ax[j].plot(along, offsets, style, ms=5, label=name)
        ax[j].set_xlabel("distance along the rail (scene units)")
        ax[j].set_ylabel("offset %s" % label)
        ax[j].grid(True, alpha=0.3)
    ax[0].legend()
    fig.suptitle(title or "camera centres after similarity alignment, offsets from the truth")
    fig.tight_layout()
    fig.savefig(out_png, dpi=100)


def compare(args):
    truth = read_truth(args.truth) if args.truth else None
    results, paths = {}, {}
    first_relative = None
    for spec in args.model:
        name, sparse = spec.split("=", 1)
        if not os.path.isdir(sparse):
            results[name] = {"registered": 0, "error": "no reconstruction at " + sparse}
            continue
        stats, poses = read_model(sparse)
        if truth:
            frames, rot, pos, aligned = align_to_truth(poses, truth)
            travel = np.linalg.norm(truth[max(truth)][1] - truth[min(truth)][1])
            stats.update(rotation_error_deg_mean=float(rot.mean()),
                         rotation_error_deg_max=float(rot.max()),
                         position_error_mean=float(pos.mean()),
                         position_error_max=float(pos.max()),
                         position_error_max_of_travel=float(pos.max() / travel))
            paths[name] = (frames, aligned)
        elif len(poses) >= 2:
            # No truth: the relative pose of the first two images against the first model's.
            R, t = relative_pose(poses)
            if first_relative is None:
                first_relative = (R, t)
            stats.update(relative_rotation_deg_vs_first=float(
                rotation_angle_deg(R @ first_relative[0].T)),
                relative_direction_deg_vs_first=float(np.degrees(np.arccos(
                    np.clip(t @ first_relative[1], -1, 1)))))
        results[name] = stats
    keys = ["registered", "points", "track_length", "reprojection_px"]
    if not truth and first_relative is not None:
        keys += ["relative_rotation_deg_vs_first", "relative_direction_deg_vs_first"]
    if truth:
        keys += ["rotation_error_deg_mean", "rotation_error_deg_max", "position_error_mean",
                 "position_error_max"]
    print("| model | " + " | ".join(keys) + " |")
    print("|---" * (len(keys) + 1) + "|")
    for name, stats in results.items():
        cells = []
        for k in keys:
            v = stats.get(k)
            cells.append("-" if v is None else ("%d" % v if k in ("registered", "points")
                                                 else "%.4g" % v))
        print("| %s | %s |" % (name, " | ".join(cells)))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=2)
    if args.plot and truth:
        plot_paths(truth, paths, args.plot, args.title)
    failed = []
    for name, stats in results.items():
        if args.require_registered is not None and (stats.get("registered") or 0) < \
                args.require_registered:
            failed.append("%s: %s images registered, %d required" %
                          (name, stats.get("registered"), args.require_registered))
        if args.max_rotation_deg is not None and not (
                stats.get("rotation_error_deg_max", np.inf) <= args.max_rotation_deg):
            failed.append("%s: rotation error %s deg > %g" %
                          (name, stats.get("rotation_error_deg_max"), args.max_rotation_deg))
        if args.max_position is not None and not (
                stats.get("position_error_max", np.inf) <= args.max_position):
            failed.append("%s: position error %s > %g" %
                          (name, stats.get("position_error_max"), args.max_position))
    for f in failed:
        print("FAILED " + f)
    return 1 if failed else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    a = sub.add_parser("agreement")
    a.add_argument("database_a")
    a.add_argument("database_b")
    e = sub.add_parser("export-matches")
    e.add_argument("database")
    e.add_argument("output")
    c = sub.add_parser("compare")
    c.add_argument("--model", action="append", required=True)
    c.add_argument("--truth")
    c.add_argument("--json")
    c.add_argument("--plot")
    c.add_argument("--title")
    c.add_argument("--require-registered", type=int)
    c.add_argument("--max-rotation-deg", type=float)
    c.add_argument("--max-position", type=float)
    args = parser.parse_args()
    if args.command == "agreement":
        agreement(args.database_a, args.database_b)
        return 0
    if args.command == "export-matches":
        export_matches(args.database, args.output)
        return 0
    return compare(args)


if __name__ == "__main__":
    sys.exit(main())

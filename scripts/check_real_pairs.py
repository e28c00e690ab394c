#!/usr/bin/env python3
# Checks the ground truth that scripts/fetch_real_pairs.sh laid out: on a few pairs of each scene,
# SIFT matches (cv2.SIFT_create, Lowe's ratio test at 0.8) are scored by their Sampson distance in
# pixels under the essential matrix of the cameras, E = [t]x R with x_b = R x_a + t, F = Kb^-T E
# Ka^-1. With right cameras most matches (all but the false ones) lie within 1 px; as a control,
# the same matches are scored under the E of another pair of the scene (wrong cameras).
#
#   /usr/bin/python3 scripts/check_real_pairs.py [--pairs N] [--scenes A,B] [DEST]
#
# DEST defaults to ${XDG_CACHE_HOME:-$HOME/.cache}/opencv_essential/real. The pairs of a scene are
# (0,1), (0,2), (1,2), (1,3), ...: the first N (default 3) pairs one or two apart in file order.
# Prints one line per pair: the relative rotation (degrees), the matches, the fraction within 1 px
# under the ground truth and under the control. Needs numpy and cv2.
# Licensed under the Apache License, Version 2.0.
import argparse
import os
import sys

import cv2
import numpy as np


def read_scene(d):
    views = []
    for line in open(os.path.join(d, "cameras.txt")):
        if line.startswith("#") or not line.strip():
            continue
        f = line.split()
        if len(f) != 19:
            sys.exit(f"{d}/cameras.txt: a line has {len(f)} fields, expected 19")
        v = [float(x) for x in f[1:]]
        K = np.array([[v[2], 0, v[4]], [0, v[3], v[5]], [0, 0, 1]])
        views.append((f[0], K, np.array(v[6:15]).reshape(3, 3), np.array(v[15:18])))
    return views


def relative(a, b):
    R = b[2] @ a[2].T
    t = b[3] - R @ a[3]
    return R, t / np.linalg.norm(t)


def skew(t):
    return np.array([[0, -t[2], t[1]], [t[2], 0, -t[0]], [-t[1], t[0], 0]])


def sampson_px(F, p1, p2):
    x1 = np.c_[p1, np.ones(len(p1))]
    x2 = np.c_[p2, np.ones(len(p2))]
    Fx1 = x1 @ F.T
    Ftx2 = x2 @ F
    num = np.sum(x2 * Fx1, axis=1) ** 2
    den = Fx1[:, 0] ** 2 + Fx1[:, 1] ** 2 + Ftx2[:, 0] ** 2 + Ftx2[:, 1] ** 2
    return np.sqrt(num / den)


def matches(img1, img2, sift):
    k1, d1 = sift.detectAndCompute(img1, None)
    k2, d2 = sift.detectAndCompute(img2, None)
    if d1 is None or d2 is None or len(k1) < 2 or len(k2) < 2:
        return np.zeros((0, 2)), np.zeros((0, 2))
    knn = cv2.BFMatcher(cv2.NORM_L2).knnMatch(d1, d2, k=2)
    good = [m for m, n in (p for p in knn if len(p) == 2) if m.distance < 0.8 * n.distance]
    p1 = np.float64([k1[m.queryIdx].pt for m in good]).reshape(-1, 2)
    p2 = np.float64([k2[m.trainIdx].pt for m in good]).reshape(-1, 2)
    return p1, p2


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("dest", nargs="?", default=os.path.join(
        os.environ.get("XDG_CACHE_HOME", os.path.expanduser("~/.cache")), "opencv_essential/real"))
    ap.add_argument("--pairs", type=int, default=3)
    ap.add_argument("--scenes", default="")
    args = ap.parse_args()
    names = sorted(s for s in os.listdir(args.dest)
                   if os.path.isfile(os.path.join(args.dest, s, "cameras.txt")))
    if args.scenes:
        names = [s for s in names if s in args.scenes.split(",")]
    sift = cv2.SIFT_create()
    print("scene pair rotation_deg matches within_1px_gt within_1px_control")
    for s in names:
        d = os.path.join(args.dest, s)
        views = read_scene(d)
        pairs = [(i // 2, i // 2 + 1 + i % 2) for i in range(args.pairs)]
        for i, j in pairs:
            if j >= len(views):
                continue
            a, b = views[i], views[j]
            R, t = relative(a, b)
            # control: the cameras of the pair two further on (another motion of the same scene)
            k, m = (i + 2) % len(views), (j + 3) % len(views)
            Rc, tc = relative(views[k], views[m])
            img1 = cv2.imread(os.path.join(d, "images", a[0]), cv2.IMREAD_GRAYSCALE)
            img2 = cv2.imread(os.path.join(d, "images", b[0]), cv2.IMREAD_GRAYSCALE)
            p1, p2 = matches(img1, img2, sift)
            angle = np.degrees(np.arccos(np.clip((np.trace(R) - 1) / 2, -1, 1)))
            if len(p1) == 0:
                print(f"{s} {a[0]}-{b[0]} {angle:.1f} 0 - -")
                continue
            Ka_inv, Kb_inv = np.linalg.inv(a[1]), np.linalg.inv(b[1])
            fr = []
            for RR, tt in ((R, t), (Rc, tc)):
                F = Kb_inv.T @ skew(tt) @ RR @ Ka_inv
                fr.append(np.mean(sampson_px(F, p1, p2) < 1.0))
            print(f"{s} {a[0]}-{b[0]} {angle:.1f} {len(p1)} {fr[0]:.3f} {fr[1]:.3f}", flush=True)


if __name__ == "__main__":
    main()

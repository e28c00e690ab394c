#!/usr/bin/python3
# This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
# See the LICENSE file at the top of the source tree.
"""The Leuven pair with cv2's ORB and matching: cv_essential.findEssentialMatIter next to
cv2.findEssentialMat on the same matches, and a figure of the inliers and a few epipolar lines.

  PYTHONPATH=build/python /usr/bin/python3 samples/python/essential_pair.py [--out pair.png]
"""
import argparse
import pathlib
import time

import cv2
import numpy as np

import cv_essential

DATA = pathlib.Path(__file__).resolve().parents[2] / "data" / "pairs"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--image1", default=str(DATA / "leuvenA.jpg"))
    parser.add_argument("--image2", default=str(DATA / "leuvenB.jpg"))
    parser.add_argument("--camera", default=str(DATA / "leuven.camera"),
                        help="a file 'fx fy cx cy [width height]'")
    parser.add_argument("--out", help="write the figure (PNG) here")
    args = parser.parse_args()

    fx, fy, cx, cy = [float(v) for v in open(args.camera).read().split()[:4]]
    K = np.array([[fx, 0, cx], [0, fy, cy], [0, 0, 1]])
    img1 = cv2.imread(args.image1, cv2.IMREAD_GRAYSCALE)
    img2 = cv2.imread(args.image2, cv2.IMREAD_GRAYSCALE)
    if img1 is None or img2 is None:
        raise SystemExit("cannot read the images")
    orb = cv2.ORB_create(4000)
    k1, d1 = orb.detectAndCompute(img1, None)
    k2, d2 = orb.detectAndCompute(img2, None)
    matches = cv2.BFMatcher(cv2.NORM_HAMMING, crossCheck=True).match(d1, d2)
    p1 = np.float64([k1[m.queryIdx].pt for m in matches])
    p2 = np.float64([k2[m.trainIdx].pt for m in matches])
    print(f"{len(k1)} / {len(k2)} ORB features, {len(matches)} cross-checked matches")

    t0 = time.perf_counter()
    E, mask = cv_essential.findEssentialMatIter(p1, p2, K, cv2.RANSAC, 0.999, 1.0)
    ours_ms = 1000 * (time.perf_counter() - t0)
    n, R, t, _ = cv_essential.recoverPose(E, p1, p2, K, mask=mask.copy())
    t0 = time.perf_counter()
    Ecv, maskcv = cv2.findEssentialMat(p1, p2, K, cv2.RANSAC, 0.999, 1.0)
    cv_ms = 1000 * (time.perf_counter() - t0)
    ncv, Rcv, tcv, _ = cv2.recoverPose(Ecv, p1, p2, K, mask=maskcv.copy())
    angle = np.degrees(np.arccos(np.clip((np.trace(R @ Rcv.T) - 1) / 2, -1, 1)))
    tangle = np.degrees(np.arccos(np.clip(float(t.ravel() @ tcv.ravel()), -1, 1)))
    print(f"cv_essential: {int(mask.sum())} inliers, {ours_ms:.1f} ms")
    print(f"cv2:          {int(maskcv.sum())} inliers, {cv_ms:.1f} ms")
    print(f"poses differ by {angle:.2f} deg (rotation), {tangle:.2f} deg (translation direction)")

    if args.out:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        inl = mask.ravel().astype(bool)
        fig, ax = plt.subplots(1, 2, figsize=(14, 5))
        ax[0].imshow(img1, cmap="gray")
        ax[1].imshow(img2, cmap="gray")
        ax[0].plot(p1[~inl, 0], p1[~inl, 1], "r.", ms=2, label="outliers")
        ax[0].plot(p1[inl, 0], p1[inl, 1], "g.", ms=3, label="inliers")
        ax[1].plot(p2[inl, 0], p2[inl, 1], "g.", ms=3)
        F = np.linalg.inv(K).T @ E @ np.linalg.inv(K)
        w = img2.shape[1]
        for i in np.flatnonzero(inl)[:: max(1, inl.sum() // 8)][:8]:
            a, b, c = F @ np.append(p1[i], 1.0)  # epipolar line in image 2
            ax[1].plot([0, w], [-c / b, -(c + a * w) / b], lw=0.8)
        ax[1].set_xlim(0, w)
        ax[1].set_ylim(img2.shape[0], 0)  # the lines extend beyond the image: keep its frame
        for a_ in ax:
            a_.set_axis_off()
        ax[0].legend(loc="lower right")
        ax[0].set_title(f"cv_essential: {inl.sum()} of {len(inl)} matches are inliers")
        ax[1].set_title("epipolar lines of 8 inliers")
        fig.tight_layout()
        fig.savefig(args.out, dpi=100)
        print(f"figure: {args.out}")


if __name__ == "__main__":
    main()

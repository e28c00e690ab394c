#!/usr/bin/python3
# This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
# See the LICENSE file at the top of the source tree.
"""The Python binding's cost and speed: thread CPU time per call of cv_essential.findEssentialMatIter
against cv2.findEssentialMat (the same points, interleaved), the binding's overhead against the C++
call (EssentialReport.timeTotalMs, the library's own clock), and findEssentialMatBatch's pairs per
second at 1 and 2 threads against a Python loop over cv2.findEssentialMat.

  PYTHONPATH=build/python /usr/bin/python3 bench/python/bench_cv_essential.py [--problems 100]
"""
import argparse
import statistics
import time

import cv2
import numpy as np

import cv_essential


def scene(n, ratio, rng):
    K = np.array([[500.0, 0, 320], [0, 500, 240], [0, 0, 1]])
    X = np.column_stack([rng.uniform(-2, 2, n), rng.uniform(-2, 2, n), rng.uniform(4, 12, n)])
    angle = rng.uniform(0.0, 0.3)
    c, s = np.cos(angle), np.sin(angle)
    R = np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    t = rng.normal(size=3)
    t /= np.linalg.norm(t)
    x1 = X @ K.T
    x2 = (X @ R.T + t) @ K.T
    p1 = x1[:, :2] / x1[:, 2:] + rng.normal(0, 0.5, (n, 2))
    p2 = x2[:, :2] / x2[:, 2:] + rng.normal(0, 0.5, (n, 2))
    bad = rng.random(n) > ratio
    p2[bad] = rng.uniform([0, 0], [640, 480], (int(bad.sum()), 2))
    return p1, p2, K


def cpu_ms(f):
    t0 = time.thread_time()
    out = f()
    return 1000.0 * (time.thread_time() - t0), out


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--problems", type=int, default=100)
    parser.add_argument("--points", type=int, default=500)
    args = parser.parse_args()
    rng = np.random.default_rng(1)
    print(f"N = {args.points}, {args.problems} problems per ratio, thread CPU time, medians")
    print("| inliers | cv_essential ms | cv2 ms | cv2 / ours | binding overhead |")
    print("|---|---|---|---|---|")
    for ratio in (0.9, 0.5):
        ours, theirs, overhead = [], [], []
        for _ in range(args.problems):
            p1, p2, K = scene(args.points, ratio, rng)
            params = cv_essential.EssentialParams()
            t, (_, _, report) = cpu_ms(lambda: cv_essential.findEssentialMatIter(p1, p2, K, params))
            ours.append(t)
            overhead.append(t - report.timeTotalMs)
            t, _ = cpu_ms(lambda: cv2.findEssentialMat(p1, p2, K))
            theirs.append(t)
        mo, mt, oh = statistics.median(ours), statistics.median(theirs), statistics.median(overhead)
        print(f"| {ratio:.0%} | {mo:.3f} | {mt:.3f} | {mt / mo:.1f}x | {oh * 1000:.0f} us "
              f"({100 * oh / mo:.1f}%) |")

    pairs = [scene(args.points, 0.5, rng) for _ in range(4 * args.problems)]
    print(f"\nbatch of {len(pairs)} pairs (50% inliers), wall time")
    print("| method | pairs / s |")
    print("|---|---|")
    t0 = time.perf_counter()
    for p1, p2, K in pairs:
        cv2.findEssentialMat(p1, p2, K)
    loop = len(pairs) / (time.perf_counter() - t0)
    print(f"| Python loop over cv2.findEssentialMat | {loop:.0f} |")
    for threads in (1, 2):
        t0 = time.perf_counter()
        cv_essential.findEssentialMatBatch(pairs, threads=threads)
        rate = len(pairs) / (time.perf_counter() - t0)
        print(f"| cv_essential.findEssentialMatBatch, {threads} thread(s) | {rate:.0f} |")


if __name__ == "__main__":
    main()

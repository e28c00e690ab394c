#!/usr/bin/python3
# This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
# See the LICENSE file at the top of the source tree.
"""The Python binding's cost and speed: thread CPU time per call of cv_essential.findEssentialMatIter
against cv2.findEssentialMat (the same points, interleaved), the binding's overhead (the Python
call's thread CPU time minus the C++ call's, both on CLOCK_THREAD_CPUTIME_ID: the C++ call is timed
inside the module by the private hook _forms.nativeCallMs), and findEssentialMatBatch's pairs per
second at 1 and 2 threads against a Python loop over cv2.findEssentialMat.

  PYTHONPATH=build/python /usr/bin/python3 bench/python/bench_cv_essential.py [--problems 100]
"""
import argparse
import pathlib
import statistics
import sys
import time

import cv2
import numpy as np

import cv_essential

# The scenes of the Python examples (samples/python/synthetic_scene.py).
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "samples" / "python"))
from synthetic_scene import synthetic_pair  # noqa: E402


def cpu_ms(f):
    t0 = time.thread_time()
    out = f()
    return 1000.0 * (time.thread_time() - t0), out


def paired_call(p1, p2, K, params, native_first):
    """(ms through Python, ms of the same call in C++): the params form called from Python, and
    timed inside the module around the library call alone (the private hook
    _forms.nativeCallMs), both on the thread CPU clock, in the given order."""
    native = cv_essential._forms.nativeCallMs
    if native_first:
        c = native(p1, p2, K, params)
        py = cpu_ms(lambda: cv_essential.findEssentialMatIter(p1, p2, K, params))[0]
    else:
        py = cpu_ms(lambda: cv_essential.findEssentialMatIter(p1, p2, K, params))[0]
        c = native(p1, p2, K, params)
    return py, c


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--problems", type=int, default=100)
    parser.add_argument("--points", type=int, default=500)
    parser.add_argument("--rounds", type=int, default=6, help="interleaved calls per problem")
    args = parser.parse_args()
    rng = np.random.default_rng(1)
    print(f"N = {args.points}, {args.problems} problems per ratio, thread CPU time, medians")
    print("| inliers | cv_essential ms | cv2 ms | cv2 / ours | C++ call (params form) ms | binding overhead |")
    print("|---|---|---|---|---|---|")
    for ratio in (0.9, 0.5):
        problems = [synthetic_pair(args.points, ratio, rng) for _ in range(args.problems)]
        params = cv_essential.EssentialParams()
        # Speed against cv2: the drop-in form and cv2.findEssentialMat interleaved, per problem
        # the median of the rounds.
        ours, theirs = [], []
        for p1, p2, K in problems:
            o, t = [], []
            for _ in range(args.rounds):
                o.append(cpu_ms(lambda: cv_essential.findEssentialMatIter(p1, p2, K))[0])
                t.append(cpu_ms(lambda: cv2.findEssentialMat(p1, p2, K))[0])
            ours.append(statistics.median(o))
            theirs.append(statistics.median(t))
        # The binding's overhead: the params form through Python and the same call in C++
        # (nativeCallMs), paired, their order alternating, every call the same work (same seed).
        # A loop of its own: cv2's calls in between (their worker threads spinning on the other
        # core) slowed whichever call came next and blurred the pairs.
        native, overhead = [], []
        for p1, p2, K in problems:
            for r in range(args.rounds):
                py, c = paired_call(p1, p2, K, params, native_first=r % 2 == 1)
                native.append(c)
                overhead.append(py - c)
        mo, mt, mn = statistics.median(ours), statistics.median(theirs), statistics.median(native)
        oh = statistics.median(overhead)
        print(f"| {ratio:.0%} | {mo:.3f} | {mt:.3f} | {mt / mo:.1f}x | {mn:.3f} | "
              f"{oh * 1000:.1f} us ({100 * oh / mn:.1f}%) |")

    # The fixed cost of a call, where the library does almost nothing (one sample, no refinement,
    # no pose): paired differences over many calls.
    p1, p2, K = synthetic_pair(args.points, 0.9, rng)
    tiny = cv_essential.EssentialParams(maxIterations=1, sampleBudget=cv_essential.BUDGET_CONFIDENCE,
                                        refine=False, recoverPose=False, planeParallax=False)
    fixed = []
    for r in range(20 * args.problems):
        py, c = paired_call(p1, p2, K, tiny, native_first=r % 2 == 1)
        fixed.append(py - c)
    print(f"\nfixed cost of a call (one sample, no refinement, {len(fixed)} paired calls): "
          f"{statistics.median(fixed) * 1000:.1f} us")

    pairs = [synthetic_pair(args.points, 0.5, rng) for _ in range(4 * args.problems)]
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

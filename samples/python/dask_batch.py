#!/usr/bin/python3
# This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
# See the LICENSE file at the top of the source tree.
"""Many image pairs on many machines: cv_essential.findEssentialMatBatch mapped over partitions of
pairs on a dask.distributed cluster.

Each partition is a list of (points1, points2, cameraMatrix) with its index range; a worker runs the
batch on its threads and returns the essential matrices and inlier counts. The seed of pair i is
batchPairSeed(seed, i) with i the pair's global index, so the result does not depend on how the
pairs are partitioned or where they run: estimate_on_cluster(...) equals estimate_locally(...).

  /usr/bin/python3 samples/python/dask_batch.py                    # a LocalCluster of 2 workers
  /usr/bin/python3 samples/python/dask_batch.py --scheduler tcp://host:8786   # a real cluster

On a real cluster every worker needs cv_essential importable (the package installed, or
PYTHONPATH pointing at it) and the same OpenCV.
"""
import argparse
import pathlib
import sys

import numpy as np

import cv_essential

# The scene generator beside this file (also when the file is loaded by path, as its test does).
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from synthetic_scene import synthetic_pair  # noqa: E402


def synthetic_pairs(count, points=300, seed=1):
    """Pairs of a random scene and motion each (60% inliers), for the example."""
    rng = np.random.default_rng(seed)
    return [synthetic_pair(points, 0.6, rng, max_angle=0.2) for _ in range(count)]


def estimate_partition(first, pairs, seed, threads=0):
    """The batch of one partition on the worker's threads; firstIndex gives pair k the seed of
    pair first + k of the whole list, so the partitions together equal one batch."""
    out = cv_essential.findEssentialMatBatch(pairs, cv_essential.EssentialParams(seed=seed),
                                             threads=threads, firstIndex=first)
    return [(r.E, r.report.inliers) for r in out]


def estimate_locally(pairs, seed):
    """The reference: the whole list in one process (findEssentialMatBatch, all threads)."""
    out = cv_essential.findEssentialMatBatch(pairs, cv_essential.EssentialParams(seed=seed))
    return [(r.E, r.report.inliers) for r in out]


def estimate_on_cluster(client, pairs, seed, partition=16):
    """Maps estimate_partition over partitions of `partition` pairs and gathers them in order."""
    futures = [client.submit(estimate_partition, i, pairs[i:i + partition], seed, pure=False)
               for i in range(0, len(pairs), partition)]
    results = []
    for part in client.gather(futures):
        results.extend(part)
    return results


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scheduler", help="address of a dask scheduler (default: a LocalCluster "
                        "of two worker processes)")
    parser.add_argument("--pairs", type=int, default=64)
    parser.add_argument("--seed", type=int, default=7)
    args = parser.parse_args()

    from dask.distributed import Client, LocalCluster

    pairs = synthetic_pairs(args.pairs)
    if args.scheduler:
        client = Client(args.scheduler)
    else:
        client = Client(LocalCluster(n_workers=2, threads_per_worker=1, processes=True))
    with client:
        remote = estimate_on_cluster(client, pairs, args.seed)
    local = estimate_locally(pairs, args.seed)
    same = all(np.array_equal(a[0], b[0]) and a[1] == b[1] for a, b in zip(remote, local))
    print(f"{len(remote)} pairs on the cluster, {len(local)} locally; identical: {same}")
    return 0 if same else 1


if __name__ == "__main__":
    raise SystemExit(main())

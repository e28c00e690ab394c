# This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
# The Dask example (samples/python/dask_batch.py) on a LocalCluster of two worker processes gives
# exactly the single-process batch's results.
import importlib.util
import pathlib

import distributed  # python3-distributed (scripts/bootstrap.sh installs it)
import numpy as np

SAMPLE = pathlib.Path(__file__).resolve().parents[2] / "samples" / "python" / "dask_batch.py"


def load_sample():
    spec = importlib.util.spec_from_file_location("dask_batch", SAMPLE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_local_cluster_equals_single_process():
    sample = load_sample()
    pairs = sample.synthetic_pairs(24)
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                       dashboard_address=None)
    with cluster, distributed.Client(cluster) as client:
        remote = sample.estimate_on_cluster(client, pairs, seed=3, partition=5)
    local = sample.estimate_locally(pairs, seed=3)
    assert len(remote) == len(local) == 24
    for (E1, n1), (E2, n2) in zip(remote, local):
        assert np.array_equal(E1, E2) and n1 == n2
    assert sum(n > 0 for _, n in local) >= 20

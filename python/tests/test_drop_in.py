# This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
# Parity of cv_essential.findEssentialMatIter with cv2.findEssentialMat (camera-matrix form).
import cv2
import numpy as np
import pytest

import cv_essential


def scene(n=200, seed=1):
    rng = np.random.default_rng(seed)
    X = np.column_stack([rng.uniform(-1, 1, n), rng.uniform(-1, 1, n), rng.uniform(3, 8, n)])
    angle = 0.1
    R = np.array([[np.cos(angle), 0, np.sin(angle)], [0, 1, 0], [-np.sin(angle), 0, np.cos(angle)]])
    t = np.array([0.5, 0.05, 0.1])
    K = np.array([[500.0, 0, 320], [0, 500, 240], [0, 0, 1]])
    x1 = (K @ X.T).T
    X2 = (R @ X.T).T + t
    x2 = (K @ X2.T).T
    p1 = x1[:, :2] / x1[:, 2:] + rng.normal(0, 0.3, (n, 2))
    p2 = x2[:, :2] / x2[:, 2:] + rng.normal(0, 0.3, (n, 2))
    return p1, p2, K, R, t / np.linalg.norm(t)


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_same_shapes_and_pose_as_cv2(dtype):
    p1, p2, K, R, t = scene()
    E, mask = cv_essential.findEssentialMatIter(p1.astype(dtype), p2.astype(dtype), K)
    Ecv, maskcv = cv2.findEssentialMat(p1.astype(dtype), p2.astype(dtype), K)
    assert E.shape == (3, 3) and E.dtype == np.float64
    assert mask.shape == maskcv.shape and mask.dtype == maskcv.dtype
    _, Rour, tour, _ = cv2.recoverPose(E, p1, p2, K)
    angle = np.degrees(np.arccos(np.clip((np.trace(Rour @ R.T) - 1) / 2, -1, 1)))
    assert angle < 0.5
    assert np.degrees(np.arccos(np.clip(float(tour.ravel() @ t), -1, 1))) < 3.0


def test_bad_input_raises_cv2_error():
    p1, p2, K, _, _ = scene()
    with pytest.raises(cv2.error):
        cv_essential.findEssentialMatIter(p1[:4], p2[:4], K)


def pose_error(E, p1, p2, K, R, t):
    _, Rour, tour, _ = cv2.recoverPose(E[:3], p1, p2, K)
    angle = np.degrees(np.arccos(np.clip((np.trace(Rour @ R.T) - 1) / 2, -1, 1)))
    return angle, np.degrees(np.arccos(np.clip(float(tour.ravel() @ t), -1, 1)))


def test_focal_form_as_cv2():
    p1, p2, K, R, t = scene()
    E, mask = cv_essential.findEssentialMatIter(p1, p2, focal=500.0, pp=(320.0, 240.0))
    Ecv, maskcv = cv2.findEssentialMat(p1, p2, focal=500.0, pp=(320.0, 240.0))
    assert E.shape == Ecv.shape and mask.shape == maskcv.shape and mask.dtype == maskcv.dtype
    r, tt = pose_error(E, p1, p2, K, R, t)
    assert r < 0.5 and tt < 3.0


def test_two_camera_form_as_cv2():
    p1, p2, K, R, t = scene()
    E, mask = cv_essential.findEssentialMatIter(p1, p2, K, None, K, None)
    Ecv, maskcv = cv2.findEssentialMat(p1, p2, K, None, K, None)
    assert E.shape == Ecv.shape and mask.shape == maskcv.shape and mask.dtype == maskcv.dtype
    r, tt = pose_error(E, p1, p2, K, R, t)
    assert r < 0.5 and tt < 3.0


def test_usac_params_form_takes_cv2_object():
    p1, p2, K, R, t = scene()
    params = cv2.UsacParams()
    params.threshold = 1.0
    params.confidence = 0.999
    params.maxIterations = 1000
    E, mask = cv_essential.findEssentialMatIter(p1, p2, K, K, None, None, params)
    Ecv, maskcv = cv2.findEssentialMat(p1, p2, K, K, None, None, params)
    assert E.shape == Ecv.shape and mask.shape == maskcv.shape and mask.dtype == maskcv.dtype
    r, tt = pose_error(E, p1, p2, K, R, t)
    assert r < 0.5 and tt < 3.0


def test_keyword_names_as_cv2():
    p1, p2, K, _, _ = scene()
    E, mask = cv_essential.findEssentialMatIter(points1=p1, points2=p2, cameraMatrix=K,
                                                method=cv2.RANSAC, prob=0.99, threshold=2.0,
                                                maxIters=500)
    assert E.shape == (3, 3) and mask.shape == (len(p1), 1)


def rotation_error(Ra, Rb):
    return np.degrees(np.arccos(np.clip((np.trace(Ra @ Rb.T) - 1) / 2, -1, 1)))


def test_recover_pose_forms_as_cv2():
    p1, p2, K, R, t = scene()
    E, mask = cv2.findEssentialMat(p1, p2, K)
    n, Ro, to, mo = cv_essential.recoverPose(E, p1, p2, K)
    nc, Rc, tc, mc = cv2.recoverPose(E, p1, p2, K)
    assert Ro.shape == Rc.shape == (3, 3) and to.shape == tc.shape == (3, 1)
    assert mo.shape == mc.shape and mo.dtype == mc.dtype
    # Same decomposition and cheirality vote as cv2 (the C++ tests: within 2e-15).
    assert np.linalg.norm(Ro - Rc) < 1e-9 and abs(n - nc) <= 2
    # focal / pp
    n2, R2, t2, _ = cv_essential.recoverPose(E, p1, p2, focal=500.0, pp=(320.0, 240.0))
    assert np.linalg.norm(R2 - Rc) < 1e-9
    # distanceThresh with the triangulated points
    # cv2 reads a positional fifth argument as the output R: distanceThresh goes by keyword.
    assert len(cv_essential.recoverPose(E, p1, p2, K, 50.0)) == 4
    assert len(cv2.recoverPose(E, p1, p2, K, 50.0)) == 4
    out = cv_essential.recoverPose(E, p1, p2, K, distanceThresh=50.0)
    outc = cv2.recoverPose(E, p1, p2, K, distanceThresh=50.0)
    assert len(out) == len(outc) == 5
    assert out[4].shape == outc[4].shape
    assert np.linalg.norm(out[1] - outc[1]) < 1e-9
    # two cameras: estimate and pose
    res = cv_essential.recoverPose(p1, p2, K, None, K, None)
    assert len(res) == 5
    assert rotation_error(res[2], R) < 0.5
    # recoverPoseIter, the C++ API's name, is the same function under both names.
    ni, Ri, ti, mi = cv_essential.recoverPoseIter(E, p1, p2, K)
    assert ni == n and np.array_equal(Ri, Ro) and np.array_equal(ti, to) and np.array_equal(mi, mo)
    with pytest.raises(cv2.error, match="recoverPoseIter"):
        cv_essential.recoverPoseIter(E, "not points", p2, K)


def test_module_params_report_and_solvers():
    p1, p2, K, R, t = scene()
    params = cv_essential.EssentialParams(solver="nister", threshold=1.5, planeParallax=False)
    assert params.solver == "nister" and params.threshold == 1.5 and not params.planeParallax
    assert "solver='nister'" in repr(params)
    with pytest.raises(TypeError):
        cv_essential.EssentialParams(no_such_field=1)
    E, mask, report = cv_essential.findEssentialMatIter(p1, p2, K, params)
    assert report.success and report.poseRecovered and report.inliers == int(mask.sum())
    assert rotation_error(report.R, R) < 0.5
    assert report.t.shape == (3, 1)
    assert {"gn", "lm", "nister", "robust"} <= set(cv_essential.listSolvers())
    with pytest.raises(cv2.error):
        cv_essential.findEssentialMatIter(p1, p2, K, cv_essential.EssentialParams(solver="nope"))


def test_estimate_releases_the_gil():
    # While an estimate with a 500 ms budget runs in one thread, the main thread finishes a short
    # loop long before the estimate ends. With the GIL held during the call, the main thread could
    # not run until the call returned. (An ordering with a margin of hundreds of milliseconds, not
    # a speed measurement.)
    import threading
    import time

    rng = np.random.default_rng(5)
    p1 = rng.uniform(0, 640, (2000, 2))
    p2 = rng.uniform(0, 480, (2000, 2))  # no geometry: the search runs its whole time budget
    K = np.array([[500.0, 0, 320], [0, 500, 240], [0, 0, 1]])
    params = cv_essential.EssentialParams(timeBudgetMs=500.0, confidence=1 - 1e-12,
                                          maxIterations=100000000)
    ended = {}

    def estimate():
        cv_essential.findEssentialMatIter(p1, p2, K, params)
        ended["estimate"] = time.perf_counter()

    thread = threading.Thread(target=estimate)
    thread.start()
    time.sleep(0.05)  # let the estimate start (sleeping releases the GIL)
    total = 0
    for i in range(10000):
        total += i
    ended["main"] = time.perf_counter()
    thread.join()
    assert ended["main"] < ended["estimate"] - 0.2


def five_point_with_cv2(x1, x2):
    # cv2 returns every solution of exactly five points stacked into a (3k, 3) array.
    E, _ = cv2.findEssentialMat(x1, x2, np.eye(3), cv2.RANSAC, 0.999, 1e-3)
    if E is None:
        return []
    return [E[3 * i:3 * i + 3] for i in range(E.shape[0] // 3)]


def test_python_registered_solver():
    cv_essential.registerSolver("py_cv2_five_point", five_point_with_cv2)
    assert "py_cv2_five_point" in cv_essential.listSolvers()
    p1, p2, K, R, t = scene(n=100)
    params = cv_essential.EssentialParams(solver="py_cv2_five_point", maxIterations=200)
    E, mask, report = cv_essential.findEssentialMatIter(p1, p2, K, params)
    assert report.success and rotation_error(report.R, R) < 0.5


def test_python_solver_exception_becomes_cv2_error():
    def broken(x1, x2):
        raise RuntimeError("this solver is broken")

    cv_essential.registerSolver("py_broken", broken)
    p1, p2, K, _, _ = scene(n=50)
    with pytest.raises(cv2.error, match="py_broken|broken"):
        cv_essential.findEssentialMatIter(p1, p2, K, cv_essential.EssentialParams(solver="py_broken"))


def test_batch_is_deterministic_and_reports_bad_pairs():
    pairs = []
    for i in range(6):
        p1, p2, K, _, _ = scene(n=150, seed=10 + i)
        pairs.append((p1, p2, K))
    pairs.append((pairs[0][0], pairs[0][1][:10], pairs[0][2]))  # sizes differ: bad pair
    seen = []
    one = cv_essential.findEssentialMatBatch(pairs, threads=1)
    two = cv_essential.findEssentialMatBatch(pairs, threads=2,
                                             progress=lambda done, total: seen.append((done, total)))
    assert len(one) == len(two) == 7
    for a, b in zip(one[:6], two[:6]):
        assert a.error == "" and np.array_equal(a.E, b.E) and np.array_equal(a.mask, b.mask)
    assert one[6].error != "" and two[6].error != ""
    assert sorted(seen) == [(k, 7) for k in range(1, 8)]
    # Pair 3 alone, with its derived seed, gives the same E.
    params = cv_essential.EssentialParams(seed=cv_essential.batchPairSeed(
        cv_essential.EssentialParams().seed, 3))
    E, _, _ = cv_essential.findEssentialMatIter(*pairs[3], params)
    assert np.array_equal(E, one[3].E)
    # A part of the list with the index of its first pair gives the whole batch's results.
    part = cv_essential.findEssentialMatBatch(pairs[3:5], threads=1, firstIndex=3)
    assert all(np.array_equal(a.E, b.E) for a, b in zip(part, one[3:5]))
    assert one[6].E is None and one[6].report.numPoints == 0

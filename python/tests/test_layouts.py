# This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
# Every point and camera-matrix layout is accepted or refused as the installed cv2 does (float16:
# refused by cv2 4.6, read as CV_16F from 4.8 on); accepted layouts
# give results of cv2's shapes and dtypes, and the values of the plain float64 N x 2 layout.
import cv2
import numpy as np
import pytest

import cv_essential
from layouts import POINT_LAYOUTS, compare_points, outcome, scene


@pytest.mark.parametrize("name", list(POINT_LAYOUTS))
def test_point_layout_as_cv2(name):
    theirs, ours = compare_points(name)
    if theirs[0] == "raise":
        # cv2 raises cv2.error for every refusal (a failed overload resolution included).
        assert theirs[1] == "error"
        assert ours[0] == "raise" and ours[1] == "error", ours
        return
    assert ours[0] == "ok", ours
    # The values: those of the same points as a contiguous float64 N x 2 array, bit for bit.
    p1, p2, K = scene()
    make = POINT_LAYOUTS[name]
    ref1 = np.asarray(make(p1), np.float64).reshape(-1, 2)
    ref2 = np.asarray(make(p2), np.float64).reshape(-1, 2)
    E, mask = cv_essential.findEssentialMatIter(ref1, ref2, K)
    if E is None and ours[1][0] is None:
        # Accepted, but the values carry no geometry (cv2 5's bool arrays: every coordinate 0 or
        # 1): the module returns no E, where OpenCV returns one fitted to chance.
        assert ours[1][1] == theirs[1][1]  # the mask's shape and dtype
    else:
        assert ours[1] == theirs[1]  # shapes and dtypes of (E, mask)
    assert np.array_equal(ours[2][0], E) and np.array_equal(ours[2][1], mask)


CAMERA_LAYOUTS = {
    "3 x 3 float64": lambda K: K,
    "3 x 3 float32": lambda K: K.astype(np.float32),
    "3 x 3 int32": lambda K: K.astype(np.int32),
    "3 x 3 Fortran order": lambda K: np.asfortranarray(K),
    "9 float64": lambda K: K.ravel(),
    "a float (cv2: a 4 x 1 matrix)": lambda K: 500.0,
    "an int": lambda K: 500,
    "a tuple of 9": lambda K: tuple(K.ravel()),
    "a list of lists": lambda K: K.tolist(),
    "None": lambda K: None,
}


@pytest.mark.parametrize("name", list(CAMERA_LAYOUTS))
def test_camera_matrix_layout_as_cv2(name):
    p1, p2, K = scene()
    Kx = CAMERA_LAYOUTS[name](K)
    theirs = outcome(cv2.findEssentialMat, p1, p2, Kx)
    ours = outcome(cv_essential.findEssentialMatIter, p1, p2, Kx)
    assert ours[:2] == theirs[:2]


def test_refusals_name_the_argument():
    p1, p2, K = scene()
    with pytest.raises(cv2.error, match="points2.*list"):
        cv_essential.findEssentialMatIter(p1, p2.tolist(), K)
    with pytest.raises(cv2.error, match="mask.*complex128"):
        cv_essential.findEssentialMatIter(p1, p2, K, mask=np.ones(len(p1), np.complex128))
    with pytest.raises(cv2.error, match="cameraMatrix.*str"):
        cv_essential.findEssentialMatIter(p1, p2, cameraMatrix="K")


def test_non_array_arguments_as_cv2():
    # Numbers, keywords and counts: accepted or refused (always with cv2.error) as cv2 does.
    p1, p2, K = scene()
    calls = [
        ((p1, p2, K, 8.0), {}),  # a float method
        ((p1, p2, K, "x"), {}),
        ((p1, p2, K, cv2.RANSAC, 1), {}),  # prob 1: refused by the estimator
        ((p1, p2, 500.0, (320, 240)), {}),  # focal and pp, positional
        ((p1, p2, 500.0, [320, 240]), {}),
        ((p1, p2), {"focal": 500.0, "pp": (320.0, 240.0)}),
        ((p1, p2), {}),
        ((p1, p2, K), {"foo": 1}),
        ((p1,), {}),
        ((p1, p2, K), {"mask": np.ones((len(p1), 1), np.uint8)}),
        ((p1, p2, K), {"mask": [1] * len(p1)}),
        ((p1, p2, K), {"maxIters": 10.5}),
        ((p1, p2, K, K, None, None, "params"), {}),
        ((p1, p2, K, None, K, None, cv2.LMEDS), {}),
    ]
    for args, kwargs in calls:
        theirs = outcome(lambda *a: cv2.findEssentialMat(*a, **kwargs), *args)
        ours = outcome(lambda *a: cv_essential.findEssentialMatIter(*a, **kwargs), *args)
        assert ours[:2] == theirs[:2], (args[2:], kwargs, theirs[:2], ours[:2])


def test_recover_pose_layouts_as_cv2():
    p1, p2, K = scene()
    E, _ = cv2.findEssentialMat(p1, p2, K)
    for name, make in POINT_LAYOUTS.items():
        theirs = outcome(cv2.recoverPose, E, make(p1), make(p2), K)
        ours = outcome(cv_essential.recoverPose, E, make(p1), make(p2), K)
        assert ours[:2] == theirs[:2], name
    for Ex in (E.ravel(), E.reshape(1, 9), E.astype(np.int32), E.tolist(), None):
        assert outcome(cv_essential.recoverPose, Ex, p1, p2, K)[:2] == \
            outcome(cv2.recoverPose, Ex, p1, p2, K)[:2]
    # One deliberate difference: cv2 4.6 raises on a float32 E (an internal type mismatch in
    # OpenCV, its bug), the module reads it as it reads a float64 one.
    assert outcome(cv2.recoverPose, E.astype(np.float32), p1, p2, K)[0] == "raise"
    n, R, t, _ = cv_essential.recoverPose(E.astype(np.float32), p1, p2, K)
    assert np.allclose(R, cv_essential.recoverPose(E, p1, p2, K)[1], atol=1e-5)


def test_caller_arrays_are_not_written():
    p1, p2, K = scene()
    mask = np.zeros((len(p1), 1), np.uint8)
    before = (p1.copy(), p2.copy(), mask.copy())
    _, out = cv_essential.findEssentialMatIter(p1, p2, K, mask=mask)
    assert out is not mask and out.sum() > 0
    assert np.array_equal(p1, before[0]) and np.array_equal(mask, before[2])

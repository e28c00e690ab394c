#!/usr/bin/env python
# This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
# See the LICENSE file at the top of the source tree.
#
# cv2.essential as OpenCV's Python generator makes it from the module's headers, in OpenCV's own
# Python test layout (<module>/misc/python/test, run by <opencv>/modules/python/test/test.py;
# scripts/build_in_opencv.sh builds it and scripts/test.sh runs it). The names and signatures are
# those of the standalone package cv_essential (python/cv_essential.pyi).
from __future__ import print_function

import os
import re

import numpy as np
import cv2 as cv

from tests_common import NewOpenCVTests


def two_view_scene(n=200, outliers=60, seed=3):
    """n correspondences of a random scene seen by two cameras (K below), 0.3 px noise, the last
    `outliers` of them replaced by random points; returns points1, points2, K, R, unit t."""
    rng = np.random.default_rng(seed)
    X = np.column_stack([rng.uniform(-1, 1, n), rng.uniform(-1, 1, n), rng.uniform(3, 8, n)])
    angle = 0.1
    R = np.array([[np.cos(angle), 0, np.sin(angle)], [0, 1, 0],
                  [-np.sin(angle), 0, np.cos(angle)]])
    t = np.array([0.5, 0.05, 0.1])
    K = np.array([[500.0, 0, 320], [0, 500, 240], [0, 0, 1]])
    x1 = (K @ X.T).T
    x2 = (K @ ((R @ X.T).T + t).T).T
    p1 = x1[:, :2] / x1[:, 2:] + rng.normal(0, 0.3, (n, 2))
    p2 = x2[:, :2] / x2[:, 2:] + rng.normal(0, 0.3, (n, 2))
    p2[n - outliers:] = rng.uniform(0, 640, (outliers, 2))
    return p1, p2, K, R, t / np.linalg.norm(t)


def pose_errors_deg(R_est, t_est, R, t):
    rotation = np.degrees(np.arccos(np.clip((np.trace(R_est @ R.T) - 1) / 2, -1, 1)))
    direction = np.degrees(np.arccos(np.clip(float(np.ravel(t_est) @ t), -1, 1)))
    return rotation, direction


PARAMS_HPP = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..', 'include',
                          'opencv2', 'essential', 'params.hpp')


def cpp_fields(struct):
    """Data members of the C++ declaration of `struct` (the one the compiler sees) in params.hpp."""
    with open(PARAMS_HPP) as f:
        text = f.read()
    body = text[text.index('struct CV_EXPORTS %s\n' % struct):]
    body = re.sub(r'/\*.*?\*/', '', body[body.index('{') + 1:body.index('\n};')], flags=re.S)
    return {m.group(1) for m in re.finditer(r'^\s+[\w:<>]+\s+(\w+)\s*=', body, flags=re.M)}


class essential_test(NewOpenCVTests):

    def test_structs_have_every_cpp_field(self):
        # params.hpp declares both structs twice: for the compiler (with defaults) and for OpenCV's
        # generator (with the binding macros); the bindings must carry every C++ field.
        params = cv.essential.EssentialParams()
        report = cv.essential.EssentialReport()
        for struct, obj, least in (('EssentialParams', params, 20), ('EssentialReport', report, 25)):
            fields = cpp_fields(struct)
            self.assertGreaterEqual(len(fields), least)
            self.assertEqual(fields, {n for n in dir(obj) if not n.startswith('_')})
        self.assertEqual(params.seed, 0x6573736e7469616c)
        self.assertEqual(params.sampleBudget, cv.essential.BUDGET_OPENCV_TIME)

    def test_drop_in_matches_cv_findEssentialMat(self):
        p1, p2, K, R, t = two_view_scene()
        E, mask = cv.essential.findEssentialMatIter(p1, p2, K, cv.RANSAC, 0.999, 1.0)
        E_cv, mask_cv = cv.findEssentialMat(p1, p2, K, cv.RANSAC, 0.999, 1.0)
        self.assertEqual(E.shape, (3, 3))
        self.assertEqual(E.dtype, np.float64)
        self.assertEqual(mask.shape, mask_cv.shape)
        self.assertEqual(mask.dtype, mask_cv.dtype)
        # Unit Frobenius norm, as OpenCV's.
        self.assertAlmostEqual(np.linalg.norm(E), 1.0, delta=1e-9)
        # 0.3 px noise on 140 inliers: the pose is within a fraction of a degree (3 degrees for
        # the translation direction, the less determined of the two), and the 60 random points
        # are rejected (at most a few fall near their epipolar lines by chance).
        _, R_est, t_est, _ = cv.essential.recoverPoseIter(E, p1, p2, K, mask=mask.copy())
        rotation, direction = pose_errors_deg(R_est, t_est, R, t)
        self.assertLess(rotation, 0.5)
        self.assertLess(direction, 3.0)
        self.assertGreater(int(np.count_nonzero(mask[:140])), 130)
        self.assertLess(int(np.count_nonzero(mask[140:])), 5)

    def test_params_overload_returns_a_report(self):
        p1, p2, K, R, t = two_view_scene()
        params = cv.essential.EssentialParams()
        self.assertEqual(params.solver, "nister")
        self.assertEqual(params.maxIterations, 1000)
        self.assertEqual(params.score, cv.SCORE_METHOD_MSAC)
        self.assertEqual(params.engine, cv.essential.ENGINE_ADAPTIVE)
        params.solver = "gn"
        E, mask, report = cv.essential.findEssentialMatIter(p1, p2, K, params)
        self.assertTrue(report.success)
        self.assertEqual(report.numPoints, len(p1))
        self.assertEqual(report.inliers, int(np.count_nonzero(mask)))
        self.assertTrue(report.poseRecovered)
        rotation, direction = pose_errors_deg(np.asarray(report.R), np.asarray(report.t), R, t)
        self.assertLess(rotation, 0.5)
        self.assertLess(direction, 3.0)
        np.testing.assert_allclose(np.asarray(report.E), E, atol=1e-12)

    def test_recoverPose_forms(self):
        p1, p2, K, R, t = two_view_scene(outliers=0)
        E, _ = cv.essential.findEssentialMatIter(p1, p2, K)
        count, R_est, t_est, mask = cv.essential.recoverPoseIter(E, p1, p2, K)
        # The original spelling is the same function.
        count_old, R_old, _, _ = cv.essential.recoverPose(E, p1, p2, K)
        self.assertEqual(count_old, count)
        np.testing.assert_array_equal(R_old, R_est)
        self.assertEqual(count, int(np.count_nonzero(mask)))
        self.assertGreater(count, 190)
        rotation, direction = pose_errors_deg(R_est, t_est, R, t)
        self.assertLess(rotation, 0.5)
        self.assertLess(direction, 3.0)
        # OpenCV's distance cut, passed explicitly, with the triangulated points (4 x N).
        count50, _, _, _, points = cv.essential.recoverPoseIter(E, p1, p2, K, distanceThresh=50.0)
        self.assertEqual(points.shape, (4, len(p1)))
        self.assertLessEqual(count50, count)

    def test_listSolvers_names_the_built_in_solvers(self):
        solvers = cv.essential.listSolvers()
        for name in ("gn", "lm", "nister", "robust"):
            self.assertIn(name, solvers)
        self.assertEqual(list(solvers), sorted(solvers))

    def test_bad_input_raises_cv_error(self):
        p1, p2, K, _, _ = two_view_scene()
        with self.assertRaises(cv.error):
            cv.essential.findEssentialMatIter(p1[:4], p2[:4], K)

    def test_opencv_loop_engine(self):
        # In-tree the module is compiled against this very OpenCV 4.6, whose RANSAC loop it runs.
        self.assertTrue(cv.essential.isOpenCvLoopAvailable())
        p1, p2, K, R, t = two_view_scene()
        params = cv.essential.EssentialParams()
        params.engine = cv.essential.ENGINE_OPENCV
        E, mask, report = cv.essential.findEssentialMatIter(p1, p2, K, params)
        self.assertTrue(report.success)
        rotation, direction = pose_errors_deg(np.asarray(report.R), np.asarray(report.t), R, t)
        self.assertLess(rotation, 0.5)
        self.assertLess(direction, 3.0)


if __name__ == '__main__':
    NewOpenCVTests.bootstrap()

# This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
# EssentialParams and EssentialReport carry every field of their C++ structs
# (opencv2/essential/params.hpp), with the C++ defaults, and survive pickling.
import pathlib
import pickle
import re

import cv2
import numpy as np
import pytest

import cv_essential

HEADER = (pathlib.Path(__file__).resolve().parents[2] /
          "modules/essential/include/opencv2/essential/params.hpp")


def header_fields(struct):
    """The data members of `struct` in the header: {name: default text}."""
    text = HEADER.read_text()
    body = text[text.index(f"struct CV_EXPORTS {struct}"):]
    body = body[body.index("{") + 1:body.index("\n};")]
    body = re.sub(r"/\*.*?\*/", "", body, flags=re.S)
    fields = {}
    for line in body.splitlines():
        m = re.match(r"\s+[\w:<>]+\s+(\w+)\s*=\s*([^;]+);", line)
        if m:
            fields[m.group(1)] = m.group(2).strip()
    return fields


def test_params_have_every_field_with_the_cpp_default():
    fields = header_fields("EssentialParams")
    assert len(fields) >= 20
    params = cv_essential.EssentialParams()
    assert set(fields) == {n for n in dir(params) if not n.startswith("_")}
    for name in fields:
        assert f"{name}=" in repr(params)
    # Defaults read from C++, spot-checked against the header's text.
    assert params.solver == fields["solver"].strip('"')
    assert params.maxIterations == int(fields["maxIterations"])
    assert params.confidence == float(fields["confidence"])
    assert params.seed == int(fields["seed"].rstrip("ULL"), 16)
    assert params.sampleBudget == cv_essential.BUDGET_OPENCV_TIME
    assert params.engine == cv_essential.ENGINE_ADAPTIVE
    assert params.score == cv2.SCORE_METHOD_MSAC and params.sampler == cv2.SAMPLING_UNIFORM


def test_report_has_every_field():
    fields = header_fields("EssentialReport")
    assert len(fields) >= 25
    assert set(fields) == {n for n in dir(cv_essential.EssentialReport) if not n.startswith("_")}


def scene(n=150, seed=3):
    rng = np.random.default_rng(seed)
    X = np.column_stack([rng.uniform(-1, 1, n), rng.uniform(-1, 1, n), rng.uniform(3, 8, n)])
    K = np.array([[500.0, 0, 320], [0, 500, 240], [0, 0, 1]])
    x1 = X @ K.T
    x2 = (X + [0.5, 0, 0.1]) @ K.T
    p2 = x2[:, :2] / x2[:, 2:] + rng.normal(0, 0.3, (n, 2))
    return x1[:, :2] / x1[:, 2:], p2, K


def test_report_values_are_consistent():
    p1, p2, K = scene()
    E, mask, report = cv_essential.findEssentialMatIter(p1, p2, K, cv_essential.EssentialParams())
    assert report.success and report.numPoints == len(p1) and report.inliers == int(mask.sum())
    assert np.allclose(report.E, E) and report.E.shape == (3, 3) and report.t.shape == (3, 1)
    assert report.hypothesesGenerated >= report.iterations > 0
    assert report.hypothesesScored > 0 and report.pointsScored >= report.hypothesesScored
    assert report.refineIterations > 0
    parts = report.timeSetupMs + report.timeSearchMs + report.timeRefineMs + report.timePoseMs
    assert 0 < parts <= report.timeTotalMs * 1.001 + 1e-6
    assert 0 <= report.homographyFraction <= 1 and 0 <= report.rotationOnlyFraction <= 1


def test_params_report_and_results_pickle():
    params = cv_essential.EssentialParams(solver="lm", threshold=2.5, seed=7, planeParallax=False)
    back = pickle.loads(pickle.dumps(params))
    assert repr(back) == repr(params)
    p1, p2, K = scene()
    _, _, report = cv_essential.findEssentialMatIter(p1, p2, K, params)
    again = pickle.loads(pickle.dumps(report))
    for name in header_fields("EssentialReport"):
        assert np.array_equal(getattr(again, name), getattr(report, name)), name
    result = cv_essential.findEssentialMatBatch([(p1, p2, K)], params)[0]
    copy = pickle.loads(pickle.dumps(result))
    assert np.array_equal(copy.E, result.E) and np.array_equal(copy.mask, result.mask)
    assert copy.report.inliers == result.report.inliers and copy.error == ""


def test_params_refuse_unknown_fields_and_bad_values():
    with pytest.raises(TypeError, match="no_such_field"):
        cv_essential.EssentialParams(no_such_field=1)
    with pytest.raises(TypeError):
        cv_essential.EssentialParams(maxIterations="many")
    with pytest.raises(ValueError):
        cv_essential.EssentialParams(distance=7)
    # Every enum field is an int checked against its enumeration, the error naming the field.
    for field, bad in [("score", 9), ("engine", 3), ("sampler", -1), ("sampleBudget", 2)]:
        with pytest.raises(ValueError, match=f"EssentialParams.{field} must be one of"):
            cv_essential.EssentialParams(**{field: bad})
    params = cv_essential.EssentialParams(score=cv2.SCORE_METHOD_LMEDS,
                                          sampler=cv2.SAMPLING_PROSAC,
                                          engine=cv_essential.ENGINE_PREEMPTIVE)
    assert (params.score, params.sampler) == (cv2.SCORE_METHOD_LMEDS, cv2.SAMPLING_PROSAC)
    # A score the module does not implement is a valid ScoreMethod: refused by the estimate.
    p1, p2, K = scene()
    with pytest.raises(cv2.error, match="SCORE_METHOD_MAGSAC"):
        cv_essential.findEssentialMatIter(
            p1, p2, K, cv_essential.EssentialParams(score=cv2.SCORE_METHOD_MAGSAC))

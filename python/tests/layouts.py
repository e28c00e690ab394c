# This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
# The point layouts a Python user may pass, and how cv2.findEssentialMat and
# cv_essential.findEssentialMatIter treat each: accepted or refused, the results' shapes and
# dtypes. Used by test_layouts.py (parity) and, run as a script, prints the table of
# python/README.md:
#   PYTHONPATH=build/python /usr/bin/python3 python/tests/layouts.py
import cv2
import numpy as np

import cv_essential


def scene(n=60, seed=1):
    rng = np.random.default_rng(seed)
    X = np.column_stack([rng.uniform(-1, 1, n), rng.uniform(-1, 1, n), rng.uniform(4, 8, n)])
    K = np.array([[500.0, 0, 320], [0, 500, 240], [0, 0, 1]])
    c, s = np.cos(0.1), np.sin(0.1)
    R = np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    x1 = X @ K.T
    x2 = (X @ R.T + [1.0, 0, 0.2]) @ K.T
    return x1[:, :2] / x1[:, 2:], x2[:, :2] / x2[:, 2:], K


# name -> function of an (N, 2) float64 array; the values of every accepted layout are those of
# np.asarray(layout, float64).reshape(-1, 2), the reference the parity test compares against.
POINT_LAYOUTS = {
    "N x 2 float64": lambda p: p.copy(),
    "N x 2 float32": lambda p: p.astype(np.float32),
    "N x 1 x 2 float32 (cv2's KeyPoint_convert layout)": lambda p: p.astype(np.float32).reshape(-1, 1, 2),
    "1 x N x 2 float64": lambda p: p.reshape(1, -1, 2),
    "N x 2 x 1 float64": lambda p: p.reshape(-1, 2, 1),
    "N x 2 int32": lambda p: np.round(p).astype(np.int32),
    "N x 2 int64": lambda p: np.round(p).astype(np.int64),
    "N x 2 uint64": lambda p: np.round(p).astype(np.uint64),
    "N x 2 int16": lambda p: np.round(p).astype(np.int16),
    "N x 2 uint16": lambda p: np.round(p).astype(np.uint16),
    "N x 2 int8": lambda p: np.clip(np.round(p / 8), -128, 127).astype(np.int8),
    "N x 2 uint8": lambda p: np.clip(np.round(p / 4), 0, 255).astype(np.uint8),
    "N x 2 float64, every other row (strided view)": lambda p: np.repeat(p, 2, axis=0)[::2],
    "N x 2 float64, Fortran order": lambda p: np.asfortranarray(p),
    "N x 2 float64, big-endian": lambda p: p.astype(">f8"),
    "N x 2 float16": lambda p: p.astype(np.float16),
    "N x 2 uint32": lambda p: np.round(p).astype(np.uint32),
    "N x 2 bool": lambda p: p > 300,
    "N x 2 complex128": lambda p: p.astype(np.complex128),
    "N x 2 object": lambda p: p.astype(object),
    "2 x N float64": lambda p: p.T.copy(),
    "N x 3 float64 (homogeneous)": lambda p: np.column_stack([p, np.ones(len(p))]),
    "2N float64 (flat)": lambda p: p.ravel(),
    "N x 1 x 1 x 2 float64": lambda p: p.reshape(-1, 1, 1, 2),
    "list of tuples": lambda p: [tuple(r) for r in p],
    "list of lists": lambda p: p.tolist(),
    "tuple of tuples": lambda p: tuple(tuple(r) for r in p),
    "None": lambda p: None,
}


def outcome(function, *args):
    """('ok', shapes and dtypes of the results, results) or ('raise', exception type name)."""
    try:
        out = function(*args)
    except Exception as e:  # the comparison is the point: any exception is recorded
        return ("raise", type(e).__name__, None)
    shapes = tuple(None if a is None else (a.shape, str(a.dtype)) if isinstance(a, np.ndarray)
                   else type(a).__name__ for a in out)
    return ("ok", shapes, out)


def compare_points(name):
    """cv2's and our outcome of findEssentialMatIter(points1, points2, K) with `name`'s layout."""
    p1, p2, K = scene()
    make = POINT_LAYOUTS[name]
    theirs = outcome(cv2.findEssentialMat, make(p1), make(p2), K)
    ours = outcome(cv_essential.findEssentialMatIter, make(p1), make(p2), K)
    return theirs, ours


def table():
    rows = ["| points layout | cv2.findEssentialMat | cv_essential | same |", "|---|---|---|---|"]
    for name in POINT_LAYOUTS:
        theirs, ours = compare_points(name)

        def cell(o):
            if o[0] == "raise":
                return "raises cv2.error" if o[1] == "error" else f"raises {o[1]}"
            return "E {} {}, mask {} {}".format(o[1][0][0], o[1][0][1], o[1][1][0], o[1][1][1])

        same = theirs[:2] == ours[:2] if theirs[0] == "ok" else ours[0] == "raise"
        rows.append(f"| {name} | {cell(theirs)} | {cell(ours)} | {'yes' if same else 'NO'} |")
    return "\n".join(rows)


if __name__ == "__main__":
    print(table())

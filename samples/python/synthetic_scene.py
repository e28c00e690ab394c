# This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
# See the LICENSE file at the top of the source tree.
"""Random two-view scenes for the Python examples and the binding's benchmark: points in a box in
front of a 500-pixel camera (640 x 480), a rotation about the vertical axis, a random unit
translation, Gaussian pixel noise, and outliers uniform over the second image."""
import numpy as np

# The camera of every scene: focal length 500 px, principal point at the centre of 640 x 480.
CAMERA = np.array([[500.0, 0, 320], [0, 500, 240], [0, 0, 1]])


def synthetic_pair(points, inlier_ratio, rng, max_angle=0.3, noise_px=0.5):
    """(p1, p2, K): `points` matches in pixels, each an inlier with probability `inlier_ratio`,
    the rotation angle uniform in [0, max_angle] radians; `rng` a numpy Generator."""
    X = np.column_stack([rng.uniform(-2, 2, points), rng.uniform(-2, 2, points),
                         rng.uniform(4, 12, points)])
    angle = rng.uniform(0.0, max_angle)
    c, s = np.cos(angle), np.sin(angle)
    R = np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    t = rng.normal(size=3)
    t /= np.linalg.norm(t)
    x1 = X @ CAMERA.T
    x2 = (X @ R.T + t) @ CAMERA.T
    p1 = x1[:, :2] / x1[:, 2:] + rng.normal(0, noise_px, (points, 2))
    p2 = x2[:, :2] / x2[:, 2:] + rng.normal(0, noise_px, (points, 2))
    outliers = rng.random(points) > inlier_ratio
    p2[outliers] = rng.uniform([0, 0], [640, 480], (int(outliers.sum()), 2))
    return p1, p2, CAMERA.copy()

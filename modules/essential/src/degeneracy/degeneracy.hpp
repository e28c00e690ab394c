// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Whether a rotation alone explains the correspondences: the test behind
// EssentialReport::degenerate. With no parallax (pure rotation, a baseline too short for the
// depths, all points far away) every E = [t]x R with the right R fits the data for any t, so an
// estimate "succeeds" with all points as inliers and a translation direction that is noise.

#ifndef OPENCV_ESSENTIAL_DEGENERACY_DEGENERACY_HPP
#define OPENCV_ESSENTIAL_DEGENERACY_DEGENERACY_HPP

#include "input/problem.hpp"

#include <opencv2/core.hpp>

namespace cv {
namespace essential {
namespace degeneracy {

/** Fits the rotation R that best maps the rays of view 1 onto those of view 2 (orthogonal
Procrustes on the unit bearing vectors of the masked points) and returns the fraction of those
points whose image-2 position is within `maxDistance` (normalised units) of the projection of
R x1. 0 when fewer than 3 points are masked in. */
double rotationOnlyFraction(const Problem& points, const uchar* mask, double maxDistance);

/** Fits a homography x2 ~ H x1 to the masked points (direct linear transform, least squares) and
returns the fraction of them whose image-2 position is within `maxDistance` (normalised units) of
H x1. 0 when fewer than 5 points are masked in. */
double homographyFraction(const Problem& points, const uchar* mask, double maxDistance);

} // namespace degeneracy
} // namespace essential
} // namespace cv

#endif

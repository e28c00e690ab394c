// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The Sampson distance of a correspondence to an essential matrix: the first-order approximation
// of its geometric (reprojection) error, r^2 / (|(E q1)_xy|^2 + |(E^T q2)_xy|^2). It is the error
// cv::findEssentialMat thresholds, so thresholds mean the same in both.

#ifndef OPENCV_ESSENTIAL_GEOMETRY_SAMPSON_HPP
#define OPENCV_ESSENTIAL_GEOMETRY_SAMPSON_HPP

#include <Eigen/Core>

namespace cv {
namespace essential {
namespace geometry {

/** Squared Sampson distance, written element-wise on the 9 entries so the caller's loop over
structure-of-arrays points vectorises. A zero denominator (a point on both epipoles) gives +inf for
a non-zero residual and NaN-free 0/0 -> handled by the caller through the comparison semantics
(NaN compares false, so such a point never counts as an inlier). */
inline double sampsonSquared(const Eigen::Matrix3d& E, double x1, double y1, double x2, double y2)
{
    const double e1x = E(0, 0) * x1 + E(0, 1) * y1 + E(0, 2);
    const double e1y = E(1, 0) * x1 + E(1, 1) * y1 + E(1, 2);
    const double e1z = E(2, 0) * x1 + E(2, 1) * y1 + E(2, 2);
    const double e2x = E(0, 0) * x2 + E(1, 0) * y2 + E(2, 0);
    const double e2y = E(0, 1) * x2 + E(1, 1) * y2 + E(2, 1);
    const double r = x2 * e1x + y2 * e1y + e1z;
    return r * r / (e1x * e1x + e1y * e1y + e2x * e2x + e2y * e2y);
}

} // namespace geometry
} // namespace essential
} // namespace cv

#endif

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
// The signs of a correspondence's two depths under a pose, without triangulating: what both
// cheirality tests need (the sample check of solvers/sample_cheirality.hpp and the in-front score
// of scoring/in_front_score.hpp), each with its own parallax below which the signs are noise's.
#ifndef OPENCV_ESSENTIAL_GEOMETRY_DEPTH_SIGNS_HPP
#define OPENCV_ESSENTIAL_GEOMETRY_DEPTH_SIGNS_HPP

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace cv {
namespace essential {
namespace geometry {

/** For X2 = R X1 + t, the point's ray in view 1 rotated into view 2 (a = R q1) and its ray in view
2 (q2): from lambda2 q2 = lambda1 a + t with c = q2 x a, lambda1 = -(q2 x t).c / |c|^2 and
lambda2 = -(a x t).c / |c|^2. Writes depth1 and depth2, the two depths times |c|^2 > 0 (so with
their signs), and returns true; returns false, writing nothing, when the sine of the angle between
the rays is at most minParallax: a point that far away (or that near the epipole) has depth signs
that image noise decides. */
inline bool scaledDepths(const Eigen::Vector3d& a, const Eigen::Vector3d& q2,
                         const Eigen::Vector3d& t, double minParallax, double& depth1,
                         double& depth2)
{
    const Eigen::Vector3d c = q2.cross(a);
    if (c.squaredNorm() <= minParallax * minParallax * a.squaredNorm() * q2.squaredNorm())
        return false;
    depth1 = -q2.cross(t).dot(c);
    depth2 = -a.cross(t).dot(c);
    return true;
}

} // namespace geometry
} // namespace essential
} // namespace cv

#endif

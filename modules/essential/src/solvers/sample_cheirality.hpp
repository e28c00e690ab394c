// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Cheirality of a minimal-set solution: can the sample's points lie in front of both cameras for
// one of the four poses of E? A five-point sample has up to ten exact solutions; the true one
// always passes, and most of the others do not.

#ifndef OPENCV_ESSENTIAL_SOLVERS_SAMPLE_CHEIRALITY_HPP
#define OPENCV_ESSENTIAL_SOLVERS_SAMPLE_CHEIRALITY_HPP

#include "geometry/depth_signs.hpp"
#include "geometry/essential_parameterisation.hpp"

#include <opencv2/core.hpp>

#include <cmath>

namespace cv {
namespace essential {
namespace solvers {

/** Below this sine of the angle between the two rays of a point (its parallax) the sign of its
depth is not decided: with image noise of 0.001 normalised units (0.5 px at f = 500) the rays of a
point at infinity make angles of that order in either direction. Such points take no part. */
constexpr double kMinCheiralityParallax = 3e-3;

namespace detail {

/** Depth signs of the sample points under the rotation R and translation t (X2 = R X1 + t):
`front` when every decided point has positive depths in both views, `back` when every decided
point has negative ones (then -t puts them in front). */
inline void depthSigns(const Eigen::Matrix3d& R, const Eigen::Vector3d& t, const Point2d* x1,
                       const Point2d* x2, int n, bool& front, bool& back)
{
    front = back = true;
    for (int i = 0; i < n && (front || back); ++i) {
        const Eigen::Vector3d a = R * Eigen::Vector3d(x1[i].x, x1[i].y, 1.0);
        const Eigen::Vector3d q2(x2[i].x, x2[i].y, 1.0);
        double depth1, depth2;
        if (!geometry::scaledDepths(a, q2, t, kMinCheiralityParallax, depth1, depth2)) continue;
        front &= depth1 > 0.0 && depth2 > 0.0;
        back &= depth1 < 0.0 && depth2 < 0.0;
    }
}

/** Whether one of the four poses (R, +-t), (R', +-t), with R' = (2 t t^T - I) R the twisted pair
and t a unit vector, puts every decided sample point in front of both cameras. */
inline bool anyPoseInFront(const Eigen::Matrix3d& R, const Eigen::Vector3d& t, const Point2d* x1,
                           const Point2d* x2, int n)
{
    bool front, back;
    depthSigns(R, t, x1, x2, n, front, back);
    if (front || back) return true;
    const Eigen::Matrix3d twisted = (2.0 * t * t.transpose() - Eigen::Matrix3d::Identity()) * R;
    depthSigns(twisted, t, x1, x2, n, front, back);
    return front || back;
}

} // namespace detail

/** Whether one of the four poses (R, +-t), (R', +-t) of E = [t]x R, with R' = (2 t t^T - I) R the
twisted pair, puts every sample point with a decided depth (kMinCheiralityParallax) in front of
both cameras. */
inline bool sampleIsInFront(const geometry::EssentialPose& pose, const Point2d* x1,
                            const Point2d* x2, int n)
{
    return detail::anyPoseInFront(pose.R, pose.t(), x1, x2, n);
}

/** Whether one of the four poses of the essential matrix E (any scale and sign) puts every sample
point with a decided depth in front of both cameras, as sampleIsInFront. False for a matrix without
a well-defined left null vector (zero or not finite). The search runs it on every solver's
solutions before they are scored: a minimal solver's wrong roots often fail it, and so do the models
of mixed samples that fit a wrong epipolar geometry with support (on a real pair whose model fitted
238 of 281 matches within 1 px, the best of its four poses had 42 of them in front). */
inline bool essentialSampleIsInFront(const Matx33d& E, const Point2d* x1, const Point2d* x2, int n)
{
    Eigen::Matrix3d e;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            e(r, c) = E(r, c);
    // t spans the left null space of E = [t]x R, orthogonal to every column: the largest cross
    // product of two columns is the best conditioned estimate of it.
    Eigen::Vector3d t = e.col(0).cross(e.col(1));
    const Eigen::Vector3d t12 = e.col(1).cross(e.col(2)), t20 = e.col(2).cross(e.col(0));
    if (t12.squaredNorm() > t.squaredNorm()) t = t12;
    if (t20.squaredNorm() > t.squaredNorm()) t = t20;
    const double tn = t.norm(), en = e.norm();
    if (!(tn > 0.0) || !(en > 0.0) || !std::isfinite(tn) || !std::isfinite(en)) return false;
    t /= tn;
    // With E / s = [t]x R (s = |E|_F / sqrt(2), up to sign), R = cof(E / s) - [t]x (E / s): the
    // cofactor matrix of [t]x R is t t^T R and -[t]x [t]x R = (I - t t^T) R. A sign flip of E
    // gives the twisted rotation, which anyPoseInFront tries as well. A closed form rather than
    // geometry::decomposeEssential's SVD, because this runs on every root before it is scored.
    const Eigen::Matrix3d es = e * (std::sqrt(2.0) / en);
    Eigen::Matrix3d cof;
    cof.row(0) = es.row(1).cross(es.row(2));
    cof.row(1) = es.row(2).cross(es.row(0));
    cof.row(2) = es.row(0).cross(es.row(1));
    Eigen::Matrix3d tx;
    tx << 0.0, -t.z(), t.y(), t.z(), 0.0, -t.x(), -t.y(), t.x(), 0.0;
    return detail::anyPoseInFront(cof - tx * es, t, x1, x2, n);
}

/** Keeps, in order, the first `count` solutions that pass essentialSampleIsInFront on the sample;
returns how many. */
inline int keepSolutionsInFront(Matx33d* solutions, int count, const Point2d* x1, const Point2d* x2,
                                int n)
{
    int kept = 0;
    for (int h = 0; h < count; ++h)
        if (essentialSampleIsInFront(solutions[h], x1, x2, n)) solutions[kept++] = solutions[h];
    return kept;
}

} // namespace solvers
} // namespace essential
} // namespace cv

#endif

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Cheirality of a minimal-set solution: can the sample's points lie in front of both cameras for
// one of the four poses of E? A five-point sample has up to ten exact solutions; the true one
// always passes, and most of the others do not.

#ifndef OPENCV_ESSENTIAL_SOLVERS_SAMPLE_CHEIRALITY_HPP
#define OPENCV_ESSENTIAL_SOLVERS_SAMPLE_CHEIRALITY_HPP

#include "geometry/depth_signs.hpp"
#include "geometry/essential_parameterisation.hpp"
#include "simd_dispatch.hpp"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>

namespace cv {
namespace essential {
namespace solvers {

/** Below this sine of the angle between the two rays of a point (its parallax) the sign of its
depth is not decided: with image noise of 0.001 normalised units (0.5 px at f = 500) the rays of a
point at infinity make angles of that order in either direction. Such points take no part. */
constexpr double kMinCheiralityParallax = 3e-3;

namespace detail {

/** Whether one of the four poses (R, +-t), (R', +-t), with R' = (2 t t^T - I) R the twisted pair
and t a unit vector, puts every decided sample point in front of both cameras. The four are tested
in one pass over the points, from one rotated ray a point (geometry::DepthProducts); the loop ends
as soon as no pose is left. */
ESSENTIAL_INLINE_INTO_CLONES bool anyPoseInFront(const Eigen::Matrix3d& R, const Eigen::Vector3d& t,
                                                 const Point2d* x1, const Point2d* x2, int n)
{
    const double minParallax2 = kMinCheiralityParallax * kMinCheiralityParallax;
    double r[9];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            r[3 * i + j] = R(i, j);
    const double tv[3] = {t.x(), t.y(), t.z()};
    bool front = true, back = true, twistedFront = true, twistedBack = true;
    for (int i = 0; i < n && (front || back || twistedFront || twistedBack); ++i) {
        const geometry::DepthProducts p =
            geometry::depthProducts(r, tv, x1[i].x, x1[i].y, x2[i].x, x2[i].y);
        if (p.decided(minParallax2)) {
            const double depth1 = p.depth1(), depth2 = p.depth2();
            front &= depth1 > 0.0 && depth2 > 0.0;
            back &= depth1 < 0.0 && depth2 < 0.0;
        }
        const geometry::DepthProducts w = p.twisted();
        if (w.decided(minParallax2)) {
            const double depth1 = w.depth1(), depth2 = w.depth2();
            twistedFront &= depth1 > 0.0 && depth2 > 0.0;
            twistedBack &= depth1 < 0.0 && depth2 < 0.0;
        }
    }
    return front || back || twistedFront || twistedBack;
}

} // namespace detail

/** Whether one of the four poses (R, +-t), (R', +-t) of E = [t]x R, with R' = (2 t t^T - I) R the
twisted pair, puts every sample point with a decided depth (kMinCheiralityParallax) in front of
both cameras. */
ESSENTIAL_INLINE_INTO_CLONES bool sampleIsInFront(const geometry::EssentialPose& pose,
                                                  const Point2d* x1, const Point2d* x2, int n)
{
    return detail::anyPoseInFront(pose.R, pose.t(), x1, x2, n);
}

/** Whether one of the four poses of the essential matrix E (any scale and sign) puts every sample
point with a decided depth in front of both cameras, as sampleIsInFront. False for a matrix without
a well-defined left null vector (zero or not finite). The search runs it on every solver's
solutions before they are scored: a minimal solver's wrong roots often fail it, and so do the models
of mixed samples that fit a wrong epipolar geometry with support (on a real pair whose model fitted
238 of 281 matches within 1 px, the best of its four poses had 42 of them in front). */
ESSENTIAL_INLINE_INTO_CLONES bool essentialSampleIsInFront(const Matx33d& E, const Point2d* x1,
                                                           const Point2d* x2, int n)
{
    const double* e = E.val; // row-major: e[3 r + c]
    // t spans the left null space of E = [t]x R, orthogonal to every column: the largest cross
    // product of two columns is the best conditioned estimate of it.
    auto columnCross = [e](int i, int j, double v[3]) {
        v[0] = e[3 + i] * e[6 + j] - e[6 + i] * e[3 + j];
        v[1] = e[6 + i] * e[j] - e[i] * e[6 + j];
        v[2] = e[i] * e[3 + j] - e[3 + i] * e[j];
        return v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    };
    double t[3], other[3];
    double t2 = columnCross(0, 1, t);
    for (int k = 1; k < 3; ++k) {
        const double o2 = columnCross(k, (k + 1) % 3, other);
        if (o2 > t2) {
            t2 = o2;
            std::copy(other, other + 3, t);
        }
    }
    double e2 = 0.0;
    for (int k = 0; k < 9; ++k)
        e2 += e[k] * e[k];
    const double tn = std::sqrt(t2), en = std::sqrt(e2);
    if (!(tn > 0.0) || !(en > 0.0) || !std::isfinite(tn) || !std::isfinite(en)) return false;
    for (double& v : t)
        v /= tn;
    // With E / s = [t]x R (s = |E|_F / sqrt(2), up to sign), R = cof(E / s) - [t]x (E / s): the
    // cofactor matrix of [t]x R is t t^T R and -[t]x [t]x R = (I - t t^T) R. A sign flip of E
    // gives the twisted rotation, which anyPoseInFront tries as well. A closed form rather than
    // geometry::decomposeEssential's SVD, because this runs on every root before it is scored.
    const double scale = std::sqrt(2.0) / en;
    double es[9];
    for (int k = 0; k < 9; ++k)
        es[k] = e[k] * scale;
    Eigen::Matrix3d R;
    for (int r = 0; r < 3; ++r) {
        const double* a = es + 3 * ((r + 1) % 3);
        const double* b = es + 3 * ((r + 2) % 3);
        R(r, 0) = a[1] * b[2] - a[2] * b[1];
        R(r, 1) = a[2] * b[0] - a[0] * b[2];
        R(r, 2) = a[0] * b[1] - a[1] * b[0];
    }
    for (int c = 0; c < 3; ++c) { // minus t x (column c of E / s)
        R(0, c) -= t[1] * es[6 + c] - t[2] * es[3 + c];
        R(1, c) -= t[2] * es[c] - t[0] * es[6 + c];
        R(2, c) -= t[0] * es[3 + c] - t[1] * es[c];
    }
    return detail::anyPoseInFront(R, Eigen::Vector3d(t[0], t[1], t[2]), x1, x2, n);
}

/** Keeps, in order, the first `count` solutions that pass essentialSampleIsInFront on the sample;
returns how many. Out of line (sample_cheirality.cpp) in a SIMD clone: the search runs it on every
root of every sample. */
int keepSolutionsInFront(Matx33d* solutions, int count, const Point2d* x1, const Point2d* x2,
                         int n);

} // namespace solvers
} // namespace essential
} // namespace cv

#endif

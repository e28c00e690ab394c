// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Cheirality test for the four poses of an essential matrix. Each correspondence is triangulated by
// the two-view least-squares depths (z1, z2) that best satisfy z2 q2 = z1 R q1 + t; a point counts
// for a pose when both depths are positive. There is deliberately no far-point cut: a point at any
// distance in front of both cameras counts, so that deep scenes seen from a short baseline still
// decide the sign of t (cv::recoverPose in OpenCV 4.6 ignores points beyond 50 baselines).

#include "pose/pose_recovery.hpp"

#include "geometry/essential_decomposition.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace cv {
namespace essential {
namespace pose {

namespace {

/** Whether the correspondence (q1, q2), homogeneous with last coordinate 1, has positive depth in
both views for the pose (R, t), X2 = R X1 + t.

With a = R q1 and b = q2 the depths minimise |z1 a + t - z2 b|^2, whose normal equations are
    [ a.a  -a.b ] [z1]   [ -a.t ]
    [ -a.b  b.b ] [z2] = [  b.t ].
Their determinant d = |a|^2 |b|^2 - (a.b)^2 = |a x b|^2 is >= 0, so the signs of the depths are
those of the numerators of Cramer's rule; parallel rays (d = 0) have no depth and never count. */
inline bool inFront(const Eigen::Matrix3d& R, const Eigen::Vector3d& t, const Point2d& q1,
                    const Point2d& q2)
{
    const Eigen::Vector3d a = R * Eigen::Vector3d(q1.x, q1.y, 1.0);
    const Eigen::Vector3d b(q2.x, q2.y, 1.0);
    const double aa = a.dot(a), bb = b.dot(b), ab = a.dot(b);
    const double at = a.dot(t), bt = b.dot(t);
    const double det = aa * bb - ab * ab;
    if (!(det > 0.0)) return false;
    const double z1 = ab * bt - at * bb; // times det
    const double z2 = aa * bt - ab * at; // times det
    return z1 > 0.0 && z2 > 0.0;
}

} // namespace

bool poseCandidates(const Matx33d& E, Eigen::Matrix3d& R1, Eigen::Matrix3d& R2, Eigen::Vector3d& t)
{
    Eigen::Matrix3d Ee;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            Ee(i, j) = E(i, j);
    if (!geometry::decomposeEssential(Ee, R1, R2, t) || !t.allFinite() || !(t.norm() > 0.0))
        return false;
    t.normalize();
    return true;
}

bool recoverPoseNormalised(const Matx33d& E, const Problem& points, const uchar* maskIn,
                           uchar* maskOut, PoseResult& out)
{
    const int n = points.size();
    Eigen::Matrix3d R1, R2;
    Eigen::Vector3d t;
    if (!poseCandidates(E, R1, R2, t)) {
        if (maskOut)
            for (int i = 0; i < n; ++i)
                maskOut[i] = 0;
        return false;
    }

    // The candidates in the order cv::recoverPose tries them; ties go to the first, as there.
    const Eigen::Matrix3d* rotations[4] = {&R1, &R2, &R1, &R2};
    const Eigen::Vector3d translations[4] = {t, t, -t, -t};
    int counts[4] = {0, 0, 0, 0};
    for (int i = 0; i < n; ++i) {
        if (maskIn && !maskIn[i]) continue;
        for (int c = 0; c < 4; ++c)
            if (inFront(*rotations[c], translations[c], points.point1(i), points.point2(i)))
                ++counts[c];
    }
    const int best = static_cast<int>(std::max_element(counts, counts + 4) - counts);

    if (maskOut) {
        // maskOut may alias maskIn: read each entry before writing it.
        for (int i = 0; i < n; ++i) {
            const bool used = !maskIn || maskIn[i] != 0;
            maskOut[i] = (used && inFront(*rotations[best], translations[best], points.point1(i),
                                          points.point2(i)))
                             ? uchar(1)
                             : uchar(0);
        }
    }
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
            out.R(i, j) = (*rotations[best])(i, j);
        out.t[i] = translations[best][i];
    }
    out.inFront = counts[best];
    return true;
}

} // namespace pose
} // namespace essential
} // namespace cv

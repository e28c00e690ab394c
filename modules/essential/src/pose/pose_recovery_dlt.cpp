// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "pose/pose_recovery_dlt.hpp"

#include <Eigen/Core>
#include <Eigen/SVD>

#include <algorithm>
#include <vector>

namespace cv {
namespace essential {
namespace pose {

Vec4d triangulateDlt(const Matx33d& R, const Vec3d& t, const Point2d& q1, const Point2d& q2)
{
    // Rows of P = [I | 0] and P' = [R | t].
    Eigen::Matrix4d A;
    A.row(0) << -1.0, 0.0, q1.x, 0.0;
    A.row(1) << 0.0, -1.0, q1.y, 0.0;
    for (int k = 0; k < 4; ++k) {
        const double p1 = k < 3 ? R(0, k) : t[0];
        const double p2 = k < 3 ? R(1, k) : t[1];
        const double p3 = k < 3 ? R(2, k) : t[2];
        A(2, k) = q2.x * p3 - p1;
        A(3, k) = q2.y * p3 - p2;
    }
    const Eigen::JacobiSVD<Eigen::Matrix4d> svd(A, Eigen::ComputeFullV);
    Eigen::Vector4d X = svd.matrixV().col(3);
    if (X[3] < 0) X = -X;
    return Vec4d(X[0], X[1], X[2], X[3]);
}

namespace {

/** OpenCV's test for one pose: positive depth in view 1 (Z W > 0), both depths below the
threshold, positive depth in view 2. A point at infinity (W = 0) never counts. */
bool counts(const Matx33d& R, const Vec3d& t, const Vec4d& X, double distanceThresh)
{
    if (!(X[2] * X[3] > 0)) return false;
    const Vec3d P1(X[0] / X[3], X[1] / X[3], X[2] / X[3]);
    if (!(P1[2] < distanceThresh)) return false;
    const Vec3d P2 = R * P1 + t;
    return P2[2] > 0 && P2[2] < distanceThresh;
}

} // namespace

bool recoverPoseDistanceThresh(const Matx33d& E, const Problem& points, const uchar* maskIn,
                               double distanceThresh, uchar* maskOut, Vec4d* triangulated,
                               PoseResult& out)
{
    const int n = points.size();
    Eigen::Matrix3d R1e, R2e;
    Eigen::Vector3d te;
    if (!poseCandidates(E, R1e, R2e, te)) {
        if (maskOut) std::fill(maskOut, maskOut + n, uchar(0));
        return false;
    }
    Matx33d R1, R2;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            R1(i, j) = R1e(i, j);
            R2(i, j) = R2e(i, j);
        }
    const Vec3d t(te[0], te[1], te[2]);

    // The candidates in the order cv::recoverPose tries them; ties go to the first, as there.
    const Matx33d rotations[4] = {R1, R2, R1, R2};
    const Vec3d translations[4] = {t, t, -t, -t};
    std::vector<uchar> inFront(4 * static_cast<size_t>(n), 0);
    int counted[4] = {0, 0, 0, 0};
    for (int c = 0; c < 4; ++c)
        for (int i = 0; i < n; ++i) {
            if (maskIn && !maskIn[i]) continue;
            const Vec4d X =
                triangulateDlt(rotations[c], translations[c], points.point1(i), points.point2(i));
            if (counts(rotations[c], translations[c], X, distanceThresh)) {
                inFront[static_cast<size_t>(c) * n + i] = 1;
                ++counted[c];
            }
        }
    const int best = static_cast<int>(std::max_element(counted, counted + 4) - counted);
    if (maskOut)
        std::copy(inFront.begin() + static_cast<long>(best) * n,
                  inFront.begin() + static_cast<long>(best + 1) * n, maskOut);
    if (triangulated)
        for (int i = 0; i < n; ++i)
            triangulated[i] = triangulateDlt(rotations[best], translations[best], points.point1(i),
                                             points.point2(i));
    out.R = rotations[best];
    out.t = translations[best];
    out.inFront = counted[best];
    return true;
}

} // namespace pose
} // namespace essential
} // namespace cv

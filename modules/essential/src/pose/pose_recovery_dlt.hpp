// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The cheirality test of cv::recoverPose's distanceThresh form: each correspondence triangulated
// by the linear (DLT) method of cv::triangulatePoints, a point counting for a pose when its depth
// is positive and below distanceThresh in both views. The module's other recoverPose overloads
// use pose_recovery.hpp instead (least-squares depths, no distance cut, one SVD per call instead
// of one per point and pose).

#ifndef OPENCV_ESSENTIAL_POSE_POSE_RECOVERY_DLT_HPP
#define OPENCV_ESSENTIAL_POSE_POSE_RECOVERY_DLT_HPP

#include "pose/pose_recovery.hpp"

#include <opencv2/core.hpp>

namespace cv {
namespace essential {
namespace pose {

/** The homogeneous point X (X2 = R X1 + t) whose projections best fit the normalised points q1, q2
in the algebraic sense of the DLT: the right singular vector of the smallest singular value of the
4 x 4 system [x1 p3 - p1; y1 p3 - p2; x2 p3' - p1'; y2 p3' - p2'] built from the rows of
P = [I | 0] and P' = [R | t], as cv::triangulatePoints. Unit norm, with W >= 0. */
Vec4d triangulateDlt(const Matx33d& R, const Vec3d& t, const Point2d& q1, const Point2d& q2);

/** Chooses among the four poses of E the one with the most points in front of both cameras and
closer than distanceThresh in both (depths in units of the baseline, |t| = 1), every point
triangulated by triangulateDlt. Same arguments and result as recoverPoseNormalised; if
`triangulated` is not null it receives the n homogeneous points of the chosen pose. */
bool recoverPoseDistanceThresh(const Matx33d& E, const Problem& points, const uchar* maskIn,
                               double distanceThresh, uchar* maskOut, Vec4d* triangulated,
                               PoseResult& out);

} // namespace pose
} // namespace essential
} // namespace cv

#endif

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Relative pose from an essential matrix: the SVD decomposition's four (R, +-t) candidates and the
// cheirality test that picks one, on normalised points.

#ifndef OPENCV_ESSENTIAL_POSE_POSE_RECOVERY_HPP
#define OPENCV_ESSENTIAL_POSE_POSE_RECOVERY_HPP

#include "input/problem.hpp"

#include <opencv2/core.hpp>

#include <Eigen/Core>

namespace cv {
namespace essential {
namespace pose {

struct PoseResult
{
    Matx33d R = Matx33d::eye();
    Vec3d t = Vec3d(0, 0, 0);
    int inFront = 0; //!< points (among those masked in) with positive depth in both views
};

/** The two rotations and the unit translation of E (its four pose candidates are (R1 or R2, +-t)),
the start of both pose recoveries; false when E has no such decomposition (zero, non-finite, or a
translation that is not finite and non-zero). */
bool poseCandidates(const Matx33d& E, Eigen::Matrix3d& R1, Eigen::Matrix3d& R2, Eigen::Vector3d& t);

/** Chooses among the four poses of E the one with the most points in front of both cameras.

@param E essential matrix.
@param points the normalised correspondences (n = points.size()).
@param maskIn if not null, only points with maskIn[i] != 0 take part.
@param maskOut if not null, set to 1 for the points that take part and lie in front of both cameras
for the chosen pose, 0 otherwise (may alias maskIn).
@return false if E cannot be decomposed (then `out` is untouched and maskOut is zeroed). */
bool recoverPoseNormalised(const Matx33d& E, const Problem& points, const uchar* maskIn,
                           uchar* maskOut, PoseResult& out);

} // namespace pose
} // namespace essential
} // namespace cv

#endif

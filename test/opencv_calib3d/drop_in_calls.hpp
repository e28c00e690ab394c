// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The names that OpenCV's own calib3d tests call after rename_calls.cmake has rewritten them:
// cv::findEssentialMat becomes cv::essential::findEssentialMatIter (the module has every overload
// of it), cv::recoverPose becomes essential_drop_in::recoverPose, which is the module's
// cv::essential::recoverPose plus the one overload of OpenCV 4.6's recoverPose that the tests call
// and the module does not have.

#ifndef ESSENTIAL_TEST_OPENCV_CALIB3D_DROP_IN_CALLS_HPP
#define ESSENTIAL_TEST_OPENCV_CALIB3D_DROP_IN_CALLS_HPP

#include <opencv2/essential.hpp>

namespace essential_drop_in {

using cv::essential::recoverPose;

/** OpenCV 4.6's recoverPose(points1, points2, cameraMatrix1, distCoeffs1, cameraMatrix2,
distCoeffs2, E, R, t, method, prob, threshold, mask), which estimates E and the pose of two
different cameras in one call. The module has no such overload; this is the composition that OpenCV
itself runs, made of the module's two drop-in functions: E from findEssentialMatIter's two-camera
overload (the same arguments), then recoverPose on the points undistorted by their own camera,
with the identity camera matrix and the mask of the E estimate. */
int recoverPose(cv::InputArray points1, cv::InputArray points2, cv::InputArray cameraMatrix1,
                cv::InputArray distCoeffs1, cv::InputArray cameraMatrix2,
                cv::InputArray distCoeffs2, cv::OutputArray E, cv::OutputArray R, cv::OutputArray t,
                int method = cv::RANSAC, double prob = 0.999, double threshold = 1.0,
                cv::InputOutputArray mask = cv::noArray());

} // namespace essential_drop_in

#endif // ESSENTIAL_TEST_OPENCV_CALIB3D_DROP_IN_CALLS_HPP

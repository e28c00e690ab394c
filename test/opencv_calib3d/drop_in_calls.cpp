// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "drop_in_calls.hpp"

#include <opencv2/calib3d.hpp>

namespace essential_drop_in {

int recoverPose(cv::InputArray points1, cv::InputArray points2, cv::InputArray cameraMatrix1,
                cv::InputArray distCoeffs1, cv::InputArray cameraMatrix2,
                cv::InputArray distCoeffs2, cv::OutputArray E, cv::OutputArray R, cv::OutputArray t,
                int method, double prob, double threshold, cv::InputOutputArray mask)
{
    const cv::Mat essential = cv::essential::findEssentialMatIter(
        points1, points2, cameraMatrix1, distCoeffs1, cameraMatrix2, distCoeffs2, method, prob,
        threshold, mask);
    // Normalised image coordinates: the pose step then needs no camera matrix.
    cv::Mat normalised1, normalised2;
    cv::undistortPoints(points1, normalised1, cameraMatrix1, distCoeffs1);
    cv::undistortPoints(points2, normalised2, cameraMatrix2, distCoeffs2);
    essential.copyTo(E);
    return cv::essential::recoverPose(essential, normalised1, normalised2,
                                      cv::Mat::eye(3, 3, CV_64F), R, t, mask);
}

} // namespace essential_drop_in

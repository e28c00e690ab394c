// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The pieces of findEssentialMatIter that the two-camera recoverPose shares (find_essential.cpp):
// the estimate from two cameras with distortion (and, through input/params_from_opencv.hpp, the
// drop-in settings of OpenCV's arguments).

#ifndef OPENCV_ESSENTIAL_DROP_IN_ESTIMATE_HPP
#define OPENCV_ESSENTIAL_DROP_IN_ESTIMATE_HPP

#include "input/mask_output.hpp"
#include "input/params_from_opencv.hpp"
#include "input/point_layouts.hpp"

#include "opencv2/essential/params.hpp"

#include <opencv2/core.hpp>

#include <vector>

namespace cv {
namespace essential {

/** E from two cameras, each view undistorted and normalised with its own camera matrix and
distortion, the pixel threshold converted with the mean focal length of the two cameras (as
OpenCV). Points are read as `reading` says, the mask written as `maskWriting` says. If not null,
normalised1 / normalised2 receive the undistorted normalised points. */
Mat estimateTwoCameras(InputArray points1, InputArray points2, InputArray cameraMatrix1,
                       InputArray distCoeffs1, InputArray cameraMatrix2, InputArray distCoeffs2,
                       const EssentialParams& params, PointReading reading, OutputArray mask,
                       MaskWriting maskWriting, std::vector<Point2d>* normalised1 = nullptr,
                       std::vector<Point2d>* normalised2 = nullptr);

} // namespace essential
} // namespace cv

#endif

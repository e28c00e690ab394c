// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The module's settings from OpenCV's arguments: the method flag, prob, threshold and maxIters of
// the drop-in overloads, or a UsacParams (the mapping documented in essential.hpp).

#ifndef OPENCV_ESSENTIAL_INPUT_PARAMS_FROM_OPENCV_HPP
#define OPENCV_ESSENTIAL_INPUT_PARAMS_FROM_OPENCV_HPP

#include "opencv2/essential/params.hpp"

#include <opencv2/calib3d.hpp>

namespace cv {
namespace essential {

/** The settings of a drop-in overload from OpenCV's method, prob, threshold and maxIters (the
table in essential.hpp); throws StsBadArg naming an invalid argument. */
EssentialParams dropInParams(int method, double prob, double threshold, int maxIters);

/** The settings of the UsacParams overload; throws StsBadArg naming an invalid field. */
EssentialParams usacParams(const UsacParams& usac);

} // namespace essential
} // namespace cv

#endif

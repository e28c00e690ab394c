// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Checks of the module's own settings and of distortion coefficients: a cv::Exception naming the
// field or argument, before anything is estimated.

#ifndef OPENCV_ESSENTIAL_INPUT_CHECK_PARAMS_HPP
#define OPENCV_ESSENTIAL_INPUT_CHECK_PARAMS_HPP

#include "opencv2/essential/params.hpp"

#include <opencv2/core.hpp>

#include <cmath>

namespace cv {
namespace essential {

/** Whether a call has a time budget: a positive finite timeBudgetMs (0 and +inf mean none). */
inline bool hasTimeBudget(const EssentialParams& params)
{
    return params.timeBudgetMs > 0 && std::isfinite(params.timeBudgetMs);
}

/** Throws StsBadArg (a value out of range) or StsNotImplemented (a combination the module does not
have) naming the EssentialParams field. */
void checkEssentialParams(const EssentialParams& params);

/** Throws StsBadArg unless `d` is empty or holds 4, 5, 8, 12 or 14 finite coefficients of any
depth cv::undistortPoints converts; `name` is the argument's name in the message. */
void checkDistortion(InputArray d, const char* name);

} // namespace essential
} // namespace cv

#endif

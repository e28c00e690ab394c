// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// EssentialReport's degeneracy fields for an accepted estimate: how much of its support a rotation
// alone or a homography explains, and whether that makes the estimate degenerate.

#ifndef OPENCV_ESSENTIAL_DEGENERACY_DEGENERACY_REPORT_HPP
#define OPENCV_ESSENTIAL_DEGENERACY_DEGENERACY_REPORT_HPP

#include "input/problem.hpp"

#include "opencv2/essential/params.hpp"

#include <opencv2/core.hpp>

namespace cv {
namespace essential {
namespace degeneracy {

/** Sets report.rotationOnlyFraction, homographyFraction and degenerate from the inliers of the
estimate (`threshold` is its inlier threshold, normalised units). */
void reportDegeneracy(const Problem& problem, const uchar* inliers, double threshold,
                      EssentialReport& report);

} // namespace degeneracy
} // namespace essential
} // namespace cv

#endif

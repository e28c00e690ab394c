// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Is the winner's support more than chance? Any five correspondences fit some essential matrix
// exactly, and among thousands of hypotheses the best collects a few more inliers by luck even on
// data with no geometry at all (independent random points). Returning that model would be a silent
// wrong answer; this test rejects it.

#ifndef OPENCV_ESSENTIAL_DEGENERACY_SUPPORT_TEST_HPP
#define OPENCV_ESSENTIAL_DEGENERACY_SUPPORT_TEST_HPP

#include "input/problem.hpp"

#include <opencv2/core.hpp>

#include <vector>

namespace cv {
namespace essential {
namespace degeneracy {

/** The chance inlier rate of E on this data: the fraction of deliberately wrong pairs
(q1[i], q2[(i + shift) mod N], for a few shifts) within the threshold. It accounts for how the
points are spread in both images, which an analytic rate would have to assume. */
double chanceInlierRate(const Matx33d& E, const Problem& problem, InlierTest test);

/** True when `inliers` (which include the `sampleSize` points the model was fitted to) exceed what
the best of `hypotheses` random models would reach by chance: with the chance rate p from
chanceInlierRate(), the extra inliers X ~ Poisson((N - sampleSize) p), and the support is
significant when P(X >= inliers - sampleSize) <= alpha / hypotheses (Bonferroni over the
hypotheses, alpha = 0.01). When N is so small that even all points being inliers could not pass,
the test has no power and the model is accepted (as cv::findEssentialMat would). */
bool supportIsSignificant(const Matx33d& E, const Problem& problem, InlierTest test, int inliers,
                          int sampleSize, int hypotheses);

/** The least inlier count (sample included) that supportIsSignificant() accepts for E with
`hypotheses` hypotheses tried; -1 when the test has no power (every count is accepted). */
int significantInliers(const Matx33d& E, const Problem& problem, InlierTest test, int sampleSize,
                       int hypotheses);

/** Five correspondences are a minimal set: an essential matrix fits any five exactly. */
constexpr int kMinimalSample = 5;

/** Whether the inliers hold more than `count` (<= kMinimalSample) distinct correspondences.
Repeated correspondences add no constraint: five distinct points given twelve times each are fitted
exactly by up to ten essential matrices, and 60 "inliers" of one of them are no evidence (the
chance-support test counts points, not distinct ones). Stops at the first count + 1 distinct ones,
so on ordinary data it looks at a handful of points. */
bool moreDistinctInliersThan(const Problem& problem, const std::vector<uchar>& mask, int count);

} // namespace degeneracy
} // namespace essential
} // namespace cv

#endif

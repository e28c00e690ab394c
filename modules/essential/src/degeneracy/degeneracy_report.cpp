// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "degeneracy/degeneracy_report.hpp"

#include "degeneracy/degeneracy.hpp"

namespace cv {
namespace essential {
namespace degeneracy {

namespace {

/** EssentialReport::degenerate: an inlier counts as explained by a rotation alone (or by a
homography) when its image-2 position is within this many Sampson thresholds of the rotated ray (or
mapped point) of image 1: the same noise gives a transfer distance in one image of about twice the
Sampson distance, which splits the error between both images. */
constexpr double kRotationOnlyDistance = 2.0;

/** ... and the estimate is degenerate when at least this fraction of its inliers is so explained.
Measured (test/test_degenerate_scenes.cpp, 300 points, 0.5 px noise, 10 scenes each): pure rotation
and baselines of 1e-4 give rotation-only fractions of 0.976 to 0.997 (the remainder is noise beyond
twice the threshold), planes and single-depth scenes homography fractions of 0.968 to 1; a baseline
of 0.05 gives at most 0.11 and 0.31, and 120 problems of the synthetic protocol at most 0.036 and
0.093. */
constexpr double kDegenerateFraction = 0.9;

} // namespace

void reportDegeneracy(const Problem& problem, const uchar* inliers, double threshold,
                      EssentialReport& report)
{
    report.rotationOnlyFraction =
        rotationOnlyFraction(problem, inliers, kRotationOnlyDistance * threshold);
    report.homographyFraction =
        homographyFraction(problem, inliers, kRotationOnlyDistance * threshold);
    report.degenerate = report.rotationOnlyFraction >= kDegenerateFraction ||
                        report.homographyFraction >= kDegenerateFraction;
}

} // namespace degeneracy
} // namespace essential
} // namespace cv

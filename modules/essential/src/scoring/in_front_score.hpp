// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
// The MSAC score that counts a point as an inlier only when it also lies in front of both cameras.
// An essential matrix fits a correspondence whatever the sign of the depths, so a wrong model can
// collect inliers that no pose of it places in front of the cameras; on real pairs such a model can
// have a lower plain MSAC cost than the true one (castle-P30 0023-0024 in docs/REAL_PAIRS.md: 8% of
// its inliers behind a camera, 14.9 degrees off). This score is for a second search when the winner
// of the first has that many inliers behind (pipeline/estimate.cpp): it decomposes each hypothesis
// that survives the plain score's early exit, so it costs more per hypothesis than scoreMsac.
#ifndef OPENCV_ESSENTIAL_SCORING_IN_FRONT_SCORE_HPP
#define OPENCV_ESSENTIAL_SCORING_IN_FRONT_SCORE_HPP

#include "input/problem.hpp"
#include "scoring/msac_score.hpp"

#include <opencv2/core.hpp>

namespace cv {
namespace essential {
namespace scoring {

/** The MSAC cost of E where an inlier behind either camera costs threshold^2 like an outlier, for
the pose of E ((R1 or R2) with (t or -t), geometry/essential_decomposition.hpp) that gives the
lowest such cost; `inliers` counts the inliers in front under that pose. Never below
scoreMsac(E, problem): a hypothesis whose plain cost reaches bestCost is returned with that plain
score (cost >= bestCost) without being decomposed. An E that cannot be decomposed costs N
threshold^2 with no inliers. */
Score scoreMsacInFront(const Matx33d& E, const Problem& problem, InlierTest test,
                       double bestCost = HUGE_VAL);

/** Of E's inliers (squared distance at most threshold^2, as inlierMask), how many lie in front of
both cameras under the pose that places the most of them there (0 if E cannot be decomposed). */
int inliersInFront(const Matx33d& E, const Problem& problem, InlierTest test);

} // namespace scoring
} // namespace essential
} // namespace cv

#endif

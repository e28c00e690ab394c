// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// MSAC scoring: the sum over all points of the squared inlier distance (the problem's: Sampson or
// symmetric epipolar) truncated at the squared threshold (Torr and Zisserman). Lower is better; an
// inlier is a point under the threshold.

#ifndef OPENCV_ESSENTIAL_SCORING_MSAC_SCORE_HPP
#define OPENCV_ESSENTIAL_SCORING_MSAC_SCORE_HPP

#include "input/problem.hpp"
#include "scoring/sprt.hpp"

#include <opencv2/core.hpp>

namespace cv {
namespace essential {
namespace scoring {

struct Score
{
    double cost = HUGE_VAL; //!< truncated sum of squared inlier distances
    int inliers = 0;        //!< points with squared distance at most threshold^2 (as OpenCV)
    int scored = 0; //!< points whose distance was computed (fewer than N after an early exit)
};

/** Scores E on all points under `test`. Gives up (returning a cost >= bestCost) as soon as the
partial cost reaches bestCost: a hypothesis that cannot win needs no exact score. */
Score scoreMsac(const Matx33d& E, const Problem& problem, InlierTest test,
                double bestCost = HUGE_VAL);

/** The MSAC score of E on the points [begin, end) only (for preemptive scoring block by block),
with the same early exit at bestCost. */
Score scoreMsacRange(const Matx33d& E, const Problem& problem, InlierTest test, int begin, int end,
                     double bestCost = HUGE_VAL);

/** MSAC scoring with Wald's SPRT (scoring/sprt.hpp): the points are checked in order and the
log-likelihood ratio of `sprt` accumulated point by point; as soon as it exceeds sprt.logA the
hypothesis is rejected (`rejected` set, the returned Score counting the points checked and the
inliers among them). The MSAC early exit at bestCost applies as well (checked every 16 points). */
Score scoreMsacSprt(const Matx33d& E, const Problem& problem, InlierTest test, double bestCost,
                    const SprtTest& sprt, bool& rejected);

/** Squared Sampson distance of every point to E, whatever the call's inlier distance (LMedS
ranks by it, as OpenCV's LMEDS does). */
void sampsonErrors(const Matx33d& E, const Problem& problem, double* errors);

/** Squared distance (test.distance) of every point to E. */
void squaredDistances(const Matx33d& E, const Problem& problem, InlierTest test, double* errors);

/** The distances of all points to E in bands one threshold wide: counts[k] is the number of points
with k t < distance <= (k + 1) t (band 0 holds the inliers, distance 0 included), for k < `bands`;
farther points are not counted. For termination::NoiseAdaptedRatio. */
void distanceBands(const Matx33d& E, const Problem& problem, InlierTest test, int bands,
                   int* counts);

/** Writes mask[i] = 1 for the inliers of E under `test`, 0 otherwise; returns their number. */
int inlierMask(const Matx33d& E, const Problem& problem, InlierTest test, uchar* mask);

} // namespace scoring
} // namespace essential
} // namespace cv

#endif

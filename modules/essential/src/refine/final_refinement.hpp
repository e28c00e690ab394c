// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The final estimate: which correspondences the last refinement of the search winner sees, and
// with which loss. docs/ACCURACY.md has the measurements behind every choice here.

#ifndef OPENCV_ESSENTIAL_REFINE_FINAL_REFINEMENT_HPP
#define OPENCV_ESSENTIAL_REFINE_FINAL_REFINEMENT_HPP

#include "input/problem.hpp"
#include "refine/irls_refinement.hpp"

#include <opencv2/core.hpp>

namespace cv {
namespace essential {
namespace refine {

/** Measured with bench/essential_accuracy_candidates (docs/ACCURACY.md, "Analysis"): every
candidate starts from the same search winners, 300-400 problems of the synthetic protocol per
inlier ratio, AUC@1 of max(rotation, translation direction) error. */
struct FinalRefinementSettings
{
    /** The noise level sigma of the Sampson distances is estimated (estimateNoise) from the points
    within this many thresholds of the search winner; 0: not estimated, assumedNoise is used. A
    threshold is usually set at about twice the noise, but not always: with the wide-camera
    variant (noise 1.66 px) and OpenCV's default threshold of 1 px, a band and a loss set by the
    threshold cut the inliers' distribution at 0.6 sigma and AUC@1 falls to 0.58 / 0.41 at 90 / 50%
    inliers, where the estimated sigma gives 0.79 / 0.70 (the best selection, the true inliers by
    least squares: 0.81 / 0.73). */
    double noiseWindow = 4.0;
    /** Fewer points than this in the window: sigma is not estimated. */
    int minNoisePoints = 20;
    /** sigma in thresholds when it is not estimated. */
    double assumedNoise = 0.5;
    /** The refinement sees the points within max(minBand thresholds, bandInSigmas sigma) of the
    search winner. Not the winner's inliers: the winner is off by about 0.15 degrees, and the
    points within one threshold of a model that is off are a sample biased towards it, which a
    refinement on them alone cannot leave (AUC@1 at 90% inliers: 0.908 on the winner's inliers,
    0.940 within 2 thresholds). Bands of 2 and 3 thresholds were within 0.002 of each other, 2
    ahead at every inlier ratio; 3 to 5 sigmas within 0.004. */
    double minBand = 2.0;
    double bandInSigmas = 4.0;
    /** ... and only those in front of both cameras for the winner's pose (the cheirality vote of
    pose::recoverPoseNormalised): about half the wrong matches that fall near their epipolar line
    are behind a camera. AUC@1 at 25% inliers 0.823 without, 0.869 with. */
    bool inFrontOnly = true;
    /** Loss: Tukey's biweight at scale tukeyInSigmas sigma (0: Cauchy, below) from round
    firstTukeyRound on. A wrong match near its epipolar line pulls a Cauchy minimum (by c^2 / s at
    distance s); Tukey's weight is 0 beyond c and small near it, so on noise-free data the pose is
    exact unless a wrong match lies within c of its epipolar line (test_final_refinement.cpp: exact
    on 8 and 9 of 10 scenes with 30% and 60% wrong matches, the final step before this one on none
    of them). 4.685 sigma is the usual 95%-efficiency constant (3.5
    and 6 were worse by up to 0.015 and 0.006 AUC@1). One Tukey round from the search winner
    against Cauchy (one round, 2 sigma): AUC@1 0.944 / 0.917 / 0.875 against 0.944 / 0.916 / 0.866
    at 90 / 50 / 25% inliers, 0.799 / 0.711 against 0.792 / 0.696 with the wide camera; the same
    from search winners without local optimisation (0.943 / 0.911). */
    double tukeyInSigmas = 4.685;
    int firstTukeyRound = 0;
    /** ... but never below minTukeyScale thresholds: the threshold is the caller's statement of
    the noise level, and an estimate far below it is more likely wrong than right. With
    pixel-quantised corners and a tiny motion (rail-a, forward, one frame apart) most points do not
    move at all and fit every E with the right rotation: the median distance comes out at 0.01 px,
    a loss that narrow sees only those points, and the translation flipped on 2 of 12 pairs (on 1
    with a floor of 0.5, on none with 0.75 or 1). The floor does not bind on the synthetic protocol
    (noise 0.5 px: 4.685 sigma = 2.3 thresholds); on noise-free data it lets the wrong matches
    within one threshold of their epipolar line pull (without it: exact on all 20 scenes above). */
    double minTukeyScale = 1.0;
    /** Cauchy scale for the rounds before firstTukeyRound: max(minScale thresholds, scaleInSigmas
    sigma). 1 threshold (2 sigmas) beat 0.5 by 0.005 AUC@1 on average over 90/70/50/25% inliers;
    1.5 was no better. */
    double minScale = 1.0;
    double scaleInSigmas = 2.0;
    /** Rounds of selection and refinement, each around the last one's result: another one (up to
    maxRounds) when the noise estimated around the result is below nextRoundBelow times the noise
    the round was set up with. A start that is off inflates the noise estimate, and the band and
    the loss follow it; the search winners do not (one round, whose result a second round changed
    by -0.001 to +0.002 AUC@1 for a second refinement's time), starts 0.1 to 0.3 degrees off the
    truth do (test_final_refinement.cpp). */
    int maxRounds = 2;
    double nextRoundBelow = 0.8;
    /** The IRLS's cap and stopping rule (IrlsSettings): on these points, caps from 5 to 100 and
    relative tolerances from 1e-6 to 1e-10 gave AUC@1 within 0.002 of each other. */
    IrlsSettings irls;
};

struct FinalRefinementResult
{
    Matx33d E;
    int iterations = 0;    //!< IRLS iterations over all rounds
    int rounds = 0;        //!< rounds run
    int pointsUsed = 0;    //!< correspondences the last refinement saw
    double noise = 0.0;    //!< sigma used (normalised units)
    bool improved = false; //!< a refinement lowered its cost (E differs from the start)
};

/** Robust estimate of the noise of the Sampson distances to E: 1.4826 times the median distance
of the points within `window` thresholds of E; 0 if fewer than minPoints are. */
double estimateNoise(const Problem& problem, const Matx33d& E, double threshold, double window,
                     int minPoints);

/** Refines E0, the search winner for the inlier test `test` (the threshold in normalised units;
the distance selects the points near E0, the robust cost is on the Sampson distance), as
FinalRefinementSettings describes: the points near E0 (and in front of both cameras for its pose)
by IRLS with a robust loss whose scale follows the estimated noise. Fewer than 5 such points leave
E0 unchanged. */
FinalRefinementResult
refineFinal(const Problem& problem, const Matx33d& E0, InlierTest test,
            const FinalRefinementSettings& settings = FinalRefinementSettings());

} // namespace refine
} // namespace essential
} // namespace cv

#endif

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The final estimate: which correspondences the last refinement of the search winner sees, and
// with which loss. docs/ACCURACY.md has the measurements behind every choice here.

#ifndef OPENCV_ESSENTIAL_REFINE_FINAL_REFINEMENT_HPP
#define OPENCV_ESSENTIAL_REFINE_FINAL_REFINEMENT_HPP

#include "problem.hpp"
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
    /** Cauchy scale: max(minScale thresholds, scaleInSigmas sigma). With the outliers' pull gone
    (the points above) a wider loss keeps more of the inliers' information: 1 threshold (2 sigmas)
    beats 0.5 by 0.005 AUC@1 on average over 90/70/50/25% inliers, 1.5 is no better. The floor
    keeps the loss from shrinking to nothing on noise-free data. */
    double minScale = 1.0;
    double scaleInSigmas = 2.0;
    /** Selections and refinements, each selecting around the last one's result: a second round
    changed AUC@1 by -0.001 to +0.004 for 50% more time, so one. */
    int rounds = 1;
    /** The IRLS's cap and stopping rule (IrlsSettings): on these points, caps from 5 to 100 and
    relative tolerances from 1e-6 to 1e-10 gave AUC@1 within 0.002 of each other. */
    IrlsSettings irls;
};

struct FinalRefinementResult
{
    Matx33d E;
    int iterations = 0;    //!< IRLS iterations over all rounds
    int pointsUsed = 0;    //!< correspondences the last refinement saw
    double noise = 0.0;    //!< sigma used (normalised units)
    bool improved = false; //!< a refinement lowered its cost (E differs from the start)
};

/** Robust estimate of the noise of the Sampson distances to E: 1.4826 times the median distance
of the points within `window` thresholds of E; 0 if fewer than minPoints are. */
double estimateNoise(const Problem& problem, const Matx33d& E, double threshold, double window,
                     int minPoints);

/** Refines E0, the search winner for the (normalised) inlier threshold `threshold`, as
FinalRefinementSettings describes: the points near E0 (and in front of both cameras for its pose)
by IRLS with a Cauchy loss whose scale follows the estimated noise. Fewer than 5 such points leave
E0 unchanged. */
FinalRefinementResult
refineFinal(const Problem& problem, const Matx33d& E0, double threshold,
            const FinalRefinementSettings& settings = FinalRefinementSettings());

} // namespace refine
} // namespace essential
} // namespace cv

#endif

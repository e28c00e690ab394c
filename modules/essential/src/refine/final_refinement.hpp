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

struct FinalRefinementSettings
{
    /** The refinement sees the points within this many thresholds of the search winner. Not 1:
    the winner is off by about 0.15 degrees (its own inliers' noise), and the points within one
    threshold of a model that is off are a sample biased towards it, which a refinement on them
    alone cannot leave (docs/ACCURACY.md: AUC@1 0.908 at 90% inliers on the winner's inliers,
    0.940 within 2 thresholds). Measured 2 and 3 within 0.002 of each other, 2 ahead at every
    inlier ratio. */
    double band = 2.0;
    /** ... and only those in front of both cameras for the winner's pose (the cheirality test of
    pose::recoverPoseNormalised): half the wrong matches that fall near their epipolar line are
    behind a camera. AUC@1 at 25% inliers 0.823 without, 0.869 with. */
    bool inFrontOnly = true;
    /** Cauchy scale in thresholds. With the outliers' pull gone (the points above) a wider loss
    keeps more of the inliers' information: 1 threshold (twice the noise when the threshold is set
    at two sigmas) beats 0.5 by 0.005 AUC@1 on average over 90/70/50/25% inliers, 1.5 is no
    better. */
    double scaleInThresholds = 1.0;
    /** The IRLS's cap and stopping rule (IrlsSettings): on these points, caps from 5 to 100 and
    relative tolerances from 1e-6 to 1e-10 gave AUC@1 within 0.002 of each other. */
    IrlsSettings irls;
};

struct FinalRefinementResult
{
    Matx33d E;
    int iterations = 0;
    int pointsUsed = 0;    //!< correspondences the refinement saw
    bool improved = false; //!< the refinement lowered its cost (E differs from the start)
};

/** Refines E0, the search winner for the (normalised) inlier threshold `threshold`: the points
within settings.band thresholds of E0 (and in front of both cameras for E0's pose) are refined by
IRLS with a Cauchy loss of scale settings.scaleInThresholds * threshold. Fewer than 5 such points
leave E0 unchanged. */
FinalRefinementResult
refineFinal(const Problem& problem, const Matx33d& E0, double threshold,
            const FinalRefinementSettings& settings = FinalRefinementSettings());

} // namespace refine
} // namespace essential
} // namespace cv

#endif

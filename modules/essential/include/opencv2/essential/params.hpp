// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#ifndef OPENCV_ESSENTIAL_PARAMS_HPP
#define OPENCV_ESSENTIAL_PARAMS_HPP

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>

#include <string>

namespace cv {
namespace essential {

//! @addtogroup essential
//! @{

/** Which hypothesise-and-verify loop runs the search. */
enum EssentialEngine {
    /** The module's adaptive loop: MSAC for `RANSAC`, least median of squares for `LMEDS`. */
    ENGINE_ADAPTIVE = 0,
    /** OpenCV's own RANSAC or LMedS loop (the one cv::findEssentialMat uses, exported by
    libopencv_calib3d), with the chosen solver as its kernel. Available when the build found that
    loop usable (see isOpenCvLoopAvailable()); otherwise selecting it raises StsNotImplemented. */
    ENGINE_OPENCV = 1,
    /** Nister's preemptive breadth-first RANSAC, as in the paper: M hypotheses generated up front,
    scored on blocks of B points in a random order, the better half kept after each block. Scores
    with MSAC; `method` must be RANSAC. */
    ENGINE_PREEMPTIVE = 2
};

/** True when this build can run solvers inside OpenCV's own RANSAC loop (ENGINE_OPENCV). */
CV_EXPORTS bool isOpenCvLoopAvailable();

/** @brief Settings of one essential-matrix estimate (the module's own overload of
findEssentialMatIter()).

The defaults are those of the drop-in overloads, which behave like `cv::findEssentialMat` with
`method = RANSAC`, `prob = 0.999`, `threshold = 1.0`, `maxIters = 1000`.
*/
struct CV_EXPORTS EssentialParams
{
    /** Name of a registered solver (see listSolvers()) or a composite such as "gn+nister" (see
    createSolver()). The default draws hypotheses from gn and nister in turn, the combination the
    paper's conclusion suggests: on the synthetic protocol it was the most reliable per unit time at
    30% inliers (docs/SOLVERS.md, "Choosing the default"). Under tight time budgets on video, "gn"
    alone did best on the rail sequences. */
    std::string solver = "gn+nister";

    /** Scoring: `cv::RANSAC` (adaptive MSAC, truncated Sampson error) or `cv::LMEDS` (least median
    of squared Sampson errors; the threshold is then derived from the data, as OpenCV does). */
    int method = RANSAC;

    /** The search loop: ENGINE_ADAPTIVE (default), ENGINE_PREEMPTIVE or ENGINE_OPENCV. */
    int engine = ENGINE_ADAPTIVE;

    /** Time budget of the whole call in milliseconds; 0 (default) for none. With a budget the
    search returns the best model found when the time left is what the final refinement needs
    (estimated from the number of points), so that the call as a whole takes about this long.
    Honoured by ENGINE_ADAPTIVE and ENGINE_PREEMPTIVE; ENGINE_OPENCV raises StsNotImplemented. */
    double timeBudgetMs = 0;

    /** ENGINE_PREEMPTIVE: number M of hypotheses generated up front. 0 (default): chosen at run
    time to fill timeBudgetMs, or 500 without a budget. */
    int preemptiveHypotheses = 0;

    /** ENGINE_PREEMPTIVE: block size B, the points scored between two halvings. */
    int preemptiveBlockSize = 100;

    /** Required probability, in (0, 1), that at least one sample was outlier-free and solved. */
    double confidence = 0.999;

    /** Inlier threshold in pixels on the Sampson distance, with pixels converted to normalised
    units by the mean focal length (fx + fy) / 2, exactly as `cv::findEssentialMat`. Must be > 0. */
    double threshold = 1.0;

    /** Iteration cap in OpenCV's units. Must be > 0. OpenCV's cap counts samples of a direct
    5-point solver, each of which solves an outlier-free sample; an iterative solver that reaches
    the true model on a fraction s of outlier-free samples (EssentialSolver::successRate(), 0.35 for
    gn) may draw up to maxIters / s samples, so that the confidence reached at the cap is the same.
    Those samples are still several times cheaper than OpenCV's (see docs/SOLVERS.md). */
    int maxIters = 1000;

    /** Seed of the random generator: the same seed and input give the same result. */
    uint64 seed = 0x6573736e7469616cULL;

    /** Refine the best hypothesis on all points by iteratively reweighted least squares (IRLS) with
    Levenberg-Marquardt in the 5-DOF parameterisation, then recompute the inlier mask. */
    bool refine = true;

    /** When a report is requested: also decompose E into R and t (with the cheirality test of
    recoverPose()) and store them in the report. */
    bool recoverPose = true;
};

/** @brief What one estimate did: the pose, the counts and the time spent per stage. */
struct CV_EXPORTS EssentialReport
{
    bool success = false;         //!< an essential matrix was found
    Matx33d E = Matx33d::zeros(); //!< the returned essential matrix (Frobenius norm sqrt(2))
    Matx33d R = Matx33d::eye();   //!< rotation from view 1 to view 2 (if poseRecovered)
    Vec3d t = Vec3d(0, 0, 0);     //!< unit translation, X2 = R X1 + s t (if poseRecovered)
    bool poseRecovered = false;   //!< R and t were computed
    int pointsInFront = 0;        //!< inliers in front of both cameras for (R, t)

    int numPoints = 0;           //!< correspondences given
    int inliers = 0;             //!< non-zero entries of the returned mask
    int iterations = 0;          //!< samples drawn (at most maxIters / solver success rate)
    int hypothesesGenerated = 0; //!< solver calls made (one per sample)
    int hypothesesConverged = 0; //!< essential matrices the solver returned
    int hypothesesScored = 0;    //!< essential matrices scored against the data
    int refineIterations = 0;    //!< IRLS iterations of the final refinement

    double timeSetupMs = 0;  //!< input checks and normalisation
    double timeSearchMs = 0; //!< sampling, solving and scoring
    double timeRefineMs = 0; //!< final IRLS refinement and mask
    double timePoseMs = 0;   //!< decomposition into R and t
    double timeTotalMs = 0;  //!< the whole call
};

//! @}

} // namespace essential
} // namespace cv

#endif // OPENCV_ESSENTIAL_PARAMS_HPP

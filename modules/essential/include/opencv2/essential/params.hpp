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

/** The distance of a correspondence to E that decides whether it is an inlier (compared with the
threshold, both in normalised units). */
enum EssentialDistance {
    /** The Sampson distance r / sqrt(|(E q1)_xy|^2 + |(E^T q2)_xy|^2), r = q2^T E q1: the
    first-order reprojection error, what cv::findEssentialMat thresholds with RANSAC and LMEDS. */
    DISTANCE_SAMPSON = 0,
    /** The symmetric epipolar distance sqrt(d1^2 + d2^2), d1 and d2 the distances of each point to
    its epipolar line: what OpenCV 4.6's USAC thresholds for essential matrices (every USAC_* flag
    and the UsacParams form). It is at least twice the Sampson distance, so the same threshold
    admits fewer inliers. */
    DISTANCE_SYMMETRIC_EPIPOLAR = 1
};

/** How many samples the adaptive engine may draw when its stopping rule is not met (hard data: few
inliers, or the best model so far is wrong). */
enum EssentialSampleBudget {
    /** maxIters / s samples, s the solver's hit rate (EssentialParams::maxIters): the confidence
    OpenCV's cap gives a direct solver. */
    BUDGET_CONFIDENCE = 0,
    /** When even the maxIters / s cap does not buy one expected good sample at the best model's
    inlier ratio (no model yet, or one as weakly supported as a wrong model on hard data), the
    search goes on until it has (confidence 1 - 1/e at that ratio), up to the samples that fit in
    three quarters of the time cv::findEssentialMat's RANSAC spends on maxIters iterations with the
    same number of points, by a fixed cost model of both (about 20 maxIters samples at N = 500, 24
    maxIters at N = 4000; src/ransac/opencv_time_budget.hpp has the measurements); and only if a
    model it could find would pass the final support test (not on a few dozen points without
    geometry). The result
    stays deterministic: the cap is a number of samples, not a clock. Data on which the stopping
    rule is met within maxIters / s (most of them) stop exactly as with BUDGET_CONFIDENCE. */
    BUDGET_OPENCV_TIME = 1
};

/** True when this build can run solvers inside OpenCV's own RANSAC loop (ENGINE_OPENCV). */
CV_EXPORTS_W bool isOpenCvLoopAvailable();

/** @brief Settings of one essential-matrix estimate (the module's own overload of
findEssentialMatIter()).

The defaults are those of the drop-in overloads, which behave like `cv::findEssentialMat` with
`method = RANSAC`, `prob = 0.999`, `threshold = 1.0`, `maxIters = 1000`.
*/
// OpenCV's Python generator (modules/python/src2/hdr_parser.py of OpenCV 4.6, inside an OpenCV
// build) cannot read member initialisers: it would take `int maxIters = 1000;` for a field named
// "maxIters = 1000". It skips `#ifndef OPENCV_BINDING_PARSER` blocks and reads the declaration in
// the `#ifdef OPENCV_BINDING_PARSER` block instead, which the compiler never sees: the same struct
// with the binding macros and the fields without their defaults. Keep the two field lists equal
// (modules/essential/misc/python/test/test_essential.py checks that cv2.essential has them all).
#ifndef OPENCV_BINDING_PARSER
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

    /** Time budget of the whole call in milliseconds; 0 (default) or +inf for none. With a budget
    the search returns the best model found when the time left is what the final refinement needs
    (estimated from the number of points), so that the call as a whole takes about this long. Any
    positive finite value is a budget; one beyond the steady clock's range (about 9e12 ms) never
    runs out. Negative values and NaN raise StsBadArg. Honoured by ENGINE_ADAPTIVE and
    ENGINE_PREEMPTIVE; ENGINE_OPENCV raises StsNotImplemented for a budget. */
    double timeBudgetMs = 0;

    /** ENGINE_PREEMPTIVE: number M of hypotheses generated up front. 0 (default): chosen at run
    time to fill timeBudgetMs, or 500 without a budget. */
    int preemptiveHypotheses = 0;

    /** ENGINE_PREEMPTIVE: block size B, the points scored between two halvings. */
    int preemptiveBlockSize = 100;

    /** Required probability, in (0, 1), that at least one sample was outlier-free and solved. */
    double confidence = 0.999;

    /** Inlier threshold in pixels on `distance`, with pixels converted to normalised units by the
    mean focal length (fx + fy) / 2, exactly as `cv::findEssentialMat`. Must be > 0. */
    double threshold = 1.0;

    /** The distance `threshold` applies to: DISTANCE_SAMPSON (default, as cv::findEssentialMat with
    RANSAC or LMEDS) or DISTANCE_SYMMETRIC_EPIPOLAR (as OpenCV's USAC; the drop-in overloads select
    it for the USAC flags and the UsacParams form). Scoring, SPRT, local optimisation's inlier sets,
    the support test and the mask use it; LMEDS and the final refinement's robust cost always use
    the Sampson distance. */
    EssentialDistance distance = DISTANCE_SAMPSON;

    /** Iteration cap in OpenCV's units. Must be > 0. OpenCV's cap counts samples of a direct
    5-point solver, each of which solves an outlier-free sample; an iterative solver that reaches
    the true model on a fraction s of outlier-free samples (EssentialSolver::hitProbabilityAt() at
    the pose of the best model so far, 0.28 to 0.41 for gn) may draw up to maxIters / s samples, so
    that the confidence reached at the cap is the same.
    Those samples are still several times cheaper than OpenCV's (see docs/SOLVERS.md). With
    sampleBudget = BUDGET_OPENCV_TIME (the default) the cap is raised to the samples that fit in
    three quarters of OpenCV's time for maxIters iterations. */
    int maxIters = 1000;

    /** The sample cap of ENGINE_ADAPTIVE with method RANSAC: BUDGET_OPENCV_TIME (default) or
    BUDGET_CONFIDENCE (EssentialSampleBudget). LMEDS draws OpenCV's fixed number of samples, and
    ENGINE_PREEMPTIVE and ENGINE_OPENCV have their own budgets; they ignore it. Default
    BUDGET_OPENCV_TIME, measured on hard sets (few inliers, a dominant plane, repeated structure,
    docs/HARD_PAIRS.md). */
    int sampleBudget = BUDGET_OPENCV_TIME;

    /** With BUDGET_OPENCV_TIME and the uniform sampler: once the samples pass the confidence cap
    (maxIters / s, where the stopping rule would have ended the search on data it finds hard),
    every other sample is spatially local, as SAMPLING_PROGRESSIVE_NAPSAC draws them (a seed and
    four of its neighbours in both images). Inliers of real pairs cluster on objects and surfaces,
    so local samples are clean far more often when inliers are few; easy data stop before the cap
    and never pay for the neighbourhood grid. Default on, measured on the hard sets
    (docs/HARD_PAIRS.md). */
    bool budgetLocalSamples = true;

    /** After the search (ENGINE_ADAPTIVE with RANSAC), check whether the winner's inliers are
    dominated by one plane (a homography fitted to them explains at least half) and, if so, search
    the "plane and parallax" models E = [e']x H, the epipole e' fixed by pairs of points off the
    plane, keeping one if its MSAC cost is lower. Planar scenes are where a search stops on a model
    the plane alone supports (the twin of the homography decomposition or a model degrees off); the
    check costs nothing when no plane dominates and about 1 ms otherwise. Default on, measured on
    hard sets (docs/HARD_PAIRS.md). */
    bool planeParallax = true;

    /** Local optimisation (LO) in the adaptive MSAC engine: each time a hypothesis becomes the
    best so far, it is polished by this many IRLS iterations (Levenberg-Marquardt on
    Cauchy-weighted Sampson residuals, scale the threshold) on the points within 2 thresholds of
    it, and the polished model replaces it when its MSAC cost on all points is lower; the
    stopping rule then uses the polished model's inlier ratio. 0 disables LO. Ignored by LMEDS and
    by ENGINE_PREEMPTIVE and ENGINE_OPENCV (they have no LO step). Must be >= 0.
    Default 5, measured (docs/ENGINE.md, "Local optimisation"): on the synthetic protocol (N = 500,
    300 problems) LO cuts the samples at 50% inliers from 695 to 513 (the polished model's higher
    inlier ratio stops the search earlier) and the median time from 3.05 to 2.78 ms, with the same
    reliability (1.000) and pose errors; at 30% inliers the iteration cap binds either way and the
    reliability goes from 0.940 to 0.943. On the Leuven pair (essential_pair, seeds 1 to 20) the
    mean inlier count goes from 327 to 338, 12 runs instead of 8 reaching the better of the two
    solutions (about 355 inliers). IRLS mostly converges within 5 iterations: 10 gives the same
    results, 1 to 3 save fewer samples. A best model supported by less than half of the points is
    first given 10 inner samples (LO-RANSAC's inner RANSAC: minimal samples drawn among the points
    within 3 thresholds of it, solved and scored like the search's, once 50 samples have been
    drawn); on 300 problems this raised the reliability at 30% inliers from 0.977 to 0.993 and at
    25% from 0.810 to 0.957 with the same sample cap (docs/PERFORMANCE.md). */
    int loIterations = 5;

    /** LO on a random subset of this many of the model's inliers; 0 (default): on all of them.
    Must be 0 or >= 5 (IRLS fits five degrees of freedom). */
    int loSampleSize = 0;

    /** How samples are drawn:
    - `cv::SAMPLING_UNIFORM` (default);
    - `cv::SAMPLING_PROSAC` (Chum and Matas' progressive sampling: the points must be sorted by
      quality, best first, as for OpenCV's USAC_PROSAC; samples come from a growing pool of the best
      points, and the adaptive engine may stop as soon as PROSAC's non-randomness and maximality
      conditions hold for some pool). Supported by ENGINE_ADAPTIVE (RANSAC and LMEDS);
    - `cv::SAMPLING_NAPSAC`: every sample spatially local, a seed and four of its neighbours in
      both images (a cell of a 16 x 16, 8 x 8, 4 x 4 or 2 x 2 grid over each image), for data whose
      inliers cluster; `cv::SAMPLING_PROGRESSIVE_NAPSAC`: local and uniform samples in turn. Both
      need ENGINE_ADAPTIVE with RANSAC.
    Other engines raise StsNotImplemented for a sampler they do not support. docs/HARD_PAIRS.md
    measures each on hard data. */
    int sampler = SAMPLING_UNIFORM;

    /** Verify hypotheses with Wald's sequential probability ratio test (Matas and Chum, R-RANSAC
    with SPRT): the points are checked in a random order and a hypothesis is rejected as soon as
    the likelihood ratio of "bad model" against "good model" exceeds the threshold A; epsilon is the
    best model's inlier ratio, delta the fraction of consistent points in rejected hypotheses, and
    the stopping rule is the paper's (equation (9) with h_i = 1: under each test the probability of
    drawing a good sample is multiplied by 1 - 1/A_i, Wald's bound on rejecting a good model). Used
    by ENGINE_ADAPTIVE with RANSAC; ignored by LMEDS, ENGINE_PREEMPTIVE and ENGINE_OPENCV. Default
    on, measured (docs/ENGINE.md, "SPRT"): at N = 1000 (300 problems, the same samples drawn with
    and without it) a hypothesis costs 54 point checks instead of 735 at 50% inliers and 105 instead
    of 911 at 30%, the median call time goes from 4.1 to 2.9 ms and from 12.7 to 7.4 ms, and the
    reliability is unchanged (1.000, 0.957); on the Leuven pair the inliers are the same for every
    seed in about half the time. */
    bool sprt = true;

    /** Seed of the random generator: the same seed and input give the same result. */
    uint64 seed = 0x6573736e7469616cULL;

    /** Refine the best hypothesis by iteratively reweighted least squares (IRLS) with
    Levenberg-Marquardt in the 5-DOF parameterisation (Tukey's biweight at a scale that follows the
    estimated noise, on the points within max(2 thresholds, 4 sigmas) of it and in front of both
    cameras; docs/ACCURACY.md), then recompute the inlier mask. */
    bool refine = true;

    /** When a report is requested: also decompose E into R and t (with the cheirality test of
    recoverPose()) and store them in the report. */
    bool recoverPose = true;
};
#endif
#ifdef OPENCV_BINDING_PARSER
struct CV_EXPORTS_W_SIMPLE EssentialParams
{
    CV_WRAP EssentialParams();
    CV_PROP_RW std::string solver;
    CV_PROP_RW int method;
    CV_PROP_RW int engine;
    CV_PROP_RW double timeBudgetMs;
    CV_PROP_RW int preemptiveHypotheses;
    CV_PROP_RW int preemptiveBlockSize;
    CV_PROP_RW double confidence;
    CV_PROP_RW double threshold;
    CV_PROP_RW EssentialDistance distance;
    CV_PROP_RW int maxIters;
    CV_PROP_RW int sampleBudget;
    CV_PROP_RW bool budgetLocalSamples;
    CV_PROP_RW bool planeParallax;
    CV_PROP_RW int loIterations;
    CV_PROP_RW int loSampleSize;
    CV_PROP_RW int sampler;
    CV_PROP_RW bool sprt;
    CV_PROP_RW uint64 seed;
    CV_PROP_RW bool refine;
    CV_PROP_RW bool recoverPose;
};
#endif

/** @brief What one estimate did: the pose, the counts and the time spent per stage. */
#ifndef OPENCV_BINDING_PARSER
struct CV_EXPORTS EssentialReport
{
    bool success = false;         //!< an essential matrix was found
    Matx33d E = Matx33d::zeros(); //!< the returned essential matrix (unit Frobenius norm)
    Matx33d R = Matx33d::eye();   //!< rotation from view 1 to view 2 (if poseRecovered)
    Vec3d t = Vec3d(0, 0, 0);     //!< unit translation, X2 = R X1 + s t (if poseRecovered)
    bool poseRecovered = false;   //!< R and t were computed
    int pointsInFront = 0;        //!< inliers in front of both cameras for (R, t)

    /** Fraction of the inliers that a rotation alone explains: their position in image 2 is
    within twice the threshold of the rotated ray of image 1 (rotation fitted to all inliers).
    Set when an essential matrix was found. */
    double rotationOnlyFraction = 0;
    /** Fraction of the inliers that a homography explains (fitted to all inliers by DLT; same
    distance). Set when an essential matrix was found. */
    double homographyFraction = 0;
    /** The inliers do not determine the pose: rotationOnlyFraction >= 0.9 (no parallax: pure
    rotation, a baseline too short for the scene's depth; every E = [t]x R with the right R fits,
    so t is noise, R is still right) or homographyFraction >= 0.9 (a planar scene or all points at
    one depth: two poses fit equally well and the estimate may be the wrong one). Treat the result
    as a rotation, or a homography, not as a pose. See docs/ROBUSTNESS.md, "Degenerate scenes". */
    bool degenerate = false;

    int numPoints = 0;           //!< correspondences given
    int inliers = 0;             //!< non-zero entries of the returned mask
    int iterations = 0;          //!< samples drawn (EssentialParams::maxIters, sampleBudget)
    int hypothesesGenerated = 0; //!< solver calls made (one per sample, plus LO's inner samples)
    int hypothesesConverged = 0; //!< essential matrices the solver returned
    int hypothesesScored = 0;    //!< essential matrices scored against the data
    int refineIterations = 0;    //!< IRLS iterations of the final refinement
    /** Sampson distances computed while scoring hypotheses (all engines but ENGINE_OPENCV, which
    reports 0): N per fully scored hypothesis, fewer after MSAC's early exit or an SPRT rejection.
    */
    int64 pointsScored = 0;
    int localOptimisations = 0;     //!< LO runs (EssentialParams::loIterations)
    int localOptimisationsKept = 0; //!< LO runs whose polished model lowered the MSAC cost
    int sprtRejections = 0;         //!< hypotheses rejected by the SPRT (EssentialParams::sprt)
    /** The plane-and-parallax check (EssentialParams::planeParallax) found the search's winner
    dominated by a plane and replaced it with a better-supported model. */
    bool planeParallaxKept = false;

    double timeSetupMs = 0;  //!< input checks and normalisation
    double timeSearchMs = 0; //!< sampling, solving and scoring
    double timeRefineMs = 0; //!< final IRLS refinement and mask
    double timePoseMs = 0;   //!< decomposition into R and t
    double timeTotalMs = 0;  //!< the whole call
};
#endif
#ifdef OPENCV_BINDING_PARSER
struct CV_EXPORTS_W_SIMPLE EssentialReport
{
    CV_WRAP EssentialReport();
    CV_PROP_RW bool success;
    CV_PROP_RW Matx33d E;
    CV_PROP_RW Matx33d R;
    CV_PROP_RW Vec3d t;
    CV_PROP_RW bool poseRecovered;
    CV_PROP_RW int pointsInFront;
    CV_PROP_RW double rotationOnlyFraction;
    CV_PROP_RW double homographyFraction;
    CV_PROP_RW bool degenerate;
    CV_PROP_RW int numPoints;
    CV_PROP_RW int inliers;
    CV_PROP_RW int iterations;
    CV_PROP_RW int hypothesesGenerated;
    CV_PROP_RW int hypothesesConverged;
    CV_PROP_RW int hypothesesScored;
    CV_PROP_RW int refineIterations;
    CV_PROP int64 pointsScored;
    CV_PROP_RW int localOptimisations;
    CV_PROP_RW int localOptimisationsKept;
    CV_PROP_RW int sprtRejections;
    CV_PROP_RW bool planeParallaxKept;
    CV_PROP_RW double timeSetupMs;
    CV_PROP_RW double timeSearchMs;
    CV_PROP_RW double timeRefineMs;
    CV_PROP_RW double timePoseMs;
    CV_PROP_RW double timeTotalMs;
};
#endif

//! @}

} // namespace essential
} // namespace cv

#endif // OPENCV_ESSENTIAL_PARAMS_HPP

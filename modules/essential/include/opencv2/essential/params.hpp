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
    /** The module's adaptive loop: MSAC or least median of squares (EssentialParams::score), with
    SPRT, local optimisation and the samplers. */
    ENGINE_ADAPTIVE = 0,
    /** OpenCV's own RANSAC or LMedS loop (the one cv::findEssentialMat uses, exported by
    libopencv_calib3d), with the chosen solver as its kernel. Available when the build found that
    loop usable (see isOpenCvLoopAvailable()); otherwise selecting it raises StsNotImplemented. */
    ENGINE_OPENCV = 1,
    /** Nister's preemptive breadth-first RANSAC, as in the paper: M hypotheses generated up front,
    scored on blocks of B points in a random order, the better half kept after each block. Scores
    with MSAC; EssentialParams::score must be SCORE_METHOD_MSAC. */
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
    /** maxIterations / s samples, s the solver's hit rate (EssentialParams::maxIterations): the
    confidence OpenCV's cap gives a direct solver. */
    BUDGET_CONFIDENCE = 0,
    /** When even the maxIterations / s cap does not buy one expected good sample at the best
    model's inlier ratio (no model yet, or one as weakly supported as a wrong model on hard data),
    the search goes on until it has (confidence 1 - 1/e at that ratio), up to the samples that fit
    in three quarters of the time cv::findEssentialMat's RANSAC spends on maxIters iterations with
    the same number of points (about 20 maxIters samples at N = 500), and only if a model it could
    find would pass the final support test. The cap is a number of samples from a fixed cost
    model, not a clock, so the result stays deterministic. Data on which the stopping rule is met
    within maxIterations / s (most of them) stop exactly as with BUDGET_CONFIDENCE. */
    BUDGET_OPENCV_TIME = 1
};

/** True when this build can run solvers inside OpenCV's own RANSAC loop (ENGINE_OPENCV). */
CV_EXPORTS_W bool isOpenCvLoopAvailable();

/** @brief Settings of one essential-matrix estimate (the module's own overload of
findEssentialMatIter()).

The defaults are those of the drop-in overloads, which behave like `cv::findEssentialMat` with
`method = RANSAC`, `prob = 0.999`, `threshold = 1.0`, `maxIters = 1000`.

The fields are grouped by the stage they set, in the pipeline's order: the drop-in's settings
(what cv::findEssentialMat takes), the search, local optimisation, the hard-data levers, the final
refinement and pose. docs/ARCHITECTURE.md names the source folder of each stage.

Names and types follow cv::UsacParams wherever it has the same setting (`confidence`, `threshold`,
`maxIterations`, `score`, `sampler`, `loIterations`, `loSampleSize`); the module's own settings use
its own enums (EssentialEngine, EssentialDistance, EssentialSampleBudget). The seed is `seed`, a
64-bit value (UsacParams' `randomGeneratorState` is an int).

Unsupported settings: a value this struct can hold but the module cannot run (a score or sampler it
does not implement, or one the chosen engine does not support) raises StsNotImplemented naming the
field; an invalid value (outside its range or enumeration) raises StsBadArg. Settings that do not
apply to the chosen engine (for example `loIterations` with ENGINE_PREEMPTIVE) are ignored, as each
field says. The drop-in forms, which must take whatever cv::findEssentialMat takes, map what the
module lacks to its nearest equivalent instead (the tables in the module description).

How the defaults were chosen, with the measurements and the commands that make them:
docs/PARAMETERS.md.
*/
// The compiled structs below are the one table of the fields: scripts/params_table.py writes every
// other copy of the list from them (the ctest entry params_table_is_current fails when a copy
// differs). One copy is here: OpenCV's Python generator (modules/python/src2/hdr_parser.py of
// OpenCV 4.6, inside an OpenCV build) cannot read member initialisers, it would take
// `int maxIterations = 1000;` for a field named "maxIterations = 1000". It skips
// `#ifndef OPENCV_BINDING_PARSER` blocks and reads the declaration in the
// `#ifdef OPENCV_BINDING_PARSER` block instead, which the compiler never sees: the same struct with
// the binding macros and the fields without their defaults.
#ifndef OPENCV_BINDING_PARSER
struct CV_EXPORTS EssentialParams
{
    /** @name The drop-in's settings
    What cv::findEssentialMat takes (`prob`, `threshold`, `maxIters`), the distance the threshold
    applies to (the USAC forms select OpenCV USAC's) and the seed (cv::UsacParams'
    `randomGeneratorState`). */
    //! @{

    /** Required probability, in (0, 1), that at least one sample was outlier-free and solved.
    Default 0.999. */
    double confidence = 0.999;

    /** Inlier threshold in pixels on `distance`, with pixels converted to normalised units by the
    mean focal length (fx + fy) / 2, exactly as `cv::findEssentialMat`. Must be > 0. Default 1. */
    double threshold = 1.0;

    /** Iteration cap in OpenCV's units (cv::findEssentialMat's `maxIters`). Must be > 0. Default
    1000. OpenCV's cap counts samples of a direct 5-point solver, each of which solves an
    outlier-free sample; an iterative solver that reaches the true model on a fraction s of
    outlier-free samples (EssentialSolver::hitProbabilityAt()) may draw up to maxIterations / s
    samples, so that the confidence reached at the cap is the same. sampleBudget may raise the cap
    further on hard data. */
    int maxIterations = 1000;

    /** The distance `threshold` applies to: DISTANCE_SAMPSON (default, as cv::findEssentialMat with
    RANSAC or LMEDS) or DISTANCE_SYMMETRIC_EPIPOLAR (as OpenCV's USAC; the drop-in forms select it
    for the USAC flags and the UsacParams form). Scoring, SPRT, local optimisation's inlier sets,
    the support test and the mask use it; LMedS and the final refinement's robust cost always use
    the Sampson distance. */
    EssentialDistance distance = DISTANCE_SAMPSON;

    /** Seed of the random generator: the same seed and input give the same result. */
    uint64 seed = 0x6573736e7469616cULL;

    //! @}

    /** @name Search
    Hypothesis generation, sampling, scoring and verification, and when the search stops
    (src/sampling, src/solvers, src/scoring, src/search, src/termination). */
    //! @{

    /** Name of a registered solver (see listSolvers()) or a composite such as "gn+nister" (see
    createSolver()). Default "nister": on real photographs (fields of view of 40 to 60 degrees) the
    iterative gn reaches the true model from a small fraction of outlier-free samples, and nister,
    whose wrong roots the search discards by cheirality before scoring, is then both more accurate
    and, on the paper's synthetic scenes, faster than gn and nister in turn (docs/REAL_PAIRS.md). */
    std::string solver = "nister";

    /** The search loop: ENGINE_ADAPTIVE (default), ENGINE_PREEMPTIVE or ENGINE_OPENCV. */
    EssentialEngine engine = ENGINE_ADAPTIVE;

    /** How hypotheses are scored: `cv::SCORE_METHOD_MSAC` (default; truncated Sampson error, what
    the drop-in forms run for `cv::RANSAC` and the USAC flags) or `cv::SCORE_METHOD_LMEDS` (least
    median of squared Sampson errors; the threshold is then derived from the data, as OpenCV does).
    SCORE_METHOD_RANSAC and SCORE_METHOD_MAGSAC raise StsNotImplemented. */
    ScoreMethod score = SCORE_METHOD_MSAC;

    /** How samples are drawn:
    - `cv::SAMPLING_UNIFORM` (default);
    - `cv::SAMPLING_PROSAC`: progressive sampling from a growing pool of the best points (the
      points must be sorted by quality, best first, as for OpenCV's USAC_PROSAC); ENGINE_ADAPTIVE;
    - `cv::SAMPLING_NAPSAC`: every sample spatially local (a seed and four of its neighbours in
      both images, on a 16 x 16 to 2 x 2 grid over each image);
      `cv::SAMPLING_PROGRESSIVE_NAPSAC`: local and uniform samples in turn. Both need
      ENGINE_ADAPTIVE with SCORE_METHOD_MSAC.
    A sampler the chosen engine does not support raises StsNotImplemented. */
    SamplingMethod sampler = SAMPLING_UNIFORM;

    /** Verify hypotheses with Wald's sequential probability ratio test (Matas and Chum, R-RANSAC
    with SPRT): the points are checked in a random order and a hypothesis is rejected as soon as
    the likelihood ratio of "bad model" against "good model" exceeds a threshold; the stopping rule
    accounts for the good models the test may reject. Used by ENGINE_ADAPTIVE with
    SCORE_METHOD_MSAC; ignored otherwise. Default on. */
    bool sprt = true;

    /** The sample cap of ENGINE_ADAPTIVE with SCORE_METHOD_MSAC: BUDGET_OPENCV_TIME (default) or
    BUDGET_CONFIDENCE. LMedS draws OpenCV's fixed number of samples, and ENGINE_PREEMPTIVE and
    ENGINE_OPENCV have their own budgets; they ignore it. */
    EssentialSampleBudget sampleBudget = BUDGET_OPENCV_TIME;

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

    /** ENGINE_PREEMPTIVE: block size B, the points scored between two halvings. Default 100. */
    int preemptiveBlockSize = 100;

    //! @}

    /** @name Local optimisation
    Polishing each new best hypothesis of the adaptive MSAC engine (src/local_optimisation). */
    //! @{

    /** Local optimisation (LO) in the adaptive MSAC engine: each new best hypothesis is polished
    by this many IRLS iterations (Levenberg-Marquardt on Cauchy-weighted Sampson residuals) on the
    points within 2 thresholds of it, and kept when its MSAC cost on all points is lower; a best
    model supported by less than half of the points first gets 10 inner samples among its
    neighbours (LO-RANSAC's inner RANSAC). 0 disables LO. Ignored by LMedS, ENGINE_PREEMPTIVE and
    ENGINE_OPENCV. Must be >= 0. Default 5. */
    int loIterations = 5;

    /** LO on a random subset of this many of the points within 2 thresholds of the model; 0: on
    all of them. Must be 0 or >= 5 (IRLS fits five degrees of freedom). Default 100: the polish
    only has to reach the model's basin (the final refinement fits all the inliers), and on 100
    points it does so as well as on all of them, at less cost where there are more (real pairs
    over eight random streams: AUC@5 +0.002, right -0.0005; the hard sets' right-rate unchanged,
    their 12 000-match rail pairs 0.91 times the time; docs/REAL_PAIRS.md, "The polish on 100
    points"). */
    int loSampleSize = 100;

    //! @}

    /** @name Hard-data levers
    What the adaptive MSAC engine does when the data are hard: local samples in the extended budget,
    the plane-and-parallax and in-front checks (src/termination, src/degeneracy, src/scoring;
    docs/HARD_PAIRS.md). */
    //! @{

    /** With BUDGET_OPENCV_TIME and the uniform sampler: once the samples pass the confidence cap,
    every other sample is spatially local, as SAMPLING_PROGRESSIVE_NAPSAC draws them (a seed and
    four of its neighbours in both images), because inliers of real pairs cluster on objects and
    surfaces. Easy data stop before the cap and never pay for it. Default on. */
    bool budgetLocalSamples = true;

    /** After the search (ENGINE_ADAPTIVE with SCORE_METHOD_MSAC), check whether the winner's
    inliers are dominated by one plane (a homography explains at least half of them) and, if so,
    search the "plane and parallax" models E = [e']x H, the epipole e' fixed by pairs of points off
    the plane, keeping one if its MSAC cost is lower: on planar scenes a search tends to stop on the
    plane's twin pose. Costs nothing when no plane dominates, a few plane fits otherwise
    (docs/TUNING.md, "Plane and parallax"). Default on. */
    bool planeParallax = true;

    /** After the search (ENGINE_ADAPTIVE with SCORE_METHOD_MSAC, sample cheirality on), count the
    winner's inliers that no pose of it places in front of both cameras; if more than 5% are
    behind, search again with an MSAC score that counts only inliers in front, and keep the winner
    with the lower such cost. A wrong model can fit points behind the cameras and beat the true one
    on the plain cost (docs/REAL_PAIRS.md). The second search has at most the confidence cap of
    maxIterations and what the first left of the sample budget, and its winner replaces the first
    only if its plain cost is at most 1.25 times the first's. Costs one pass over the inliers when
    the winner is clean (2.5% more CPU time in all on the real pairs). Default on. */
    bool inFrontCheck = true;

    //! @}

    /** @name Final refinement and pose
    What happens to the search's winner (src/refine, src/pose). */
    //! @{

    /** Refine the best hypothesis by iteratively reweighted least squares (IRLS) with
    Levenberg-Marquardt in the 5-DOF parameterisation (Tukey's biweight at a scale that follows the
    estimated noise, on the points near it and in front of both cameras; docs/ACCURACY.md), then
    recompute the inlier mask. Default on. */
    bool refine = true;

    /** When a report is requested: also decompose E into R and t (with the cheirality test of
    recoverPoseIter()) and store them in the report. Default on. */
    bool recoverPose = true;

    //! @}
};
#endif
#ifdef OPENCV_BINDING_PARSER
struct CV_EXPORTS_W_SIMPLE EssentialParams
{
    CV_WRAP EssentialParams();
    CV_PROP_RW double confidence;
    CV_PROP_RW double threshold;
    CV_PROP_RW int maxIterations;
    CV_PROP_RW EssentialDistance distance;
    CV_PROP_RW uint64 seed;
    CV_PROP_RW std::string solver;
    CV_PROP_RW EssentialEngine engine;
    CV_PROP_RW ScoreMethod score;
    CV_PROP_RW SamplingMethod sampler;
    CV_PROP_RW bool sprt;
    CV_PROP_RW EssentialSampleBudget sampleBudget;
    CV_PROP_RW double timeBudgetMs;
    CV_PROP_RW int preemptiveHypotheses;
    CV_PROP_RW int preemptiveBlockSize;
    CV_PROP_RW int loIterations;
    CV_PROP_RW int loSampleSize;
    CV_PROP_RW bool budgetLocalSamples;
    CV_PROP_RW bool planeParallax;
    CV_PROP_RW bool inFrontCheck;
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
    int iterations = 0;          //!< samples drawn (EssentialParams::maxIterations, sampleBudget)
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
    /** The in-front check (EssentialParams::inFrontCheck) found more than 5% of the search
    winner's inliers behind the cameras, so the search ran a second time scoring only inliers in
    front of both cameras (adaptive MSAC engine); its counts are included in iterations and the
    hypothesis counts above. */
    bool inFrontSearch = false;
    /** ... and its winner, having the lower in-front cost, replaced the first one. */
    bool inFrontSearchKept = false;

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
    CV_PROP_RW bool inFrontSearch;
    CV_PROP_RW bool inFrontSearchKept;
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

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The hypothesise-and-verify loops: adaptive MSAC and least median of squares (LMedS). Both draw
// samples (uniform, or PROSAC's progressive ones), ask the solver for hypotheses and keep the best
// by their score; they know the solver only through the EssentialSolver interface.

#ifndef OPENCV_ESSENTIAL_SEARCH_SEARCH_HPP
#define OPENCV_ESSENTIAL_SEARCH_SEARCH_HPP

#include "input/problem.hpp"
#include "local_optimisation/local_optimisation.hpp"
#include "opencv2/essential/solver.hpp"
#include "termination/deadline.hpp"

#include <algorithm>

namespace cv {
namespace essential {
namespace search {

struct SearchSettings
{
    /** The call's inlier test (threshold in normalised units): what MSAC, SPRT and local
    optimisation score with and the threshold the solver is given; LMedS derives its own threshold
    from the data and keeps the distance. */
    InlierTest test;
    double confidence = 0.999;
    int maxIters = 1000;
    /** The search returns its best model so far once this passes (checked every few samples). */
    termination::Deadline deadline;
    /** Preemptive search: hypotheses generated up front (0: chosen from the deadline, or
    kDefaultPreemptiveHypotheses without one) and the block size B. */
    int preemptiveHypotheses = 0;
    int preemptiveBlockSize = 100;
    /** Adaptive MSAC: local optimisation of each new best model
    (local_optimisation/local_optimisation.hpp; iterations 0: none). */
    local_optimisation::LocalOptimisationSettings lo;
    /** Adaptive MSAC and LMedS: PROSAC sampling (points sorted best first) instead of uniform. */
    bool prosac = false;
    /** Adaptive MSAC: every napsacEvery-th sample is spatially local (sampling/napsac_sampler.hpp);
    0: none, 1: all (NAPSAC), 2: every other one (the progressive mix of local and global samples).
    */
    int napsacEvery = 0;
    /** Adaptive MSAC: past the confidence cap (sampleCap() of maxIters, up to minSampleCap),
    every other sample is spatially local (napsacEvery = 2 from then on). */
    bool localSamplesInBudget = false;
    /** Adaptive MSAC: verify hypotheses with Wald's SPRT. */
    bool sprt = false;
    /** Adaptive MSAC: the sample cap is at least this many samples (0: sampleCap() alone), the
    budget of EssentialParams::sampleBudget = BUDGET_OPENCV_TIME
    (termination/opencv_time_budget.hpp).
    */
    int minSampleCap = 0;
    /** Adaptive MSAC: before the stopping rule extends the budget past the confidence cap, it reads
    the best model's inlier ratio as termination::NoiseAdaptedRatio does (the correct matches' ratio
    when the threshold lies below the noise) and stops at the cap when that ratio is met; in the
    extension it reads it so once the best model's basin is confirmed. */
    bool noiseAdaptedStop = true;
    /** Adaptive MSAC, LMedS and preemptive: keep only the solutions of a minimal (5-point) sample
    under one of whose poses the sample lies in front of both cameras
    (solvers::essentialSampleIsInFront), before they are scored. Larger samples (robust) may hold
    outliers by design and are not checked. */
    bool sampleCheirality = true;
    /** Adaptive MSAC and preemptive: pass the call's threshold to the solver
    (EssentialSolver::setThreshold, once per estimate); off for a second search of the same
    estimate. */
    bool setSolverThreshold = true;
    /** Adaptive MSAC: score with scoreMsacInFront (scoring/in_front_score.hpp) instead of plain
    MSAC, for a second search when the first one's winner has inliers behind the cameras. SPRT
    (which counts plain inliers) is not used in such a search. */
    bool scoreInFront = false;
    /** Adaptive MSAC: at most this many samples whatever the caps above say (0: no limit); a
    second search of the same estimate gets what the first left of the budget. */
    int sampleLimit = 0;
};

struct SearchResult
{
    bool found = false;
    Matx33d E;
    /** Threshold (normalised units) that defines the inliers of E: the problem's for MSAC, the
    data-derived one for LMedS. */
    double threshold = 0.0;
    int inliers = 0;
    int iterations = 0;             //!< samples drawn
    int hypothesesGenerated = 0;    //!< solver calls
    int hypothesesConverged = 0;    //!< matrices returned by the solver
    int hypothesesScored = 0;       //!< matrices scored
    int64 pointsScored = 0;         //!< Sampson distances computed while scoring hypotheses
    int localOptimisations = 0;     //!< local optimisations run
    int localOptimisationsKept = 0; //!< of which lowered the MSAC cost (the polished model kept)
    int sprtRejections = 0;         //!< hypotheses rejected by the SPRT

    /** Adds the work of another search of the same estimate (a second search). */
    void addWork(const SearchResult& other)
    {
        iterations += other.iterations;
        hypothesesGenerated += other.hypothesesGenerated;
        hypothesesConverged += other.hypothesesConverged;
        hypothesesScored += other.hypothesesScored;
        pointsScored += other.pointsScored;
        localOptimisations += other.localOptimisations;
        localOptimisationsKept += other.localOptimisationsKept;
        sprtRejections += other.sprtRejections;
    }
    /** Adds the work local optimisation did inside this search (each inner hypothesis scored). */
    void addWork(const local_optimisation::LocalOptimisationCounters& lo)
    {
        hypothesesGenerated += lo.hypothesesGenerated;
        hypothesesConverged += lo.hypothesesConverged;
        hypothesesScored += lo.hypothesesConverged;
        pointsScored += lo.pointsScored;
        localOptimisations += lo.polishes;
        localOptimisationsKept += lo.polishesKept;
    }
};

/** A search's result before its first sample: the call's threshold, which the solver is given
(SearchSettings::setSolverThreshold). */
inline SearchResult beginSearch(EssentialSolver& solver, const SearchSettings& settings)
{
    SearchResult result;
    result.threshold = settings.test.threshold;
    if (settings.setSolverThreshold)
        solver.setThreshold(settings.test.threshold); // once per estimate (EssentialSolver)
    return result;
}

/** Adaptive MSAC: stops when the samples drawn reach requiredIterations() for the best inlier ratio
so far (with the solver's hit probability at the best model's pose, hitProbabilityAt()), or
sampleCap(maxIters, the solver's rate there; successRate() before there is a model). A result needs
at least sampleSize inliers. Options (SearchSettings): local optimisation of each new best model by
IRLS on its inliers, kept when it lowers the MSAC cost; PROSAC sampling with PROSAC's stopping rule
(sampling/prosac_sampler.hpp); SPRT verification (scoring/sprt.hpp), with the sample probability in
the stopping rule lowered by the test's bound on false rejections. */
SearchResult searchMsac(const Problem& problem, EssentialSolver& solver, RNG& rng,
                        const SearchSettings& settings);

/** LMedS as cv::findEssentialMat's LMEDS: a fixed number of samples for an assumed outlier ratio of
0.45, the hypothesis with the least median squared Sampson error wins, and the inlier threshold is
max(2.5 * 1.4826 * (1 + 5 / max(N - p, 1)) * sqrt(median), 0.001), p the solver's sample size
(OpenCV: p = 5 and the same floor of 0.001 normalised units). */
SearchResult searchLmeds(const Problem& problem, EssentialSolver& solver, RNG& rng,
                         const SearchSettings& settings);

/** Nister's preemptive breadth-first RANSAC: M hypotheses generated up front (samples drawn until
M exist), then scored on blocks of B points in a random order, keeping the best
floor(M 2^-floor(i / B)) after i points, until one remains or the points run out. With a deadline
and no M given, M is chosen at run time from the measured cost of generating a hypothesis and of
scoring a point, so that generation and scoring fit the time left. */
SearchResult searchPreemptive(const Problem& problem, EssentialSolver& solver, RNG& rng,
                              const SearchSettings& settings);

/** Nister's preemption function f(i) = floor(M 2^-floor(i / B)), at least 1: how many of the M
hypotheses survive once i points have been scored, with blocks of B points. */
inline int preemptiveSurvivors(int M, int64 pointsScored, int B)
{
    const int64 halvings = pointsScored / B;
    // M < 2^31, so 31 halvings leave nothing; shifting by more would be undefined.
    const int64 kept = halvings >= 31 ? 0 : (int64(M) >> halvings);
    return static_cast<int>(std::max<int64>(1, kept));
}

/** The points of `problem` in a random order (for scoring on random subsets or in a random order).
 */
Problem shuffledCopy(const Problem& problem, RNG& rng);

/** M of the preemptive search when neither M nor a deadline is given. */
constexpr int kDefaultPreemptiveHypotheses = 500;

/** The same search run by OpenCV's exported RANSAC (method RANSAC) or LMedS (method LMEDS) loop,
with `solver` as its kernel (opencv_loop/opencv_loop.cpp). Raises StsNotImplemented when the build
has no usable OpenCV loop. */
SearchResult searchOpenCvLoop(const Problem& problem, EssentialSolver& solver, RNG& rng,
                              const SearchSettings& settings, int method);

} // namespace search
} // namespace essential
} // namespace cv

#endif

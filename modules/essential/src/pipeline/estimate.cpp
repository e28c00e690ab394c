// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "pipeline/estimate.hpp"

#include "degeneracy/degeneracy_report.hpp"
#include "degeneracy/plane_parallax.hpp"
#include "degeneracy/support_test.hpp"
#include "input/check_params.hpp"
#include "pose/pose_recovery.hpp"
#include "refine/final_refinement.hpp"
#include "sampling/sample_buffer.hpp"
#include "scoring/in_front_score.hpp"
#include "scoring/msac_score.hpp"
#include "search/minimal_set.hpp"
#include "search/search.hpp"
#include "solvers/iterative_minimal_solver.hpp"
#include "termination/opencv_time_budget.hpp"
#include "termination/termination.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace cv {
namespace essential {

namespace {

double msSince(int64 start)
{
    return double(getTickCount() - start) * 1000.0 / getTickFrequency();
}

/** The scale of the E the public functions return: unit Frobenius norm (singular values
1/sqrt(2), 1/sqrt(2), 0), as cv::findEssentialMat returns it (OpenCV's own accuracy test checks
those singular values). Inside the module E = [t]x R has norm sqrt(2). */
Matx33d unitNorm(const Matx33d& E)
{
    const double n = norm(E);
    return n > 0 ? E * (1.0 / n) : E;
}

Mat toMat(const Matx33d& E)
{
    return Mat(unitNorm(E), true);
}

/** The local optimisation's IRLS (each new best model of the adaptive search) refines the points
within kLoBand thresholds of the model with a Cauchy scale of kLoScaleFraction thresholds, as the
final refinement does when the noise is half the threshold (refine/final_refinement.hpp): the
points within one threshold of a model that is off are biased towards it. Measured with
bench/essential_accuracy_candidates (N = 500; docs/ACCURACY.md): against 1 threshold and half of
it, the search draws 22 / 420 samples instead of 24 / 464 at 90 / 50% inliers (400 problems; the
times are in docs/TUNING.md, "Local optimisation band"), and the final estimate is as precise
(AUC@1 0.944 / 0.917 against 0.944 / 0.918, 300 problems). */
constexpr double kLoBand = 2.0;
constexpr double kLoScaleFraction = 1.0;

/** Time kept back from a time budget for what follows the search: the IRLS refinement (linear in
the points, its measured cost in docs/TUNING.md, "Finishing reserve"), the mask and the pose.
docs/ENGINE.md has the overshoot measurement that checks it. */
double finishingReserveMs(int numPoints)
{
    return 0.05 + 0.0005 * numPoints;
}

/** The search runs again with the in-front score (scoring/in_front_score.hpp) when more than this
fraction of the winner's inliers lies behind the cameras under its best pose. Measured on the SIFT
real pairs of docs/REAL_PAIRS.md (869 pairs, essential_real_pairs --front-end sift): of the 763
winners within 10 degrees of the true pose, none had more than 8% of its inliers behind and 10 more
than 5%; of the 41 posed winners more than 10 degrees off, 5 had more than 8%. 5% re-searches those
5 and the 10 borderline right ones, which keep their first winner unless the second is better.
With the check (and the second search's limits below), AUC@5/10/20 0.757/0.812/0.845 ->
0.760/0.814/0.848 (means over seeds 1-4) for 2.5% more thread CPU time in all (docs/REAL_PAIRS.md).
*/
constexpr double kBehindFraction = 0.05;

/** ... and the second search's winner replaces the first only if, besides its lower in-front cost,
its plain MSAC cost is at most this many times the first's: data that really have points behind a
camera (OpenCV's own synthetic test draws unrestricted rotations) give the true model a plain cost
far below any other, which this keeps. The wrong winners it is for cost less than the true model by
at most 8% on the real pairs (castle-P30 0023-0024: 0.400 against 0.431 px^2 a point). */
constexpr double kInFrontMaxPlainCostRatio = 1.25;

} // namespace

Mat estimate(const Problem& problem, InlierTest callTest, const EssentialParams& params,
             OutputArray mask, MaskWriting maskWriting, EssentialReport* report, int64 start)
{
    const int n = problem.size();
    EssentialReport local;
    EssentialReport& rep = report ? *report : local;
    rep = EssentialReport();
    rep.numPoints = n;
    rep.timeSetupMs = msSince(start);

    Ptr<EssentialSolver> solver = createSolver(params.solver);
    if (n < solver->sampleSize())
        CV_Error(Error::StsBadArg, "solver '" + params.solver + "' needs at least " +
                                       std::to_string(solver->sampleSize()) +
                                       " correspondences, got " + std::to_string(n));
    RNG rng(params.seed);
    std::vector<uchar> inliers(static_cast<size_t>(n), 0);

    // Exactly a minimal set: return every distinct solution, stacked, as OpenCV does.
    if (n == solver->sampleSize() && n == 5) {
        const int64 t0 = getTickCount();
        Mat stacked = search::solveExactlyFive(problem, *solver, rng, rep);
        rep.timeSearchMs = msSince(t0);
        if (!stacked.empty()) std::fill(inliers.begin(), inliers.end(), uchar(1));
        rep.success = !stacked.empty();
        rep.inliers = rep.success ? n : 0;
        if (rep.success) {
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    rep.E(i, j) = stacked.at<double>(i, j);
        }
        writeMask(mask, inliers, maskWriting);
        rep.timeTotalMs = msSince(start);
        return stacked;
    }

    // The preemptive engine draws a fixed number of hypotheses (or what a time budget buys) with no
    // stopping rule: what counts is how many hypotheses the time buys, not the rate at wide
    // rotations, so iterative solvers run there as they did before their start sequence: from
    // R = I only, every root returned (docs/SOLVERS.md).
    if (params.engine == ENGINE_PREEMPTIVE)
        solvers::useIdentityStartOnlyIfIterative(*solver, /*keepCheirality=*/false);
    const int64 tSearch = getTickCount();
    search::SearchSettings settings;
    settings.test = callTest;
    settings.confidence = params.confidence;
    settings.maxIters = params.maxIterations;
    settings.preemptiveHypotheses = params.preemptiveHypotheses;
    settings.preemptiveBlockSize = params.preemptiveBlockSize;
    settings.lo.iterations = params.loIterations;
    settings.lo.sampleSize = params.loSampleSize;
    settings.lo.scale = callTest.threshold * kLoScaleFraction;
    settings.lo.band = kLoBand;
    settings.prosac = params.sampler == SAMPLING_PROSAC;
    settings.napsacEvery = params.sampler == SAMPLING_NAPSAC               ? 1
                           : params.sampler == SAMPLING_PROGRESSIVE_NAPSAC ? 2
                                                                           : 0;
    settings.sprt = params.sprt; // used by the adaptive MSAC loop only
    if (params.sampleBudget == BUDGET_OPENCV_TIME) {
        settings.minSampleCap = termination::opencvTimeSamples(params.maxIterations, n);
        settings.localSamplesInBudget =
            params.budgetLocalSamples && params.sampler == SAMPLING_UNIFORM;
    }
    if (hasTimeBudget(params))
        settings.deadline = termination::Deadline::after(params.timeBudgetMs - msSince(start) -
                                                         finishingReserveMs(n));
    auto runSearch = [&]() {
        if (params.engine == ENGINE_OPENCV)
            return search::searchOpenCvLoop(problem, *solver, rng, settings,
                                            params.score == SCORE_METHOD_LMEDS ? LMEDS : RANSAC);
        if (params.engine == ENGINE_PREEMPTIVE)
            return search::searchPreemptive(problem, *solver, rng, settings);
        if (params.score == SCORE_METHOD_LMEDS)
            return search::searchLmeds(problem, *solver, rng, settings);
        return search::searchMsac(problem, *solver, rng, settings);
    };
    search::SearchResult found = runSearch();
    if ((!found.found || found.inliers <= degeneracy::kMinimalSample) &&
        params.engine != ENGINE_OPENCV && sampling::SampleBuffer::checksCheirality(*solver)) {
        // No sample put in front of both cameras gave a model with support beyond its own sample:
        // the data may contradict cheirality (points behind a camera, as OpenCV's own synthetic
        // test makes with unrestricted random rotations; with 6 such points every sample mixes
        // points in front and behind, and only wrong roots pass). The search runs again without
        // the check, as cv::findEssentialMat would. On photographs a search nearly always finds a
        // model with more support than that, and this second pass is rare.
        settings.sampleCheirality = false;
        settings.setSolverThreshold = false;
        found = runSearch();
    }
    if (found.found && params.inFrontCheck && params.engine == ENGINE_ADAPTIVE &&
        params.score == SCORE_METHOD_MSAC && settings.sampleCheirality) {
        // A winner with many inliers behind the cameras is a wrong model that the plain MSAC cost
        // preferred (scoring/in_front_score.hpp): search again scoring only the inliers in front,
        // and keep whichever winner has the lower in-front cost.
        const int inFront = scoring::inliersInFront(found.E, problem, callTest);
        // The second search gets at most the confidence cap of maxIters (not the extended
        // budget, minSampleCap), and no more than the first left of the call's sample budget: a
        // search that spent the whole budget met hard data, often with none of the geometry,
        // where a second one would double the call's cost for little.
        const int confidenceCap =
            termination::sampleCap(params.maxIterations, solver->successRate());
        const int left = std::max(confidenceCap, settings.minSampleCap) - found.iterations;
        if (left > 0 && found.inliers - inFront > kBehindFraction * found.inliers) {
            search::SearchSettings inFrontSettings = settings;
            inFrontSettings.minSampleCap = 0;
            inFrontSettings.sampleLimit = std::min(confidenceCap, left);
            inFrontSettings.scoreInFront = true;
            inFrontSettings.sprt = false;
            inFrontSettings.setSolverThreshold = false;
            const search::SearchResult second =
                search::searchMsac(problem, *solver, rng, inFrontSettings);
            rep.inFrontSearch = true;
            if (second.found) {
                const scoring::Score secondPlain = scoring::scoreMsac(second.E, problem, callTest);
                if (scoring::scoreMsacInFront(second.E, problem, callTest).cost <
                        scoring::scoreMsacInFront(found.E, problem, callTest).cost &&
                    secondPlain.cost <= kInFrontMaxPlainCostRatio *
                                            scoring::scoreMsac(found.E, problem, callTest).cost) {
                    found.E = second.E;
                    found.inliers = secondPlain.inliers;
                    rep.inFrontSearchKept = true;
                }
            }
            found.addWork(second);
        }
    }
    rep.iterations = found.iterations;
    rep.hypothesesGenerated = found.hypothesesGenerated;
    rep.hypothesesConverged = found.hypothesesConverged;
    rep.hypothesesScored = found.hypothesesScored;
    rep.pointsScored = found.pointsScored;
    rep.localOptimisations = found.localOptimisations;
    rep.localOptimisationsKept = found.localOptimisationsKept;
    rep.sprtRejections = found.sprtRejections;
    // The MSAC cost of found.E at the call's threshold, when one stage has computed it (the
    // refinement's guard below needs it again).
    double winnerCost = -1.0;
    if (found.found && params.planeParallax && params.engine == ENGINE_ADAPTIVE &&
        params.score == SCORE_METHOD_MSAC) {
        const scoring::Score before = scoring::scoreMsac(found.E, problem, callTest);
        const degeneracy::PlaneParallaxResult checked =
            degeneracy::checkPlaneAndParallax(problem, callTest, found.E, before, rng);
        if (checked.improved) {
            found.E = checked.E;
            found.inliers = checked.score.inliers;
            rep.planeParallaxKept = true;
        } else {
            winnerCost = before.cost;
        }
    }
    rep.timeSearchMs = msSince(tSearch);
    if (!found.found) {
        writeMask(mask, inliers, maskWriting);
        rep.timeTotalMs = msSince(start);
        return Mat();
    }

    const int64 tRefine = getTickCount();
    const InlierTest searched = callTest.withThreshold(found.threshold);
    Matx33d E = found.E;
    if (params.refine) {
        const refine::FinalRefinementResult refined =
            refine::refineFinal(problem, found.E, searched);
        rep.refineIterations = refined.iterations;
        if (refined.improved) {
            // The refinement minimises a smooth robust loss on the points near the winner, not
            // the truncated MSAC cost on all; keep it unless it is clearly worse on the MSAC cost
            // (5% slack for the difference of the two losses), which guards against a refinement
            // pulled away by structured outliers.
            const double before = winnerCost >= 0.0 && searched.threshold == callTest.threshold
                                      ? winnerCost
                                      : scoring::scoreMsac(found.E, problem, searched).cost;
            const double after = scoring::scoreMsac(refined.E, problem, searched).cost;
            if (after <= 1.05 * before) E = refined.E;
        }
    }
    rep.inliers = scoring::inlierMask(E, problem, searched, inliers.data());
    rep.timeRefineMs = msSince(tRefine);
    if (rep.inliers < 5 ||
        !degeneracy::moreDistinctInliersThan(problem, inliers, degeneracy::kMinimalSample) ||
        !degeneracy::supportIsSignificant(E, problem, searched, rep.inliers, solver->sampleSize(),
                                          std::max(1, found.hypothesesScored))) {
        std::fill(inliers.begin(), inliers.end(), uchar(0));
        rep.inliers = 0;
        writeMask(mask, inliers, maskWriting);
        rep.timeTotalMs = msSince(start);
        return Mat();
    }
    rep.success = true;
    rep.E = unitNorm(E);
    if (report) {
        degeneracy::reportDegeneracy(problem, inliers.data(), found.threshold, rep);
    }

    if (report && params.recoverPose) {
        const int64 tPose = getTickCount();
        pose::PoseResult pr;
        if (pose::recoverPoseNormalised(E, problem, inliers.data(), nullptr, pr)) {
            rep.R = pr.R;
            rep.t = pr.t;
            rep.pointsInFront = pr.inFront;
            rep.poseRecovered = true;
        }
        rep.timePoseMs = msSince(tPose);
    }
    writeMask(mask, inliers, maskWriting);
    rep.timeTotalMs = msSince(start);
    return toMat(E);
}

} // namespace essential
} // namespace cv

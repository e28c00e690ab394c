// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The public findEssentialMatIter overloads: each turns its arguments into normalised
// correspondences and a normalised threshold, then runs the one pipeline below:
// search (MSAC or LMedS over the registered solver) -> plane and in-front checks -> IRLS refinement
// -> mask -> optional pose.

#include "opencv2/essential.hpp"

#include "degeneracy/degeneracy.hpp"
#include "degeneracy/plane_parallax.hpp"
#include "degeneracy/support_test.hpp"
#include "drop_in_estimate.hpp"
#include "geometry/essential_decomposition.hpp"
#include "input/mask_output.hpp"
#include "input/point_layouts.hpp"
#include "input/problem.hpp"
#include "pose/pose_recovery.hpp"
#include "refine/final_refinement.hpp"
#include "sampling/sample_buffer.hpp"
#include "scoring/in_front_score.hpp"
#include "scoring/msac_score.hpp"
#include "search/search.hpp"
#include "termination/opencv_time_budget.hpp"
#include "termination/termination.hpp"

#include <opencv2/calib3d.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <type_traits>
#include <utility>
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

/** To list the solutions of a five-point problem (what cv::findEssentialMat returns for exactly
five points) a solver that finds one root per call (gn, lm) is run on this many
rotated copies of the problem: view 1's points are rotated by a random Q (q1' ~ Q q1), which moves
the solver's start relative to the data, and each solution E' of the copy maps back to E = E' Q.
Measured with gn on 200 noise-free problems of the paper's protocol (cv::findEssentialMat finds
4.70 real roots on average there, the true one always): 30 / 60 / 120 copies find 4.21 / 4.53 /
4.67 roots and the true E in 192 / 197 / 199 problems, in 0.16 / 0.19 / 0.31 ms per call. */
constexpr int kFivePointStarts = 120;

/** Largest rotation of the copies: the solvers start at R = I, so this spreads their starts over
rotations up to this angle. */
constexpr double kFivePointMaxAngle = 60.0 * CV_PI / 180.0;

/** Two solutions closer than this (essential matrices of norm sqrt(2), up to sign) are the same
root: converged solutions agree to ~1e-7 (residuals below 1e-7), distinct roots differ by far more.
*/
constexpr double kSameSolution = 1e-4;

Mat solveExactlyFive(const Problem& problem, EssentialSolver& solver, RNG& rng,
                     EssentialReport& report)
{
    // A direct solver that finds (nearly) every root in one call, like nister, needs one call;
    // iterative ones and composites that contain one need the rotated copies.
    const int starts = solver.successRate() >= 0.99 ? 1 : kFivePointStarts;
    std::vector<Matx33d> buffer(static_cast<size_t>(solver.maxSolutions()));
    std::vector<Eigen::Matrix3d> found;
    std::vector<Point2d> rotated(5);
    for (int s = 0; s < starts; ++s) {
        Matx33d Q = Matx33d::eye();
        if (s > 0) {
            Vec3d axis(rng.gaussian(1.0), rng.gaussian(1.0), rng.gaussian(1.0));
            axis *= rng.uniform(0.0, kFivePointMaxAngle) / std::max(norm(axis), 1e-12);
            Rodrigues(axis, Q);
        }
        bool usable = true;
        for (int i = 0; i < 5; ++i) {
            const Vec3d q = Q * Vec3d(problem.p1[i].x, problem.p1[i].y, 1.0);
            usable &= q[2] > 0.3; // keep the rotated coordinates bounded
            rotated[i] = Point2d(q[0] / q[2], q[1] / q[2]);
        }
        if (!usable) continue;
        const int count = solver.solve(rotated.data(), problem.p2.data(), rng, buffer.data());
        ++report.hypothesesGenerated;
        report.hypothesesConverged += std::max(0, count);
        for (int h = 0; h < std::min(count, static_cast<int>(buffer.size())); ++h) {
            const Matx33d Eq = buffer[h] * Q;
            Eigen::Matrix3d E;
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    E(i, j) = Eq(i, j);
            if (!E.allFinite() || !(E.norm() > 0)) continue;
            const Eigen::Matrix3d C = geometry::canonicalEssential(E);
            // Compared up to sign: the canonical sign follows the largest entry, which is not a
            // stable choice when two entries tie in magnitude with opposite signs (forward motion
            // with no rotation gives E = [e_z]x, entries -1 and +1), so two copies of one root
            // may come back as C and -C.
            bool seen = false;
            for (const Eigen::Matrix3d& F : found)
                seen |= std::min((C - F).norm(), (C + F).norm()) < kSameSolution;
            if (!seen && found.size() < 10) found.push_back(C);
        }
    }
    if (found.empty()) return Mat();
    Mat stacked(3 * static_cast<int>(found.size()), 3, CV_64F);
    for (size_t s = 0; s < found.size(); ++s)
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                stacked.at<double>(3 * static_cast<int>(s) + i, j) =
                    found[s](i, j) / found[s].norm();
    return stacked;
}

/** The local optimisation's IRLS (each new best model of the adaptive search) refines the points
within kLoBand thresholds of the model with a Cauchy scale of kLoScaleFraction thresholds, as the
final refinement does when the noise is half the threshold (refine/final_refinement.hpp): the
points within one threshold of a model that is off are biased towards it. Measured with
bench/essential_accuracy_candidates (N = 500; docs/ACCURACY.md): against 1 threshold and half of
it, the search draws 22 / 420 samples instead of 24 / 464 at 90 / 50% inliers and takes 0.17 / 2.04
ms instead of 0.19 / 2.22 ms (400 problems), and the final estimate is as precise (AUC@1 0.944 /
0.917 against 0.944 / 0.918, 300 problems). */
constexpr double kLoBand = 2.0;
constexpr double kLoScaleFraction = 1.0;

/** Time kept back from a time budget for what follows the search: the IRLS refinement (measured
0.21 ms for 500 points with its cap of 20 iterations, about 0.4 us per point), the mask and the
pose. docs/ENGINE.md has the overshoot measurement that checks it. */
double finishingReserveMs(int numPoints)
{
    return 0.05 + 0.0005 * numPoints;
}

/** EssentialReport::degenerate: an inlier counts as explained by a rotation alone (or by a
homography) when its image-2 position is within this many Sampson thresholds of the rotated ray (or
mapped point) of image 1: the same noise gives a transfer distance in one image of about twice the
Sampson distance, which splits the error between both images. */
constexpr double kRotationOnlyDistance = 2.0;

/** ... and the estimate is degenerate when at least this fraction of its inliers is so explained.
Measured (test/test_degenerate_scenes.cpp, 300 points, 0.5 px noise, 10 scenes each): pure rotation
and baselines of 1e-4 give rotation-only fractions of 0.976 to 0.997 (the remainder is noise beyond
twice the threshold), planes and single-depth scenes homography fractions of 0.968 to 1; a baseline
of 0.05 gives at most 0.11 and 0.31, and 120 problems of the synthetic protocol at most 0.036 and
0.093. */
constexpr double kDegenerateFraction = 0.9;

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

/** Five correspondences are a minimal set: an essential matrix fits any five exactly. */
constexpr int kMinimalSample = 5;

/** Whether the inliers hold more than `count` (<= kMinimalSample) distinct correspondences.
Repeated correspondences add no constraint: five distinct points given twelve times each are fitted
exactly by up to ten essential matrices, and 60 "inliers" of one of them are no evidence (the
chance-support test counts points, not distinct ones). Stops at the first count + 1 distinct ones,
so on ordinary data it looks at a handful of points. */
bool moreDistinctInliersThan(const Problem& problem, const std::vector<uchar>& mask, int count)
{
    std::array<size_t, kMinimalSample + 1> distinct{};
    int found = 0;
    for (size_t i = 0; i < mask.size(); ++i) {
        if (!mask[i]) continue;
        bool repeated = false;
        for (int k = 0; k < found && !repeated; ++k) {
            const size_t j = distinct[static_cast<size_t>(k)];
            repeated = problem.x1[i] == problem.x1[j] && problem.y1[i] == problem.y1[j] &&
                       problem.x2[i] == problem.x2[j] && problem.y2[i] == problem.y2[j];
        }
        if (repeated) continue;
        distinct[static_cast<size_t>(found++)] = i;
        if (found > count) return true;
    }
    return false;
}

/** Whether a call has a time budget: a positive finite timeBudgetMs (0 and +inf mean none). */
bool hasTimeBudget(const EssentialParams& params)
{
    return params.timeBudgetMs > 0 && std::isfinite(params.timeBudgetMs);
}

/** The pipeline shared by every overload. `problem` holds normalised points and threshold;
`maskWriting` says how the mask goes into the caller's array. */
Mat estimate(const Problem& problem, const EssentialParams& params, OutputArray mask,
             MaskWriting maskWriting, EssentialReport* report, int64 start)
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
        Mat stacked = solveExactlyFive(problem, *solver, rng, rep);
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

    const int64 tSearch = getTickCount();
    ransac::SearchSettings settings;
    settings.confidence = params.confidence;
    settings.maxIters = params.maxIterations;
    settings.preemptiveHypotheses = params.preemptiveHypotheses;
    settings.preemptiveBlockSize = params.preemptiveBlockSize;
    settings.lo.iterations = params.loIterations;
    settings.lo.sampleSize = params.loSampleSize;
    settings.lo.scale = problem.threshold * kLoScaleFraction;
    settings.lo.band = kLoBand;
    settings.prosac = params.sampler == SAMPLING_PROSAC;
    settings.napsacEvery = params.sampler == SAMPLING_NAPSAC               ? 1
                           : params.sampler == SAMPLING_PROGRESSIVE_NAPSAC ? 2
                                                                           : 0;
    settings.sprt = params.sprt; // used by the adaptive MSAC loop only
    if (params.sampleBudget == BUDGET_OPENCV_TIME) {
        settings.minSampleCap = ransac::opencvTimeSamples(params.maxIterations, n);
        settings.localSamplesInBudget =
            params.budgetLocalSamples && params.sampler == SAMPLING_UNIFORM;
    }
    if (hasTimeBudget(params))
        settings.deadline =
            ransac::Deadline::after(params.timeBudgetMs - msSince(start) - finishingReserveMs(n));
    auto search = [&]() {
        if (params.engine == ENGINE_OPENCV)
            return ransac::searchOpenCvLoop(problem, *solver, rng, settings,
                                            params.score == SCORE_METHOD_LMEDS ? LMEDS : RANSAC);
        if (params.engine == ENGINE_PREEMPTIVE)
            return ransac::searchPreemptive(problem, *solver, rng, settings);
        if (params.score == SCORE_METHOD_LMEDS)
            return ransac::searchLmeds(problem, *solver, rng, settings);
        return ransac::searchMsac(problem, *solver, rng, settings);
    };
    ransac::SearchResult found = search();
    if ((!found.found || found.inliers <= kMinimalSample) && params.engine != ENGINE_OPENCV &&
        ransac::SampleBuffer::checksCheirality(*solver)) {
        // No sample put in front of both cameras gave a model with support beyond its own sample:
        // the data may contradict cheirality (points behind a camera, as OpenCV's own synthetic
        // test makes with unrestricted random rotations; with 6 such points every sample mixes
        // points in front and behind, and only wrong roots pass). The search runs again without
        // the check, as cv::findEssentialMat would. On photographs a search nearly always finds a
        // model with more support than that, and this second pass is rare.
        settings.sampleCheirality = false;
        settings.setSolverThreshold = false;
        found = search();
    }
    if (found.found && params.inFrontCheck && params.engine == ENGINE_ADAPTIVE &&
        params.score == SCORE_METHOD_MSAC && settings.sampleCheirality) {
        // A winner with many inliers behind the cameras is a wrong model that the plain MSAC cost
        // preferred (scoring/in_front_score.hpp): search again scoring only the inliers in front,
        // and keep whichever winner has the lower in-front cost.
        const int inFront = ransac::inliersInFront(found.E, problem, problem.threshold);
        // The second search gets at most the confidence cap of maxIters (not the extended
        // budget, minSampleCap), and no more than the first left of the call's sample budget: a
        // search that spent the whole budget met hard data, often with none of the geometry,
        // where a second one would double the call's cost for little.
        const int confidenceCap = ransac::sampleCap(params.maxIterations, solver->successRate());
        const int left = std::max(confidenceCap, settings.minSampleCap) - found.iterations;
        if (left > 0 && found.inliers - inFront > kBehindFraction * found.inliers) {
            ransac::SearchSettings inFrontSettings = settings;
            inFrontSettings.minSampleCap = 0;
            inFrontSettings.sampleLimit = std::min(confidenceCap, left);
            inFrontSettings.scoreInFront = true;
            inFrontSettings.sprt = false;
            inFrontSettings.setSolverThreshold = false;
            const ransac::SearchResult second =
                ransac::searchMsac(problem, *solver, rng, inFrontSettings);
            rep.inFrontSearch = true;
            if (second.found) {
                const ransac::Score secondPlain = ransac::scoreMsac(second.E, problem);
                if (ransac::scoreMsacInFront(second.E, problem).cost <
                        ransac::scoreMsacInFront(found.E, problem).cost &&
                    secondPlain.cost <=
                        kInFrontMaxPlainCostRatio * ransac::scoreMsac(found.E, problem).cost) {
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
    if (found.found && params.planeParallax && params.engine == ENGINE_ADAPTIVE &&
        params.score == SCORE_METHOD_MSAC) {
        const ransac::Score before = ransac::scoreMsac(found.E, problem);
        const ransac::PlaneParallaxResult checked =
            ransac::checkPlaneAndParallax(problem, found.E, before, rng);
        if (checked.improved) {
            found.E = checked.E;
            found.inliers = checked.score.inliers;
            rep.planeParallaxKept = true;
        }
    }
    rep.timeSearchMs = msSince(tSearch);
    if (!found.found) {
        writeMask(mask, inliers, maskWriting);
        rep.timeTotalMs = msSince(start);
        return Mat();
    }

    const int64 tRefine = getTickCount();
    Matx33d E = found.E;
    if (params.refine) {
        const refine::FinalRefinementResult refined =
            refine::refineFinal(problem, found.E, found.threshold);
        rep.refineIterations = refined.iterations;
        if (refined.improved) {
            // The refinement minimises a smooth robust loss on the points near the winner, not
            // the truncated MSAC cost on all; keep it unless it is clearly worse on the MSAC cost
            // (5% slack for the difference of the two losses), which guards against a refinement
            // pulled away by structured outliers.
            Problem scored = problem; // threshold of the search (differs for LMedS)
            scored.threshold = found.threshold;
            const double before = ransac::scoreMsac(found.E, scored).cost;
            const double after = ransac::scoreMsac(refined.E, scored).cost;
            if (after <= 1.05 * before) E = refined.E;
        }
    }
    rep.inliers = ransac::inlierMask(E, problem, found.threshold, inliers.data());
    rep.timeRefineMs = msSince(tRefine);
    if (rep.inliers < 5 || !moreDistinctInliersThan(problem, inliers, kMinimalSample) ||
        !ransac::supportIsSignificant(E, problem, found.threshold, rep.inliers,
                                      solver->sampleSize(), std::max(1, found.hypothesesScored))) {
        std::fill(inliers.begin(), inliers.end(), uchar(0));
        rep.inliers = 0;
        writeMask(mask, inliers, maskWriting);
        rep.timeTotalMs = msSince(start);
        return Mat();
    }
    rep.success = true;
    rep.E = unitNorm(E);
    if (report) {
        rep.rotationOnlyFraction =
            geometry::rotationOnlyFraction(problem.p1.data(), problem.p2.data(), inliers.data(), n,
                                           kRotationOnlyDistance * found.threshold);
        rep.homographyFraction =
            geometry::homographyFraction(problem.p1.data(), problem.p2.data(), inliers.data(), n,
                                         kRotationOnlyDistance * found.threshold);
        rep.degenerate = rep.rotationOnlyFraction >= kDegenerateFraction ||
                         rep.homographyFraction >= kDegenerateFraction;
    }

    if (report && params.recoverPose) {
        const int64 tPose = getTickCount();
        pose::PoseResult pr;
        if (pose::recoverPoseNormalised(E, problem.p1.data(), problem.p2.data(), n, inliers.data(),
                                        nullptr, pr)) {
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

/** LO iterations of the USAC flags (the table in essential.hpp and docs/ENGINE.md), in the spirit
of OpenCV's usac::setParameters: USAC_FAST fewer, USAC_ACCURATE more than the default. */
constexpr int kUsacLoIterations = 5;
constexpr int kUsacFastLoIterations = 2;
constexpr int kUsacAccurateLoIterations = 10;

/** The engine settings a USAC method flag stands for (see the table in essential.hpp). */
void applyUsacFlag(int method, EssentialParams& p)
{
    switch (method) {
    case USAC_DEFAULT:
    case USAC_PARALLEL: // runs single-threaded
    case USAC_FM_8PTS:  // an essential matrix all the same, from the configured solver
    case USAC_MAGSAC:   // MSAC scoring with the given threshold
        p.loIterations = kUsacLoIterations;
        break;
    case USAC_FAST:
        p.loIterations = kUsacFastLoIterations;
        break;
    case USAC_ACCURATE:
        p.loIterations = kUsacAccurateLoIterations;
        break;
    case USAC_PROSAC:
        p.sampler = SAMPLING_PROSAC;
        p.loIterations = kUsacLoIterations;
        break;
    default:
        break;
    }
}

} // namespace

EssentialParams dropInParams(int method, double prob, double threshold, int maxIters)
{
    checkMethod(method);
    checkConfidence(prob);
    if (method != LMEDS) checkThreshold(threshold);
    checkMaxIters(maxIters);
    EssentialParams p;
    p.score = method == LMEDS ? SCORE_METHOD_LMEDS : SCORE_METHOD_MSAC;
    p.confidence = prob;
    p.threshold = method == LMEDS ? 1.0 : threshold;
    p.maxIterations = maxIters;
    applyUsacFlag(method, p);
    // OpenCV 4.6's USAC thresholds the symmetric epipolar distance for essential matrices.
    if (method >= USAC_DEFAULT) p.distance = DISTANCE_SYMMETRIC_EPIPOLAR;
    return p;
}

namespace {

/** An enum field (of UsacParams or EssentialParams) as the int it holds. A value outside the
enumeration (which a caller can make only by a cast) must be rejected with a message, but loading it
as the enum type is undefined behaviour (UBSan's -fsanitize=enum reports it), so the bytes are read
as an int. */
template <typename Enum> int rawEnum(const Enum& field)
{
    static_assert(sizeof(Enum) == sizeof(int), "the enums read here are int-sized");
    int value;
    std::memcpy(&value, &field, sizeof value);
    return value;
}

/** UsacParams has final_polisher and final_polisher_iterations from OpenCV 4.7 on (4.6 has
neither); detected from the struct itself rather than from a version number. */
template <typename U, typename = void> struct HasFinalPolisher : std::false_type
{
};
template <typename U>
struct HasFinalPolisher<U,
                        std::void_t<decltype(std::declval<const U&>().final_polisher),
                                    decltype(std::declval<const U&>().final_polisher_iterations)>>
    : std::true_type
{
};

/** Reads final_polisher where UsacParams has it. The module's polisher is its own final IRLS
refinement (EssentialParams::refine): NONE_POLISHER (0) switches it off, as does
final_polisher_iterations = 0; LSQ_POLISHER (1), MAGSAC (2) and COV_POLISHER (3, OpenCV's default)
all run it, to its own convergence test (the iteration count is not a cap there). Anything else is
refused by name. */
template <typename U> void readFinalPolisher(const U& usac, EssentialParams& p)
{
    if constexpr (HasFinalPolisher<U>::value) {
        const int polisher = rawEnum(usac.final_polisher);
        if (polisher < 0 || polisher > 3)
            CV_Error(Error::StsBadArg, "UsacParams::final_polisher " + std::to_string(polisher) +
                                           " is not a PolishingMethod");
        if (usac.final_polisher_iterations < 0)
            CV_Error(Error::StsBadArg, "UsacParams::final_polisher_iterations must be >= 0, got " +
                                           std::to_string(usac.final_polisher_iterations));
        p.refine = polisher != 0 && usac.final_polisher_iterations > 0;
    } else {
        (void)usac;
        (void)p;
    }
}

/** The module's settings from a UsacParams (the mapping documented in essential.hpp). */
EssentialParams usacParams(const UsacParams& usac)
{
    EssentialParams p;
    const int score = rawEnum(usac.score), sampler = rawEnum(usac.sampler),
              loMethod = rawEnum(usac.loMethod);
    switch (score) {
    case SCORE_METHOD_RANSAC:
    case SCORE_METHOD_MSAC:
    case SCORE_METHOD_MAGSAC: // MSAC with the given threshold (MAGSAC++ is not implemented)
        p.score = SCORE_METHOD_MSAC;
        break;
    case SCORE_METHOD_LMEDS:
        p.score = SCORE_METHOD_LMEDS;
        break;
    default:
        CV_Error(Error::StsBadArg,
                 "UsacParams::score " + std::to_string(score) + " is not a ScoreMethod");
    }
    switch (sampler) {
    case SAMPLING_UNIFORM:
    case SAMPLING_PROSAC:
    case SAMPLING_NAPSAC:
    case SAMPLING_PROGRESSIVE_NAPSAC:
        p.sampler = static_cast<SamplingMethod>(sampler);
        break;
    default:
        CV_Error(Error::StsBadArg,
                 "UsacParams::sampler " + std::to_string(sampler) + " is not a SamplingMethod");
    }
    switch (loMethod) {
    case LOCAL_OPTIM_NULL:
        p.loIterations = 0;
        break;
    case LOCAL_OPTIM_INNER_LO:
    case LOCAL_OPTIM_INNER_AND_ITER_LO:
    case LOCAL_OPTIM_GC:
    case LOCAL_OPTIM_SIGMA:
        if (usac.loIterations < 0)
            CV_Error(Error::StsBadArg, "UsacParams::loIterations must be >= 0, got " +
                                           std::to_string(usac.loIterations));
        if (usac.loSampleSize < 0 || (usac.loSampleSize > 0 && usac.loSampleSize < 5))
            CV_Error(Error::StsBadArg, "UsacParams::loSampleSize must be 0 (all inliers) or >= 5, "
                                       "got " +
                                           std::to_string(usac.loSampleSize));
        p.loIterations = usac.loIterations;
        p.loSampleSize = usac.loSampleSize;
        break;
    default:
        CV_Error(Error::StsBadArg,
                 "UsacParams::loMethod " + std::to_string(loMethod) + " is not a LocalOptimMethod");
    }
    // isParallel and neighborsSearch are ignored (see essential.hpp).
    checkConfidence(usac.confidence);
    // The module's LMedS search has no local sampler: with SCORE_METHOD_LMEDS the NAPSAC samplers
    // run as uniform sampling (the drop-in forms accept what OpenCV accepts; see essential.hpp).
    if ((p.sampler == SAMPLING_NAPSAC || p.sampler == SAMPLING_PROGRESSIVE_NAPSAC) &&
        p.score == SCORE_METHOD_LMEDS)
        p.sampler = SAMPLING_UNIFORM;
    if (p.score != SCORE_METHOD_LMEDS) checkThreshold(usac.threshold);
    checkMaxIters(usac.maxIterations, "UsacParams::maxIterations");
    p.confidence = usac.confidence;
    p.threshold = p.score == SCORE_METHOD_LMEDS ? 1.0 : usac.threshold;
    p.maxIterations = usac.maxIterations;
    p.seed = static_cast<uint64>(static_cast<unsigned>(usac.randomGeneratorState));
    p.distance = DISTANCE_SYMMETRIC_EPIPOLAR; // as OpenCV's USAC (LMedS ranks by Sampson)
    readFinalPolisher(usac, p);
    return p;
}

/** The distance the problem's threshold applies to: LMedS ranks by the Sampson distance whatever
was asked (as OpenCV's LMEDS), everything else uses EssentialParams::distance. */
EssentialDistance inlierDistance(const EssentialParams& params)
{
    return params.score == SCORE_METHOD_LMEDS ? DISTANCE_SAMPSON : params.distance;
}

Mat estimateWithCamera(InputArray points1, InputArray points2, const Matx33d& K,
                       const EssentialParams& params, PointReading reading, OutputArray mask,
                       MaskWriting maskWriting, EssentialReport* report, int64 start)
{
    std::vector<Point2d> p1, p2;
    readPointPair(points1, points2, reading, p1, p2);
    checkPointSets(p1, p2, 5);
    const double meanFocal = 0.5 * (K(0, 0) + K(1, 1));
    std::vector<Point2d> n1 = normalisePoints(p1, K), n2 = normalisePoints(p2, K);
    checkNormalisedPoints(n1, "points1");
    checkNormalisedPoints(n2, "points2");
    Problem problem =
        makeProblem(std::move(n1), std::move(n2), normalisedThreshold(params.threshold, meanFocal),
                    inlierDistance(params));
    return estimate(problem, params, mask, maskWriting, report, start);
}

void checkDistortion(InputArray d, const char* name)
{
    if (d.empty()) return;
    Mat m = d.getMat();
    const size_t total = m.total() * static_cast<size_t>(m.channels());
    // Any integer or floating depth, as cv::undistortPoints converts it (CV_16F aside).
    if (m.depth() == CV_16F) CV_Error(Error::StsBadArg, std::string(name) + " must not be CV_16F");
    if (total != 4 && total != 5 && total != 8 && total != 12 && total != 14)
        CV_Error(Error::StsBadArg, std::string(name) +
                                       " must have 4, 5, 8, 12 or 14 coefficients (got " +
                                       std::to_string(total) + ")");
    Mat d64;
    m.convertTo(d64, CV_64F);
    if (!checkRange(d64)) CV_Error(Error::StsBadArg, std::string(name) + " has a non-finite entry");
}

} // namespace

Mat estimateTwoCameras(InputArray points1, InputArray points2, InputArray cameraMatrix1,
                       InputArray distCoeffs1, InputArray cameraMatrix2, InputArray distCoeffs2,
                       const EssentialParams& params, PointReading reading, OutputArray mask,
                       MaskWriting maskWriting, std::vector<Point2d>* normalised1,
                       std::vector<Point2d>* normalised2)
{
    const int64 start = getTickCount();
    std::vector<Point2d> p1, p2;
    readPointPair(points1, points2, reading, p1, p2);
    checkPointSets(p1, p2, 5);
    const Matx33d K1 = readCameraMatrix(cameraMatrix1, "cameraMatrix1");
    const Matx33d K2 = readCameraMatrix(cameraMatrix2, "cameraMatrix2");
    checkDistortion(distCoeffs1, "distCoeffs1");
    checkDistortion(distCoeffs2, "distCoeffs2");
    std::vector<Point2d> n1, n2;
    undistortPoints(p1, n1, K1, distCoeffs1);
    undistortPoints(p2, n2, K2, distCoeffs2);
    // Extreme distortion coefficients can send undistorted points to infinity or NaN.
    checkNormalisedPoints(n1, "points1 (undistorted with distCoeffs1)");
    checkNormalisedPoints(n2, "points2 (undistorted with distCoeffs2)");
    if (normalised1) *normalised1 = n1;
    if (normalised2) *normalised2 = n2;
    const double meanFocal = 0.25 * (K1(0, 0) + K1(1, 1) + K2(0, 0) + K2(1, 1));
    Problem problem =
        makeProblem(std::move(n1), std::move(n2), normalisedThreshold(params.threshold, meanFocal),
                    inlierDistance(params));
    return estimate(problem, params, mask, maskWriting, nullptr, start);
}

Mat findEssentialMatIter(InputArray points1, InputArray points2, InputArray cameraMatrix,
                         int method, double prob, double threshold, int maxIters, OutputArray mask)
{
    const int64 start = getTickCount();
    const EssentialParams params = dropInParams(method, prob, threshold, maxIters);
    const Matx33d K = readCameraMatrix(cameraMatrix, "cameraMatrix");
    return estimateWithCamera(points1, points2, K, params, readingForMethod(method), mask,
                              maskWritingForMethod(method), nullptr, start);
}

#if CV_VERSION_MAJOR < 5
Mat findEssentialMatIter(InputArray points1, InputArray points2, InputArray cameraMatrix,
                         int method, double prob, double threshold, OutputArray mask)
{
    return findEssentialMatIter(points1, points2, cameraMatrix, method, prob, threshold, 1000,
                                mask);
}
#endif

Mat findEssentialMatIter(InputArray points1, InputArray points2, double focal, Point2d pp,
                         int method, double prob, double threshold, int maxIters, OutputArray mask)
{
    const int64 start = getTickCount();
    const EssentialParams params = dropInParams(method, prob, threshold, maxIters);
    return estimateWithCamera(points1, points2, cameraFromFocal(focal, pp), params,
                              readingForMethod(method), mask, maskWritingForMethod(method), nullptr,
                              start);
}

#if CV_VERSION_MAJOR < 5
Mat findEssentialMatIter(InputArray points1, InputArray points2, double focal, Point2d pp,
                         int method, double prob, double threshold, OutputArray mask)
{
    return findEssentialMatIter(points1, points2, focal, pp, method, prob, threshold, 1000, mask);
}
#endif

Mat findEssentialMatIter(InputArray points1, InputArray points2, InputArray cameraMatrix1,
                         InputArray distCoeffs1, InputArray cameraMatrix2, InputArray distCoeffs2,
                         int method, double prob, double threshold, OutputArray mask)
{
    const EssentialParams params = dropInParams(method, prob, threshold, 1000);
    // OpenCV undistorts first (cv::undistortPoints reads the points), whatever the method.
    return estimateTwoCameras(points1, points2, cameraMatrix1, distCoeffs1, cameraMatrix2,
                              distCoeffs2, params, PointReading::Undistort, mask,
                              maskWritingForMethod(method));
}

Mat findEssentialMatIter(InputArray points1, InputArray points2, InputArray cameraMatrix1,
                         InputArray cameraMatrix2, InputArray distCoeffs1, InputArray distCoeffs2,
                         OutputArray mask, const UsacParams& usac)
{
    const EssentialParams params = usacParams(usac);
    // OpenCV's USAC undistorts (a continuous copy of) the points only when there are coefficients.
    const PointReading reading = distCoeffs1.empty() && distCoeffs2.empty()
                                     ? PointReading::Usac
                                     : PointReading::UndistortCopy;
    return estimateTwoCameras(points1, points2, cameraMatrix1, distCoeffs1, cameraMatrix2,
                              distCoeffs2, params, reading, mask, MaskWriting::Usac);
}

Mat findEssentialMatIter(InputArray points1, InputArray points2, InputArray cameraMatrix,
                         const EssentialParams& params, OutputArray mask, EssentialReport* report)
{
    const int64 start = getTickCount();
    const int score = rawEnum(params.score), engine = rawEnum(params.engine),
              sampler = rawEnum(params.sampler), budget = rawEnum(params.sampleBudget),
              distance = rawEnum(params.distance);
    switch (score) {
    case SCORE_METHOD_MSAC:
    case SCORE_METHOD_LMEDS:
        break;
    case SCORE_METHOD_RANSAC:
    case SCORE_METHOD_MAGSAC:
        CV_Error(
            Error::StsNotImplemented,
            std::string("EssentialParams::score ") +
                (score == SCORE_METHOD_RANSAC ? "SCORE_METHOD_RANSAC" : "SCORE_METHOD_MAGSAC") +
                " is not implemented; use SCORE_METHOD_MSAC or SCORE_METHOD_LMEDS");
    default:
        CV_Error(Error::StsBadArg, "EssentialParams::score must be SCORE_METHOD_MSAC or "
                                   "SCORE_METHOD_LMEDS, got " +
                                       std::to_string(score));
    }
    if (engine != ENGINE_ADAPTIVE && engine != ENGINE_OPENCV && engine != ENGINE_PREEMPTIVE)
        CV_Error(Error::StsBadArg, "EssentialParams::engine must be ENGINE_ADAPTIVE, "
                                   "ENGINE_PREEMPTIVE or ENGINE_OPENCV, got " +
                                       std::to_string(engine));
    if (engine == ENGINE_PREEMPTIVE && score != SCORE_METHOD_MSAC)
        CV_Error(Error::StsNotImplemented,
                 "ENGINE_PREEMPTIVE scores with MSAC: EssentialParams::score must be "
                 "SCORE_METHOD_MSAC");
    if (!(params.timeBudgetMs >= 0))
        CV_Error(Error::StsBadArg, "EssentialParams::timeBudgetMs must be >= 0 (0 or +inf: no "
                                   "budget), got " +
                                       std::to_string(params.timeBudgetMs));
    if (hasTimeBudget(params) && engine == ENGINE_OPENCV)
        CV_Error(Error::StsNotImplemented,
                 "EssentialParams::timeBudgetMs is not supported by ENGINE_OPENCV (OpenCV's loop "
                 "has no deadline); use ENGINE_ADAPTIVE or ENGINE_PREEMPTIVE");
    if (params.preemptiveHypotheses < 0)
        CV_Error(Error::StsBadArg, "EssentialParams::preemptiveHypotheses must be >= 0");
    if (params.preemptiveBlockSize < 1)
        CV_Error(Error::StsBadArg, "EssentialParams::preemptiveBlockSize must be >= 1");
    if (params.loIterations < 0)
        CV_Error(Error::StsBadArg, "EssentialParams::loIterations must be >= 0, got " +
                                       std::to_string(params.loIterations));
    if (params.loSampleSize < 0 || (params.loSampleSize > 0 && params.loSampleSize < 5))
        CV_Error(Error::StsBadArg,
                 "EssentialParams::loSampleSize must be 0 (all inliers) or >= 5, got " +
                     std::to_string(params.loSampleSize));
    if (sampler != SAMPLING_UNIFORM && sampler != SAMPLING_PROSAC && sampler != SAMPLING_NAPSAC &&
        sampler != SAMPLING_PROGRESSIVE_NAPSAC)
        CV_Error(Error::StsBadArg, "EssentialParams::sampler must be SAMPLING_UNIFORM, "
                                   "SAMPLING_PROSAC, SAMPLING_NAPSAC or "
                                   "SAMPLING_PROGRESSIVE_NAPSAC, got " +
                                       std::to_string(sampler));
    if (sampler == SAMPLING_PROSAC && engine != ENGINE_ADAPTIVE)
        CV_Error(Error::StsNotImplemented,
                 "EssentialParams::sampler SAMPLING_PROSAC needs ENGINE_ADAPTIVE");
    if ((sampler == SAMPLING_NAPSAC || sampler == SAMPLING_PROGRESSIVE_NAPSAC) &&
        (engine != ENGINE_ADAPTIVE || score != SCORE_METHOD_MSAC))
        CV_Error(
            Error::StsNotImplemented,
            std::string("EssentialParams::sampler ") +
                (sampler == SAMPLING_NAPSAC ? "SAMPLING_NAPSAC" : "SAMPLING_PROGRESSIVE_NAPSAC") +
                " needs ENGINE_ADAPTIVE with SCORE_METHOD_MSAC");
    if (budget != BUDGET_CONFIDENCE && budget != BUDGET_OPENCV_TIME)
        CV_Error(Error::StsBadArg,
                 "EssentialParams::sampleBudget must be BUDGET_CONFIDENCE or BUDGET_OPENCV_TIME, "
                 "got " +
                     std::to_string(budget));
    if (distance != DISTANCE_SAMPSON && distance != DISTANCE_SYMMETRIC_EPIPOLAR)
        CV_Error(Error::StsBadArg, "EssentialParams::distance must be DISTANCE_SAMPSON or "
                                   "DISTANCE_SYMMETRIC_EPIPOLAR, got " +
                                       std::to_string(distance));
    checkConfidence(params.confidence);
    checkThreshold(params.threshold);
    checkMaxIters(params.maxIterations, "EssentialParams::maxIterations");
    const Matx33d K = readCameraMatrix(cameraMatrix, "cameraMatrix");
    // The module's own overload reads every layout of any drop-in form (the USAC reading accepts
    // them all) and writes the mask as N x 1.
    return estimateWithCamera(points1, points2, K, params, PointReading::Usac, mask,
                              MaskWriting::Usac, report, start);
}

Mat findEssentialMatIter(InputArray points1, InputArray points2, InputArray cameraMatrix,
                         const EssentialParams& params, OutputArray mask, EssentialReport& report)
{
    return findEssentialMatIter(points1, points2, cameraMatrix, params, mask, &report);
}

} // namespace essential
} // namespace cv

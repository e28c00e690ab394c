// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The input-layer fuzz target: every public overload (findEssentialMatIter's seven,
// recoverPose's four, findEssentialMatBatch) on arbitrary matrices (any shape, depth, channel
// count and continuity, values including NaN, inf, denormals, huge and tiny magnitudes) and
// arbitrary numbers, with the estimate itself kept tiny so that the input checks dominate: at
// most 8 correspondences and a few samples where a form takes a cap, at most 5 (no search: the
// five-point solutions or an error) where it does not. The answer must be a cv::Exception or keep
// the documented contract (fuzz_contract.hpp).

#include "fuzz_builders.hpp"
#include "fuzz_contract.hpp"

#include <opencv2/essential.hpp>

#include <limits>
#include <vector>

namespace {

using namespace essential_fuzz;
namespace ess = cv::essential;

/** Points: an arbitrary matrix, or a valid layout of n points. `maxSide` 5 keeps any layout at
five points or fewer (the forms without an iteration cap). */
cv::Mat points(FuzzInput& in, int n, int maxSide)
{
    return in.pick(2) ? anyMat(in, maxSide) : makePoints(in, n);
}

cv::Mat camera(FuzzInput& in)
{
    return in.pick(4) == 0 ? anyMat(in, 4) : makeCamera(in);
}

cv::Mat distortion(FuzzInput& in)
{
    return in.pick(4) == 0 ? anyMat(in, 15) : makeDistortion(in);
}

/** A mask argument: none, or a pre-allocated matrix of any kind (the API must replace it). */
cv::Mat maskArgument(FuzzInput& in)
{
    return in.pick(3) == 0 ? anyMat(in) : cv::Mat();
}

/** The number of points an answer's mask must have. The API reads some layouts differently
per form (USAC: one point per element of a multi-channel array, 2 x N transposed; see
point_layouts.hpp), so the mask's own length is taken when it is plausible: at least one, at most
one per element of the points. */
int countOf(const cv::Mat& p, const cv::Mat& mask)
{
    const int elements = static_cast<int>(p.total()) * p.channels();
    if (mask.rows < 1 || mask.rows > elements) broken("mask length impossible for the points");
    return mask.rows;
}

ess::EssentialParams tinyParams(FuzzInput& in)
{
    ess::EssentialParams params;
    static const char* solvers[] = {"gn", "lm", "nister", "robust", "gn+nister", "", "x+", "gn:0"};
    params.solver = solvers[in.pick(8)];
    setScore(in, params, 4);
    setEnumBits(params.engine, in.pick(8) == 0 ? in.pick(5) - 1 : in.pick(3));
    params.timeBudgetMs = in.pick(4) == 0 ? in.anyDouble() : 0.0;
    if (params.timeBudgetMs > 0.2) params.timeBudgetMs = 0.2;
    params.preemptiveHypotheses = in.pick(12) - 2;
    params.preemptiveBlockSize = in.pick(12) - 2;
    params.confidence = makeProb(in);
    params.threshold = makeThreshold(in);
    params.maxIterations = makeMaxIters(in, 4);
    params.loIterations = in.pick(5) - 1;
    params.loSampleSize = in.pick(14) - 1;
    setEnumBits(params.sampler, in.pick(4) == 0 ? in.pick(6) - 1 : 0);
    setEnumBits(params.sampleBudget, in.pick(4) - 1);
    params.distance = static_cast<ess::EssentialDistance>(in.pick(2));
    params.planeParallax = in.pick(2) != 0;
    params.budgetLocalSamples = in.pick(2) != 0;
    params.sprt = in.pick(2) != 0;
    params.refine = in.pick(2) != 0;
    params.recoverPose = in.pick(2) != 0;
    return params;
}

cv::Mat anyEssential(FuzzInput& in)
{
    if (in.pick(2)) return anyMat(in, 9);
    const cv::Vec3d rvec(in.unit() - 0.5, in.unit() - 0.5, in.unit() - 0.5);
    cv::Matx33d R;
    cv::Rodrigues(rvec, R);
    const cv::Vec3d t(in.unit() - 0.5, in.unit() - 0.5, in.unit() - 0.5);
    return cv::Mat(cv::Matx33d(0, -t[2], t[1], t[2], 0, -t[0], -t[1], t[0], 0) * R);
}

void runOne(FuzzInput& in)
{
    const int api = in.pick(12);
    // Forms with an iteration cap (0, 2, 5, 6, 9, 10, 11) may see up to 8 points; the others at
    // most 5, which never searches.
    const bool capped = api == 0 || api == 2 || api == 5 || api == 6 || api >= 9;
    const int maxSide = capped ? 8 : 5;
    const int n = in.pick(4) == 0 ? in.pick(maxSide + 1) : 5 + (capped ? in.pick(4) : 0);
    const cv::Mat p1 = points(in, n, maxSide), p2 = points(in, n, maxSide);
    cv::Mat mask = maskArgument(in);
    switch (api) {
    case 0: {
        const cv::Mat K = camera(in);
        const int method = makeMethod(in);
        const double prob = makeProb(in), thr = makeThreshold(in);
        const int iters = makeMaxIters(in, 4);
        const cv::Mat E = ess::findEssentialMatIter(p1, p2, K, method, prob, thr, iters, mask);
        checkEssential(E, mask, countOf(p1, mask), true);
        break;
    }
    case 1: {
        const cv::Mat K = camera(in);
        const int method = makeMethod(in);
        const double prob = makeProb(in), thr = makeThreshold(in);
#if CV_VERSION_MAJOR < 5
        const cv::Mat E = ess::findEssentialMatIter(p1, p2, K, method, prob, thr, mask);
#else // OpenCV 5 has no form without maxIters: its default instead
        const cv::Mat E = ess::findEssentialMatIter(p1, p2, K, method, prob, thr, 1000, mask);
#endif
        checkEssential(E, mask, countOf(p1, mask), true);
        break;
    }
    case 2:
    case 3: {
        const double focal = in.pick(2) ? in.anyDouble() : 50.0 + in.pick(1000);
        const cv::Point2d pp(in.pick(2) ? in.anyDouble() : in.pick(640), in.anyDouble());
        const int method = makeMethod(in);
        const double prob = makeProb(in), thr = makeThreshold(in);
        const cv::Mat E =
            api == 2 ? ess::findEssentialMatIter(p1, p2, focal, pp, method, prob, thr,
                                                 makeMaxIters(in, 4), mask)
#if CV_VERSION_MAJOR < 5
                     : ess::findEssentialMatIter(p1, p2, focal, pp, method, prob, thr, mask);
#else
                     : ess::findEssentialMatIter(p1, p2, focal, pp, method, prob, thr, 1000, mask);
#endif
        checkEssential(E, mask, countOf(p1, mask), true);
        break;
    }
    case 4: {
        const cv::Mat K1 = camera(in), d1 = distortion(in), K2 = camera(in), d2 = distortion(in);
        const int method = makeMethod(in);
        const double prob = makeProb(in), thr = makeThreshold(in);
        const cv::Mat E =
            ess::findEssentialMatIter(p1, p2, K1, d1, K2, d2, method, prob, thr, mask);
        checkEssential(E, mask, countOf(p1, mask), true);
        break;
    }
    case 5: {
        const cv::Mat K1 = camera(in), K2 = camera(in), d1 = distortion(in), d2 = distortion(in);
        cv::UsacParams usac;
        usac.confidence = makeProb(in);
        usac.threshold = makeThreshold(in);
        usac.maxIterations = makeMaxIters(in, 4);
        usac.randomGeneratorState = static_cast<int>(in.pick(1 << 30));
        usac.score = static_cast<cv::ScoreMethod>(in.pick(6));
        usac.sampler = static_cast<cv::SamplingMethod>(in.pick(6));
        usac.loMethod = static_cast<cv::LocalOptimMethod>(in.pick(7));
        usac.loIterations = in.pick(6) - 1;
        usac.loSampleSize = in.pick(14) - 1;
        usac.neighborsSearch = static_cast<cv::NeighborSearchMethod>(in.pick(4));
        const cv::Mat E = ess::findEssentialMatIter(p1, p2, K1, K2, d1, d2, mask, usac);
        checkEssential(E, mask, countOf(p1, mask), true);
        break;
    }
    case 6: {
        const cv::Mat K = camera(in);
        const ess::EssentialParams params = tinyParams(in);
        ess::EssentialReport report;
        const cv::Mat E = ess::findEssentialMatIter(p1, p2, K, params, mask, &report);
        checkEssential(E, mask, countOf(p1, mask), true);
        if (report.success == E.empty()) broken("report.success disagrees with E");
        break;
    }
    case 7:
    case 8:
    case 9: {
        const cv::Mat E = anyEssential(in);
        cv::Mat R, t;
        int inFront = 0;
        // The points' count as recoverPose reads them: a view that is not continuous is accepted
        // (converted to double first, as OpenCV does), so the count must not require continuity.
        const int n = p1.checkVector(2, -1, /*requireContinuous*/ false);
        if (api == 7) {
            inFront = ess::recoverPoseIter(E, p1, p2, camera(in), R, t, mask);
        } else if (api == 8) {
            const double focal = in.pick(2) ? in.anyDouble() : 50.0 + in.pick(1000);
            inFront = ess::recoverPoseIter(E, p1, p2, R, t, focal,
                                           cv::Point2d(in.anyDouble(), in.anyDouble()), mask);
        } else {
            cv::Mat X;
            const double d = in.pick(2) ? in.anyDouble() : 50.0;
            inFront = ess::recoverPoseIter(E, p1, p2, camera(in), R, t, d, mask, X);
            checkTriangulated(X, n, inFront, t);
        }
        checkPose(inFront, R, t, n);
        break;
    }
    case 10: {
        // The two-camera recoverPose estimates E with the default cap: at most 5 points then.
        const cv::Mat q1 = points(in, 5, 5), q2 = points(in, 5, 5);
        const cv::Mat K1 = camera(in), d1 = distortion(in), K2 = camera(in), d2 = distortion(in);
        cv::Mat E, R, t;
        const int method = makeMethod(in);
        const double prob = makeProb(in), thr = makeThreshold(in);
        const int inFront =
            ess::recoverPoseIter(q1, q2, K1, d1, K2, d2, E, R, t, method, prob, thr, mask);
        if (!E.empty() && (E.rows != 3 || E.cols != 3 || E.type() != CV_64F || !cv::checkRange(E)))
            broken("E of the two-camera recoverPose");
        checkPose(inFront, R, t, static_cast<int>(q1.total()) * q1.channels());
        break;
    }
    default: {
        // A batch of up to three pairs with tiny settings: bad pairs are reported per pair.
        std::vector<ess::EssentialPair> pairs(static_cast<size_t>(in.pick(4)));
        for (ess::EssentialPair& pair : pairs) {
            pair.points1 = points(in, n, maxSide);
            pair.points2 = points(in, n, maxSide);
            pair.cameraMatrix = camera(in);
        }
        const auto results = ess::findEssentialMatBatch(pairs, tinyParams(in), 1 + in.pick(2));
        if (results.size() != pairs.size()) broken("batch result count");
        for (size_t i = 0; i < results.size(); ++i) {
            if (!results[i].error.empty()) continue;
            checkEssential(results[i].E, results[i].mask,
                           countOf(pairs[i].points1, results[i].mask), true);
        }
        break;
    }
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    FuzzInput in(data, size);
    return runGuarded([&] { runOne(in); });
}

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The engine-layer fuzz target: small whole estimates. Arbitrary bytes become up to 64
// correspondences (often with real geometry, so that refinement, pose recovery and the
// degeneracy measures run), a camera, and the settings of one estimate through the forms that
// cap the search: the EssentialParams form (every engine, sampler, solver, budget and option, time
// budgets near zero), the UsacParams form, the forms with maxIters, and recoverPose from E. The
// answer must keep the documented contract (fuzz_contract.hpp). The forms without an iteration cap
// are the input-layer target's (fuzz_input_layer.cpp), on samples too small to search.
//
// Built two ways (fuzz/CMakeLists.txt): with clang's -fsanitize=fuzzer as a libFuzzer binary, and
// with any compiler as a replay program (replay_main.cpp) that runs the kept inputs as a ctest
// entry.

#include "fuzz_builders.hpp"
#include "fuzz_contract.hpp"
#include <opencv2/essential.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <vector>

namespace {

using namespace essential_fuzz;

/** The usual iteration caps stay below 40 (the sample budget may still extend a search to 20 times
the cap): at caps up to 200 an execution averaged 4 ms in the fast tree (256 per second), which
made a million executions an hour's run; the longer loops add no code to cover. */
constexpr int kIterationCap = 40;

void runOne(FuzzInput& in)
{
    // The capped forms (the numbering of the switch below): maxIters form, focal form with
    // maxIters, UsacParams, EssentialParams (three times as often: every engine and option), and
    // recoverPose from E.
    static const int apis[] = {0, 2, 5, 6, 6, 6, 7, 8};
    const int api = apis[in.pick(8)];
    // Mostly the same count in both views; sometimes not. Mostly enough points to search.
    const int n = in.pick(8) == 0 ? in.pick(8) : 5 + in.pick(60);
    const int n2 = in.pick(16) == 0 ? in.pick(70) : n;
    cv::Mat p1, p2;
    if (in.pick(2) && n == n2 && n > 0) {
        std::vector<cv::Point2d> a, b;
        makeScenePoints(in, n, a, b);
        p1 = makePoints(in, n, a);
        p2 = makePoints(in, n, b);
    } else {
        p1 = makePoints(in, n);
        p2 = makePoints(in, n2);
    }
    const bool wantMask = in.pick(4) != 0;
    cv::Mat mask;
    namespace ess = cv::essential;
    switch (api) {
    case 0: {
        const cv::Mat K = makeCamera(in);
        const int method = makeMethod(in);
        const double prob = makeProb(in), thr = makeThreshold(in);
        const int iters = makeMaxIters(in, kIterationCap);
        const cv::Mat E = wantMask
                              ? ess::findEssentialMatIter(p1, p2, K, method, prob, thr, iters, mask)
                              : ess::findEssentialMatIter(p1, p2, K, method, prob, thr, iters);
        checkEssential(E, mask, n, wantMask);
        break;
    }
    case 2: {
        const double focal = in.pick(3) == 0 ? in.anyDouble() : 50.0 + in.pick(1000);
        const cv::Point2d pp(in.pick(4) == 0 ? in.anyDouble() : in.pick(640), in.pick(480));
        const int method = makeMethod(in);
        const double prob = makeProb(in), thr = makeThreshold(in);
        const cv::Mat E = ess::findEssentialMatIter(p1, p2, focal, pp, method, prob, thr,
                                                    makeMaxIters(in, kIterationCap), mask);
        checkEssential(E, mask, n, true);
        break;
    }
    case 5: {
        const cv::Mat K1 = makeCamera(in), K2 = makeCamera(in);
        const cv::Mat d1 = makeDistortion(in), d2 = makeDistortion(in);
        cv::UsacParams usac;
        usac.confidence = makeProb(in);
        usac.threshold = makeThreshold(in);
        usac.maxIterations = makeMaxIters(in, kIterationCap);
        usac.randomGeneratorState = static_cast<int>(in.pick(1 << 30));
        usac.score = static_cast<cv::ScoreMethod>(in.pick(8) == 0 ? in.pick(6) : in.pick(4));
        usac.sampler = static_cast<cv::SamplingMethod>(
            in.pick(8) == 0 ? in.pick(6)
                            : (in.pick(2) ? cv::SAMPLING_UNIFORM : cv::SAMPLING_PROSAC));
        usac.loMethod =
            static_cast<cv::LocalOptimMethod>(in.pick(8) == 0 ? in.pick(7) : in.pick(5));
        usac.loIterations = in.pick(8) == 0 ? in.pick(12) - 1 : in.pick(12);
        usac.loSampleSize = in.pick(8) == 0 ? in.pick(20) - 1 : (in.pick(2) ? 0 : 5 + in.pick(20));
        const cv::Mat E = ess::findEssentialMatIter(p1, p2, K1, K2, d1, d2, mask, usac);
        checkEssential(E, mask, n, true);
        break;
    }
    case 6: {
        const cv::Mat K = makeCamera(in);
        ess::EssentialParams params;
        static const char* solvers[] = {"gn",        "lm",      "nister", "robust", "gn+nister",
                                        "gn:3+lm:1", "no_such", "",       "gn+",    "gn:0"};
        params.solver = in.pick(4) == 0 ? solvers[in.pick(10)] : solvers[in.pick(6)];
        setScore(in, params, 6);
        setEnumBits(params.engine, in.pick(16) == 0 ? in.pick(5) - 1 : in.pick(3));
        params.timeBudgetMs = in.pick(5) == 0 ? in.anyDouble() : 0.0;
        // A budget is honoured to the end on data without geometry; keep each run short.
        if (params.timeBudgetMs > 2) params.timeBudgetMs = 2;
        params.preemptiveHypotheses = in.pick(16) == 0 ? in.pick(60) - 2 : in.pick(60);
        params.preemptiveBlockSize = in.pick(16) == 0 ? in.pick(120) - 2 : 1 + in.pick(120);
        params.confidence = makeProb(in);
        params.threshold = makeThreshold(in);
        params.maxIterations = makeMaxIters(in, kIterationCap);
        params.loIterations = in.pick(16) == 0 ? in.pick(8) - 1 : in.pick(8);
        params.loSampleSize =
            in.pick(8) == 0 ? in.pick(12) - 1 : (in.pick(2) ? 0 : 5 + in.pick(20));
        static const int samplers[] = {cv::SAMPLING_PROSAC, cv::SAMPLING_NAPSAC,
                                       cv::SAMPLING_PROGRESSIVE_NAPSAC};
        setEnumBits(params.sampler,
                    in.pick(16) == 0 ? in.pick(6) - 1 : (in.pick(4) ? 0 : samplers[in.pick(3)]));
        setEnumBits(params.sampleBudget, in.pick(16) == 0 ? in.pick(4) - 1 : in.pick(2));
        params.planeParallax = in.pick(2) != 0;
        params.budgetLocalSamples = in.pick(2) != 0;
        params.sprt = in.pick(2) != 0;
        params.seed = in.pick(1 << 30);
        params.refine = in.pick(4) != 0;
        params.recoverPose = in.pick(2) != 0;
        ess::EssentialReport report;
        const cv::Mat E = ess::findEssentialMatIter(p1, p2, K, params, mask, &report);
        checkEssential(E, mask, n, true);
        if (report.success == E.empty()) broken("report.success disagrees with E");
        if (report.inliers < 0 || report.inliers > n) broken("report.inliers out of range");
        break;
    }
    default: {
        cv::Mat E;
        switch (in.pick(4)) {
        case 0:
            E = cv::Mat(3, 3, CV_64F);
            for (int i = 0; i < 9; ++i)
                E.at<double>(i / 3, i % 3) = in.anyDouble();
            break;
        case 1:
            E = cv::Mat::eye(in.pick(5), 3, CV_32F);
            break;
        default: {
            // A valid essential matrix [t]x R with fuzzed motion.
            const cv::Vec3d rvec(in.unit() - 0.5, in.unit() - 0.5, in.unit() - 0.5);
            cv::Matx33d R;
            cv::Rodrigues(rvec, R);
            const cv::Vec3d t(in.unit() - 0.5, in.unit() - 0.5, in.unit() - 0.5);
            const cv::Matx33d tx(0, -t[2], t[1], t[2], 0, -t[0], -t[1], t[0], 0);
            E = cv::Mat(tx * R);
        }
        }
        cv::Mat R, t;
        cv::Mat poseMask;
        if (in.pick(2)) poseMask = cv::Mat(std::max(n, 0), 1, CV_8U, cv::Scalar(in.pick(3)));
        int inFront;
        if (api == 7) {
            const cv::Mat K = makeCamera(in);
            if (in.pick(2) == 0) {
                inFront = ess::recoverPoseIter(E, p1, p2, K, R, t, poseMask);
            } else {
                static const double thresholds[] = {50.0, 1.0, 1e300,
                                                    std::numeric_limits<double>::infinity()};
                const double d = in.pick(4) == 0 ? in.anyDouble() : thresholds[in.pick(4)];
                cv::Mat X;
                inFront = ess::recoverPoseIter(E, p1, p2, K, R, t, d, poseMask, X);
                checkTriangulated(X, std::max(n, 0), inFront, t);
            }
        } else {
            const double focal = in.pick(3) == 0 ? in.anyDouble() : 50.0 + in.pick(1000);
            inFront = ess::recoverPoseIter(E, p1, p2, R, t, focal, cv::Point2d(in.pick(640), 240),
                                           poseMask);
        }
        checkPose(inFront, R, t, n);
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

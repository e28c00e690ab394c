// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The fuzz target: arbitrary bytes become points, cameras, distortion and parameters of one call of
// findEssentialMatIter (any of its seven overloads) or recoverPose (any of its four). The public
// API may answer only in the documented ways: a cv::Exception, or a result that keeps the
// documented shape (E empty or 3n x 3 CV_64F and finite, mask N x 1 CV_8U of 0/1 that is all zero
// when E is empty, R a rotation, t a unit or zero vector, triangulated points 4 x N finite).
// Anything else aborts, so that libFuzzer (with AddressSanitizer and UndefinedBehaviorSanitizer)
// records the input.
//
// Built two ways (fuzz/CMakeLists.txt): with clang's -fsanitize=fuzzer as the libFuzzer binary,
// and with any compiler as a replay program (replay_main.cpp) that runs the kept inputs in
// fuzz/regression/ as an ordinary ctest entry.

#include "fuzz_input.hpp"

#include <opencv2/essential.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <vector>

namespace {

using essential_fuzz::FuzzInput;

[[noreturn]] void broken(const char* what)
{
    std::fprintf(stderr, "fuzz_essential: contract broken: %s\n", what);
    std::abort();
}

/** Correspondences with geometry, so that the fuzzer reaches the paths after a successful search
(refinement, pose, the degeneracy measures): points in front of camera 1 (camera 500, 320, 240)
moved by a fuzzed rotation and translation (zero allowed), projected, then a few coordinates
overwritten by fuzzed values. */
void makeScenePoints(FuzzInput& in, int n, std::vector<cv::Point2d>& a, std::vector<cv::Point2d>& b)
{
    const cv::Vec3d rvec(in.unit() - 0.5, in.unit() - 0.5, in.unit() - 0.5);
    cv::Matx33d R;
    cv::Rodrigues(rvec, R);
    const double scale = in.pick(4) == 0 ? 0.0 : in.unit();
    const cv::Vec3d t = scale * cv::Vec3d(in.unit() - 0.5, in.unit() - 0.5, in.unit() - 0.5);
    const bool planar = in.pick(4) == 0;
    a.resize(static_cast<size_t>(n));
    b.resize(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        const double u = 2.0 * in.unit() - 1.0, v = 2.0 * in.unit() - 1.0;
        const double depth = planar ? 4.0 : 1.0 + 20.0 * in.unit();
        const cv::Vec3d X(u * depth, v * depth, depth);
        const cv::Vec3d Y = R * X + t;
        a[static_cast<size_t>(i)] = cv::Point2d(500 * u + 320, 500 * v + 240);
        const double z = std::abs(Y[2]) > 1e-6 ? Y[2] : 1e-6;
        b[static_cast<size_t>(i)] = cv::Point2d(500 * Y[0] / z + 320, 500 * Y[1] / z + 240);
    }
    for (int k = in.pick(4); k > 0 && n > 0; --k) {
        std::vector<cv::Point2d>& side = in.pick(2) ? a : b;
        cv::Point2d& p = side[static_cast<size_t>(in.pick(n))];
        (in.pick(2) ? p.x : p.y) = in.anyDouble();
    }
}

/** Points in one of the layouts the API accepts (or a wrong one): vector<Point2d>, vector<Point2f>,
N x 2 one-channel, N x 1 two-channel, 1 x N two-channel, or another depth. `given` holds the
coordinates, or is empty for coordinates read from the input. */
cv::Mat makePoints(FuzzInput& in, int n, std::vector<cv::Point2d> given = {})
{
    // Mostly valid layouts, so that most inputs get past the input checks.
    static const int layouts[] = {0, 1, 2, 3, 7, 0, 1, 2, 3, 7, 0, 2, 4, 5, 6, 7};
    const int layout = layouts[in.pick(16)];
    std::vector<cv::Point2d> pts = std::move(given);
    if (pts.empty()) {
        pts.resize(static_cast<size_t>(n));
        for (cv::Point2d& p : pts) {
            p.x = in.coordinate();
            p.y = in.coordinate();
        }
    }
    n = static_cast<int>(pts.size());
    cv::Mat m(pts, true); // N x 1 CV_64FC2
    switch (layout) {
    case 0:
        return m;
    case 1: {
        cv::Mat f;
        m.convertTo(f, CV_32FC2);
        return f;
    }
    case 2:
        return m.reshape(1, n); // N x 2 one-channel
    case 3:
        return m.reshape(2, 1); // 1 x N two-channel
    case 4: {
        cv::Mat i;
        m.convertTo(i, CV_32SC2); // wrong depth
        return i;
    }
    case 5:
        return cv::Mat(n, 3, CV_64F, cv::Scalar(in.coordinate())); // wrong shape
    case 6:
        return cv::Mat(); // empty
    default: {
        cv::Mat f;
        m.reshape(1, n).convertTo(f, CV_32F);
        return f;
    }
    }
}

/** A camera matrix: mostly a plausible one with fuzzed entries, sometimes any 3 x 3 or a wrong
shape. */
cv::Mat makeCamera(FuzzInput& in)
{
    switch (in.pick(12)) {
    case 0: {
        cv::Mat k(3, 3, CV_64F);
        for (int i = 0; i < 9; ++i)
            k.at<double>(i / 3, i % 3) = in.anyDouble();
        return k;
    }
    case 1:
        return cv::Mat::eye(in.pick(5), in.pick(5), CV_64F);
    case 2: {
        cv::Mat k = (cv::Mat_<float>(3, 3) << 500, 0, 320, 0, 500, 240, 0, 0, 1);
        k.at<float>(in.pick(3), in.pick(3)) = static_cast<float>(in.anyDouble());
        return k;
    }
    default: {
        const double f = in.pick(8) == 0 ? in.anyDouble() : 100.0 + in.pick(1000);
        const double fy = in.pick(8) == 0 ? -f : f;
        const double skew = in.pick(8) == 0 ? in.anyDouble() : 0.0;
        return (cv::Mat_<double>(3, 3) << f, skew, in.pick(640), 0, fy, in.pick(480), 0, 0, 1);
    }
    }
}

cv::Mat makeDistortion(FuzzInput& in)
{
    static const int lengths[] = {0, 0, 0, 4, 5, 8, 12, 14, 3, 6};
    const int len = lengths[in.pick(10)];
    if (len == 0) return cv::Mat();
    cv::Mat d(1, len, CV_64F);
    for (int i = 0; i < len; ++i)
        d.at<double>(i) = in.pick(3) == 0 ? in.anyDouble() : 0.01 * (in.pick(21) - 10.0);
    return d;
}

int makeMethod(FuzzInput& in)
{
    static const int methods[] = {cv::RANSAC,
                                  cv::LMEDS,
                                  cv::USAC_DEFAULT,
                                  cv::USAC_PARALLEL,
                                  cv::USAC_FM_8PTS,
                                  cv::USAC_FAST,
                                  cv::USAC_ACCURATE,
                                  cv::USAC_PROSAC,
                                  cv::USAC_MAGSAC,
                                  -1,
                                  12345,
                                  1};
    return in.pick(8) == 0 ? methods[in.pick(12)] : methods[in.pick(9)];
}

double makeProb(FuzzInput& in)
{
    return in.pick(8) == 0 ? in.anyDouble() : 0.5 + 0.499 * in.unit();
}

double makeThreshold(FuzzInput& in)
{
    return in.pick(8) == 0 ? in.anyDouble() : 0.1 + 5.0 * in.unit();
}

/** Iteration caps stay small: a cap of 1e9 on data without geometry is a legitimate long run (the
bad-input tests check large caps), not something a fuzzer should wait for. */
int makeMaxIters(FuzzInput& in)
{
    return in.pick(8) - 2 + (in.pick(2) ? 0 : in.pick(200));
}

void checkMask(const cv::Mat& mask, int n, bool allZero)
{
    if (mask.empty() && n == 0) return;
    if (mask.rows != n || mask.cols != 1 || mask.type() != CV_8U) broken("mask shape");
    for (int i = 0; i < n; ++i) {
        const uchar v = mask.at<uchar>(i);
        if (v > 1) broken("mask value other than 0 or 1");
        if (allZero && v) broken("non-zero mask with an empty E");
    }
}

void checkEssential(const cv::Mat& E, const cv::Mat& mask, int n, bool maskRequested)
{
    if (!E.empty()) {
        if (E.cols != 3 || E.rows % 3 != 0 || E.rows == 0 || E.type() != CV_64F)
            broken("E shape or type");
        if (!cv::checkRange(E)) broken("non-finite E");
    }
    if (maskRequested) checkMask(mask, n, E.empty());
}

void checkPose(int inFront, const cv::Mat& R, const cv::Mat& t, int n)
{
    if (inFront < 0 || inFront > n) broken("recoverPose count out of range");
    if (R.rows != 3 || R.cols != 3 || R.type() != CV_64F || !cv::checkRange(R)) broken("R shape");
    if (t.rows != 3 || t.cols != 1 || t.type() != CV_64F || !cv::checkRange(t)) broken("t shape");
    const cv::Matx33d Rm = R;
    if (cv::norm(Rm.t() * Rm - cv::Matx33d::eye()) > 1e-6) broken("R not orthonormal");
    const double tn = cv::norm(t);
    if (!(std::abs(tn - 1.0) < 1e-6 || tn == 0.0)) broken("t neither unit nor zero");
}

void runOne(FuzzInput& in)
{
    const int api = in.pick(9);
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
        const int iters = makeMaxIters(in);
        const cv::Mat E = wantMask
                              ? ess::findEssentialMatIter(p1, p2, K, method, prob, thr, iters, mask)
                              : ess::findEssentialMatIter(p1, p2, K, method, prob, thr, iters);
        checkEssential(E, mask, n, wantMask);
        break;
    }
    case 1: {
        const cv::Mat K = makeCamera(in);
        const int method = makeMethod(in);
        const double prob = makeProb(in), thr = makeThreshold(in);
        const cv::Mat E = ess::findEssentialMatIter(p1, p2, K, method, prob, thr, mask);
        checkEssential(E, mask, n, true);
        break;
    }
    case 2:
    case 3: {
        const double focal = in.pick(3) == 0 ? in.anyDouble() : 50.0 + in.pick(1000);
        const cv::Point2d pp(in.pick(4) == 0 ? in.anyDouble() : in.pick(640), in.pick(480));
        const int method = makeMethod(in);
        const double prob = makeProb(in), thr = makeThreshold(in);
        const cv::Mat E =
            api == 2 ? ess::findEssentialMatIter(p1, p2, focal, pp, method, prob, thr,
                                                 makeMaxIters(in), mask)
                     : ess::findEssentialMatIter(p1, p2, focal, pp, method, prob, thr, mask);
        checkEssential(E, mask, n, true);
        break;
    }
    case 4: {
        const cv::Mat K1 = makeCamera(in), K2 = makeCamera(in);
        const cv::Mat d1 = makeDistortion(in), d2 = makeDistortion(in);
        const int method = makeMethod(in);
        const double prob = makeProb(in), thr = makeThreshold(in);
        const cv::Mat E =
            ess::findEssentialMatIter(p1, p2, K1, d1, K2, d2, method, prob, thr, mask);
        checkEssential(E, mask, n, true);
        break;
    }
    case 5: {
        const cv::Mat K1 = makeCamera(in), K2 = makeCamera(in);
        const cv::Mat d1 = makeDistortion(in), d2 = makeDistortion(in);
        cv::UsacParams usac;
        usac.confidence = makeProb(in);
        usac.threshold = makeThreshold(in);
        usac.maxIterations = makeMaxIters(in);
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
        params.method = in.pick(6) == 0 ? makeMethod(in) : (in.pick(2) ? cv::RANSAC : cv::LMEDS);
        params.engine = in.pick(16) == 0 ? in.pick(5) - 1 : in.pick(3);
        params.timeBudgetMs = in.pick(5) == 0 ? in.anyDouble() : 0.0;
        // A budget is honoured to the end on data without geometry; keep each run short.
        if (params.timeBudgetMs > 2) params.timeBudgetMs = 2;
        params.preemptiveHypotheses = in.pick(16) == 0 ? in.pick(60) - 2 : in.pick(60);
        params.preemptiveBlockSize = in.pick(16) == 0 ? in.pick(120) - 2 : 1 + in.pick(120);
        params.confidence = makeProb(in);
        params.threshold = makeThreshold(in);
        params.maxIters = makeMaxIters(in);
        params.loIterations = in.pick(16) == 0 ? in.pick(8) - 1 : in.pick(8);
        params.loSampleSize =
            in.pick(8) == 0 ? in.pick(12) - 1 : (in.pick(2) ? 0 : 5 + in.pick(20));
        static const int samplers[] = {cv::SAMPLING_PROSAC, cv::SAMPLING_NAPSAC,
                                       cv::SAMPLING_PROGRESSIVE_NAPSAC};
        params.sampler =
            in.pick(16) == 0 ? in.pick(6) - 1 : (in.pick(4) ? 0 : samplers[in.pick(3)]);
        params.sampleBudget = in.pick(16) == 0 ? in.pick(4) - 1 : in.pick(2);
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
            // Read last, so that shorter inputs (zeros past the end) keep the first form.
            const int form = in.pick(3);
            if (form == 0) {
                inFront = ess::recoverPose(E, p1, p2, K, R, t, poseMask);
            } else if (form == 1) {
                static const double thresholds[] = {50.0, 1.0, 1e300,
                                                    std::numeric_limits<double>::infinity()};
                const double d = in.pick(4) == 0 ? in.anyDouble() : thresholds[in.pick(4)];
                cv::Mat X;
                inFront = ess::recoverPose(E, p1, p2, K, R, t, d, poseMask, X);
                if (X.rows != 4 || X.cols != std::max(n, 0) || X.type() != CV_64F ||
                    !cv::checkRange(X))
                    broken("triangulated points shape");
            } else {
                cv::Mat Eout;
                const cv::Mat d1 = makeDistortion(in), d2 = makeDistortion(in);
                const int method = makeMethod(in);
                const double prob = makeProb(in), thr = makeThreshold(in);
                inFront = ess::recoverPose(p1, p2, K, d1, makeCamera(in), d2, Eout, R, t, method,
                                           prob, thr, poseMask);
                if (!Eout.empty() && (Eout.rows != 3 || Eout.cols != 3 || Eout.type() != CV_64F ||
                                      !cv::checkRange(Eout)))
                    broken("E of the two-camera recoverPose");
                if (!poseMask.empty()) checkMask(poseMask, n, Eout.empty());
            }
        } else {
            const double focal = in.pick(3) == 0 ? in.anyDouble() : 50.0 + in.pick(1000);
            inFront =
                ess::recoverPose(E, p1, p2, R, t, focal, cv::Point2d(in.pick(640), 240), poseMask);
        }
        checkPose(inFront, R, t, n);
        break;
    }
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    // OpenCV prints every CV_Error to stderr by default; the fuzzer expects exceptions.
    static const bool quiet = [] {
        cv::redirectError([](int, const char*, const char*, const char*, int, void*) { return 0; });
        return true;
    }();
    (void)quiet;
    FuzzInput in(data, size);
    try {
        runOne(in);
    } catch (const cv::Exception&) {
        // The documented answer to bad input.
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz_essential: not a cv::Exception: %s\n", e.what());
        std::abort();
    }
    return 0;
}

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The estimators the pair benchmarks compare (bench/hard_pairs.cpp, bench/real_pairs.cpp), named on
// the command line, each run on the same pixel correspondences and camera and timed by the
// thread's CPU clock:
//  - cv_ransac, usac_magsac, usac_accurate, usac_prosac: cv::findEssentialMat with that method
//    flag, prob 0.999 and the method's threshold and iteration cap (1 px, 1000: OpenCV's defaults);
//  - dropin: cv::essential::findEssentialMatIter with cv_ransac's arguments;
//  - ours[:k=v;k=v...]: the module's own overload with EssentialParams set by the keys;
//  - poselib[:maxIters=N]: poselib::estimate_relative_pose (bench/poselib_runner.hpp), when the
//    bench was built with PoseLib; min_iterations 0, max_iterations N (default 10 000);
//  - superansac: SupeRANSAC's essential-matrix estimator (bench/superansac_runner.hpp), when built
//    with it.
// The essential-matrix methods get their pose from cv::essential::recoverPoseIter on their own
// mask (no 50-baseline far-point cut, so the sign of t is decided by every point in front);
// RunOptions::timePose says whether that call is inside the timed span.

#ifndef OPENCV_ESSENTIAL_BENCH_METHODS_HPP
#define OPENCV_ESSENTIAL_BENCH_METHODS_HPP

#include "bench_common.hpp"
#include "cli_common.hpp"
#include "pose_accuracy.hpp"

#ifdef ESSENTIAL_BENCH_HAVE_POSELIB
#include "poselib_runner.hpp"
#endif
#ifdef ESSENTIAL_BENCH_HAVE_SUPERANSAC
#include "superansac_runner.hpp"
#endif

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/essential.hpp>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace essential_bench {

enum class MethodKind {
    CvRansac,
    UsacMagsac,
    UsacAccurate,
    UsacProsac,
    Dropin,
    Ours,
    PoseLib,
    SupeRansac
};

struct Method
{
    std::string label;
    MethodKind kind = MethodKind::Ours;
    cv::essential::EssentialParams params; //!< MethodKind::Ours only
    bool sortedByDistance = false;         //!< PROSAC: matches sorted best first
    double threshold = 1.0;                //!< px: OpenCV's default, for every kind but Ours
    int maxIters = 1000;                   //!< OpenCV's default; PoseLib's max_iterations
};

inline bool parseBool(const std::string& value, bool& out)
{
    if (value == "1" || value == "true" || value == "on") return out = true, true;
    if (value == "0" || value == "false" || value == "off") return out = false, true;
    return false;
}

/** Sets one `key=value` of an `ours:` method in params; fails with a message naming the key. */
inline void applyOursOption(const std::string& key, const std::string& value,
                            cv::essential::EssentialParams& params)
{
    using essential_samples::fail;
    const std::string where = "ours option '" + key + "=" + value + "': ";
    long long integer = 0;
    double number = 0;
    if (key == "solver") {
        try {
            cv::essential::createSolver(value);
        } catch (const cv::Exception& e) {
            fail(where + e.err, 2);
        }
        params.solver = value;
    } else if (key == "sampler") {
        static const std::map<std::string, cv::SamplingMethod> samplers = {
            {"uniform", cv::SAMPLING_UNIFORM},
            {"prosac", cv::SAMPLING_PROSAC},
            {"napsac", cv::SAMPLING_NAPSAC},
            {"pnapsac", cv::SAMPLING_PROGRESSIVE_NAPSAC}};
        const auto it = samplers.find(value);
        if (it == samplers.end()) fail(where + "sampler is uniform, prosac, napsac or pnapsac", 2);
        params.sampler = it->second;
    } else if (key == "maxIters") {
        if (!essential_samples::parseInt(value, integer) || integer < 1 || integer > 100000000)
            fail(where + "maxIters is a positive integer", 2);
        params.maxIterations = static_cast<int>(integer);
    } else if (key == "lo") {
        if (!essential_samples::parseInt(value, integer) || integer < 0 || integer > 1000)
            fail(where + "lo (IRLS iterations of local optimisation) is an integer >= 0", 2);
        params.loIterations = static_cast<int>(integer);
    } else if (key == "loSample") {
        if (!essential_samples::parseInt(value, integer) || integer < 0 ||
            (integer > 0 && integer < 5) || integer > 100000000)
            fail(where + "loSample (points a polish fits; 0: all) is 0 or an integer >= 5", 2);
        params.loSampleSize = static_cast<int>(integer);
    } else if (key == "sprt") {
        if (!parseBool(value, params.sprt)) fail(where + "sprt is 0 or 1", 2);
    } else if (key == "threshold") {
        if (!essential_samples::parseDouble(value, number) || !(number > 0))
            fail(where + "threshold is a positive number of pixels", 2);
        params.threshold = number;
    } else if (key == "budgetMs") {
        if (!essential_samples::parseDouble(value, number) || !(number >= 0))
            fail(where + "budgetMs (time budget) is a number of ms >= 0", 2);
        params.timeBudgetMs = number;
    } else if (key == "budget") {
        if (value == "opencv")
            params.sampleBudget = cv::essential::BUDGET_OPENCV_TIME;
        else if (value == "confidence")
            params.sampleBudget = cv::essential::BUDGET_CONFIDENCE;
        else
            fail(where + "budget is opencv or confidence", 2);
    } else if (key == "plane") {
        if (!parseBool(value, params.planeParallax)) fail(where + "plane is 0 or 1", 2);
    } else if (key == "front") {
        if (!parseBool(value, params.inFrontCheck)) fail(where + "front is 0 or 1", 2);
    } else if (key == "local") {
        if (!parseBool(value, params.budgetLocalSamples)) fail(where + "local is 0 or 1", 2);
    } else if (key == "refine") {
        if (!parseBool(value, params.refine)) fail(where + "refine is 0 or 1", 2);
    } else {
        fail("unknown ours option '" + key +
                 "' (known: solver, sampler, maxIters, lo, loSample, sprt, threshold, budgetMs, "
                 "budget, plane, front, local, refine)",
             2);
    }
}

/** "cv_ransac", "ours:k=v;k=v", "poselib:maxIters=N", "label=ours:..." or "label=cv_ransac". */
inline Method parseMethod(const std::string& text)
{
    using essential_samples::fail;
    Method m;
    std::string spec = text;
    const size_t equals = text.find('='), colon = text.find(':');
    if (equals != std::string::npos && (colon == std::string::npos || equals < colon)) {
        m.label = text.substr(0, equals);
        spec = text.substr(equals + 1);
        if (m.label.empty()) fail("--methods: empty label in '" + text + "'", 2);
    } else {
        m.label = text;
    }
    static const std::map<std::string, MethodKind> fixed = {
        {"cv_ransac", MethodKind::CvRansac},
        {"usac_magsac", MethodKind::UsacMagsac},
        {"usac_accurate", MethodKind::UsacAccurate},
        {"usac_prosac", MethodKind::UsacProsac},
        {"dropin", MethodKind::Dropin},
        {"superansac", MethodKind::SupeRansac}};
    const auto it = fixed.find(spec);
    if (it != fixed.end()) {
        m.kind = it->second;
        m.sortedByDistance = m.kind == MethodKind::UsacProsac;
#ifndef ESSENTIAL_BENCH_HAVE_SUPERANSAC
        if (m.kind == MethodKind::SupeRansac)
            fail("--methods: superansac needs a bench built with SupeRANSAC "
                 "(scripts/build_superansac.sh)",
                 2);
#endif
        return m;
    }
    if (spec == "poselib" || spec.rfind("poselib:", 0) == 0) {
#ifndef ESSENTIAL_BENCH_HAVE_POSELIB
        fail("--methods: poselib needs a bench built with PoseLib (scripts/build_poselib.sh, "
             "-DPoseLib_DIR)",
             2);
#endif
        m.kind = MethodKind::PoseLib;
        m.maxIters = 10000;
        if (spec.size() > 8) {
            long long integer = 0;
            const std::string kv = spec.substr(8);
            if (kv.rfind("maxIters=", 0) != 0 ||
                !essential_samples::parseInt(kv.substr(9), integer) || integer < 1 ||
                integer > 100000000)
                fail("--methods: poselib takes maxIters=N only, got '" + kv + "'", 2);
            m.maxIters = static_cast<int>(integer);
        }
        return m;
    }
    if (spec != "ours" && spec.rfind("ours:", 0) != 0)
        fail("--methods: unknown method '" + spec +
                 "' (cv_ransac, usac_magsac, usac_accurate, usac_prosac, dropin, "
                 "ours[:k=v;...], poselib[:maxIters=N], superansac)",
             2);
    m.kind = MethodKind::Ours;
    if (spec.size() > 5) {
        for (const std::string& kv : essential_samples::split(spec.substr(5), ';')) {
            if (kv.empty()) continue;
            const size_t eq = kv.find('=');
            if (eq == std::string::npos) fail("--methods: '" + kv + "' is not key=value", 2);
            applyOursOption(kv.substr(0, eq), kv.substr(eq + 1), m.params);
        }
    }
    m.sortedByDistance = m.params.sampler == cv::SAMPLING_PROSAC;
    return m;
}

/** What one run of a method gave. */
struct MethodOutcome
{
    double cpuMs = 0, wallMs = 0;
    int inliers = 0;    //!< non-zero mask entries (0 where the method reports none)
    bool posed = false; //!< a pose came out
    cv::Matx33d R = cv::Matx33d::eye();
    cv::Vec3d t = cv::Vec3d(0, 0, 0); //!< unit; X2 = R X1 + s t
};

struct RunOptions
{
    /** Whether the pose recovery of the essential-matrix methods is timed (PoseLib's and
    SupeRANSAC's time always includes their pose). */
    bool timePose = false;
};

/** Runs m on the correspondences (pixels) with camera K; `what` names the problem in messages. A
cv::Exception counts as a failure (no pose). */
inline MethodOutcome runMethod(const Method& m, const cv::Matx33d& Kx,
                               const std::vector<cv::Point2f>& p1,
                               const std::vector<cv::Point2f>& p2, std::uint64_t seed,
                               const std::string& what, const RunOptions& options = RunOptions())
{
    MethodOutcome out;
    const cv::Mat K(Kx);
    cv::Mat E, mask;
    cv::essential::EssentialReport report;
    const double cpu0 = threadCpuMs();
    const auto wall0 = std::chrono::steady_clock::now();
    auto stop = [&]() {
        out.cpuMs = threadCpuMs() - cpu0;
        out.wallMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall0)
                .count();
    };
    if (m.kind == MethodKind::PoseLib || m.kind == MethodKind::SupeRansac) {
        PoseEstimate e;
#ifdef ESSENTIAL_BENCH_HAVE_POSELIB
        if (m.kind == MethodKind::PoseLib)
            e = runPoseLib(p1, p2, Kx, m.threshold, m.maxIters, seed);
#endif
#ifdef ESSENTIAL_BENCH_HAVE_SUPERANSAC
        if (m.kind == MethodKind::SupeRansac)
            e = runSupeRansac(p1, p2, Kx, m.threshold, m.maxIters);
#endif
        stop();
        out.cpuMs = e.ms; // the runner's own span (its input conversion included)
        out.posed = e.ok;
        out.R = e.R;
        out.t = e.t;
        return out;
    }
    const double thr = m.threshold;
    const int iters = m.maxIters;
    try {
        switch (m.kind) {
        case MethodKind::CvRansac:
            E = cv::findEssentialMat(p1, p2, K, cv::RANSAC, 0.999, thr, iters, mask);
            break;
        case MethodKind::UsacMagsac:
            E = cv::findEssentialMat(p1, p2, K, cv::USAC_MAGSAC, 0.999, thr, iters, mask);
            break;
        case MethodKind::UsacAccurate:
            E = cv::findEssentialMat(p1, p2, K, cv::USAC_ACCURATE, 0.999, thr, iters, mask);
            break;
        case MethodKind::UsacProsac:
            E = cv::findEssentialMat(p1, p2, K, cv::USAC_PROSAC, 0.999, thr, iters, mask);
            break;
        case MethodKind::Dropin:
            E = cv::essential::findEssentialMatIter(p1, p2, K, cv::RANSAC, 0.999, thr, iters, mask);
            break;
        default: {
            cv::essential::EssentialParams params = m.params;
            params.seed = seed;
            params.recoverPose = true;
            E = cv::essential::findEssentialMatIter(p1, p2, K, params, mask, &report);
            break;
        }
        }
    } catch (const cv::Exception& e) {
        std::fprintf(stderr, "bench: %s on %s threw: %s\n", m.label.c_str(), what.c_str(),
                     e.err.c_str());
        E.release();
    }
    if (!options.timePose) stop();
    out.inliers = mask.empty() ? 0 : cv::countNonZero(mask);
    if (E.rows == 3 && E.cols == 3) {
        if (m.kind == MethodKind::Ours) {
            out.posed = report.success && report.poseRecovered;
            out.R = report.R;
            out.t = report.t;
        } else {
            cv::Mat Rm, tm, poseMask = mask.clone();
            try {
                cv::essential::recoverPoseIter(E, p1, p2, K, Rm, tm, poseMask);
                out.R = cv::Matx33d(Rm);
                out.t = cv::Vec3d(tm);
                out.posed = true;
            } catch (const cv::Exception&) {
                out.posed = false;
            }
        }
    }
    if (options.timePose) stop();
    return out;
}

} // namespace essential_bench

#endif

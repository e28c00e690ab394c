// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Whole estimates, pose recovery included, of cv::essential::findEssentialMatIter against the
// cv::findEssentialMat variants (RANSAC, USAC_MAGSAC, USAC_ACCURATE) registered in the same binary,
// on the paper's synthetic protocol (test/synthetic_scene.hpp). Timings only, never pass/fail.
//
//   essential_perf --benchmark_filter=Estimate --benchmark_repetitions=3
//                  --benchmark_enable_random_interleaving=true [--problems=100]
//
// Each benchmark is Estimate/<method>/N:<points>/inliers:<percent>; one run of it estimates
// --problems different scenes (one per benchmark iteration), and each repetition takes new scenes.
// Counters, per run: median_ms (median of the per-call wall times: estimate + recoverPose), p90_ms,
// median_cpu_ms (median of the per-call CPU times of the thread), and
// reliable (fraction with rotation error < 2 deg and translation direction error < 5 deg, the
// project's definition, docs/EXPERIMENTS.md), auc1 and auc5 (the AUC up to 1 and 5 degrees of
// max(rotation, translation direction) error, test/pose_auc.hpp; docs/ACCURACY.md). Repetitions are
// interleaved at random with the other benchmarks so that whatever slows the machine during a run
// falls on every method alike; scripts/perf.sh takes the median of median_ms and the mean of
// reliable, auc1 and auc5 over the repetitions.
//
// Method names: essential (the drop-in overload with OpenCV's default arguments),
// essential:<solver>:<engine> (the EssentialParams overload with that solver and engine),
// cv_RANSAC, cv_USAC_MAGSAC, cv_USAC_ACCURATE (cv::findEssentialMat + cv::recoverPose).

#include "pose_auc.hpp"
#include "synthetic_scene.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/essential.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <time.h>

namespace {

int gProblems = 100;

/** The scenes of one run: `run` (the repetition) selects a disjoint set of seeds. `wide`: the
wide camera (1280 x 720, 60 degrees, 1.66 px noise), where OpenCV's default 1 px threshold lies
below the noise. */
std::vector<essential_test::SyntheticScene> makeScenes(int n, int ratioPercent, bool wide, int run)
{
    std::vector<essential_test::SyntheticScene> v;
    v.reserve(static_cast<size_t>(gProblems));
    for (int p = 0; p < gProblems; ++p) {
        essential_test::SceneConfig cfg =
            wide ? essential_test::wideCameraConfig() : essential_test::SceneConfig();
        cfg.numPoints = n;
        cfg.inlierRatio = ratioPercent / 100.0;
        const uint64_t seed = 1000003ULL * static_cast<uint64_t>(run + 1) +
                              1009ULL * static_cast<uint64_t>(ratioPercent) +
                              7ULL * static_cast<uint64_t>(n) +
                              static_cast<uint64_t>(p) * 65537ULL + (wide ? 0x9e3779b9ULL : 0ULL);
        v.push_back(essential_test::makeScene(cfg, seed));
    }
    return v;
}

/** One estimate + pose; returns false if it gave no pose. R, t out. */
using Estimator =
    std::function<bool(const essential_test::SyntheticScene&, cv::Matx33d&, cv::Vec3d&)>;

bool poseFromMats(const cv::Mat& R, const cv::Mat& t, cv::Matx33d& Ro, cv::Vec3d& to)
{
    if (R.rows != 3 || R.cols != 3 || t.total() != 3) return false;
    Ro = cv::Matx33d(R);
    to = cv::Vec3d(t.reshape(1, 3));
    return true;
}

Estimator openCv(int method)
{
    return [method](const essential_test::SyntheticScene& s, cv::Matx33d& R, cv::Vec3d& t) {
        cv::Mat mask, Rm, tm;
        const cv::Mat K(s.K);
        const cv::Mat E = cv::findEssentialMat(s.px1, s.px2, K, method, 0.999, 1.0, 1000, mask);
        if (E.rows != 3 || E.cols != 3) return false;
        cv::recoverPose(E, s.px1, s.px2, K, Rm, tm, mask);
        return poseFromMats(Rm, tm, R, t);
    };
}

/** The drop-in overload, OpenCV's default arguments, and the module's recoverPose. */
Estimator essentialDropIn()
{
    return [](const essential_test::SyntheticScene& s, cv::Matx33d& R, cv::Vec3d& t) {
        cv::Mat mask, Rm, tm;
        const cv::Mat K(s.K);
        const cv::Mat E = cv::essential::findEssentialMatIter(s.px1, s.px2, K, cv::RANSAC, 0.999,
                                                              1.0, 1000, mask);
        if (E.empty()) return false;
        cv::essential::recoverPoseIter(E, s.px1, s.px2, K, Rm, tm, mask);
        return poseFromMats(Rm, tm, R, t);
    };
}

/** The EssentialParams overload with a solver and an engine; pose from the same recoverPose. */
Estimator essentialWith(const std::string& solver, cv::essential::EssentialEngine engine)
{
    return [solver, engine](const essential_test::SyntheticScene& s, cv::Matx33d& R, cv::Vec3d& t) {
        cv::Mat mask, Rm, tm;
        const cv::Mat K(s.K);
        cv::essential::EssentialParams params;
        params.solver = solver;
        params.engine = engine;
        const cv::Mat E = cv::essential::findEssentialMatIter(s.px1, s.px2, K, params, mask);
        if (E.empty()) return false;
        cv::essential::recoverPoseIter(E, s.px1, s.px2, K, Rm, tm, mask);
        return poseFromMats(Rm, tm, R, t);
    };
}

/** CPU time of this thread in milliseconds: it leaves out the time the thread waited for a core,
which wall time charges to long calls more than to short ones. */
double threadCpuMs()
{
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}

double quantile(std::vector<double> v, double q)
{
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, static_cast<size_t>(q * double(v.size() - 1) + 0.5))];
}

void runEstimates(benchmark::State& state, const Estimator& estimate, int n, int ratioPercent,
                  bool wide, const std::shared_ptr<int>& runs)
{
    const auto scenes = makeScenes(n, ratioPercent, wide, (*runs)++);
    std::vector<double> ms, cpuMs;
    ms.reserve(scenes.size());
    cpuMs.reserve(scenes.size());
    int reliable = 0;
    std::vector<double> errors; // max(rotation, translation direction) error, degrees
    errors.reserve(scenes.size());
    size_t i = 0;
    for (auto _ : state) {
        const auto& s = scenes[i++ % scenes.size()];
        cv::Matx33d R;
        cv::Vec3d t;
        const double c0 = threadCpuMs();
        const auto t0 = std::chrono::steady_clock::now();
        const bool ok = estimate(s, R, t);
        cpuMs.push_back(threadCpuMs() - c0);
        ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count());
        const double rotErr = ok ? essential_test::rotationErrorDeg(R, s.R) : 180.0;
        const double transErr = ok ? essential_test::translationErrorDeg(t, s.t) : 180.0;
        reliable += rotErr < 2.0 && transErr < 5.0;
        errors.push_back(std::max(rotErr, transErr));
    }
    state.counters["median_ms"] = quantile(ms, 0.5);
    state.counters["p90_ms"] = quantile(ms, 0.9);
    state.counters["median_cpu_ms"] = quantile(cpuMs, 0.5);
    state.counters["reliable"] = double(reliable) / double(std::max<size_t>(1, ms.size()));
    state.counters["auc1"] = essential_test::poseAuc(errors, 1.0);
    state.counters["auc5"] = essential_test::poseAuc(errors, 5.0);
}

void registerEstimate(const std::string& method, const Estimator& estimate, int n, int ratio,
                      bool wide = false)
{
    const std::string name = "Estimate/" + method + "/N:" + std::to_string(n) +
                             "/inliers:" + std::to_string(ratio) + (wide ? "/camera:wide" : "");
    auto runs = std::make_shared<int>(0);
    benchmark::RegisterBenchmark(name.c_str(),
                                 [estimate, n, ratio, wide, runs](benchmark::State& state) {
                                     runEstimates(state, estimate, n, ratio, wide, runs);
                                 })
        ->Iterations(gProblems)
        ->Unit(benchmark::kMillisecond);
}

void registerAll()
{
    const std::vector<std::pair<std::string, Estimator>> methods = {
        {"essential", essentialDropIn()},
        {"cv_RANSAC", openCv(cv::RANSAC)},
        {"cv_USAC_MAGSAC", openCv(cv::USAC_MAGSAC)},
        {"cv_USAC_ACCURATE", openCv(cv::USAC_ACCURATE)}};
    const std::vector<std::pair<int, int>> configs = {{500, 90}, {500, 70},  {500, 50}, {500, 30},
                                                      {500, 25}, {1000, 30}, {1000, 25}};
    for (const auto& c : configs)
        for (const auto& m : methods)
            registerEstimate(m.first, m.second, c.first, c.second);
    // The wide camera at OpenCV's default threshold of 1 px, below its 1.66 px noise.
    for (int ratio : {90, 70, 50, 30})
        for (const auto& m : methods)
            registerEstimate(m.first, m.second, 500, ratio, /*wide=*/true);

    // Solver x engine, the module's own overload (not part of the targets table).
    // Every built-in minimal solver and the mix, at every inlier ratio of the targets: the table
    // the default solver is chosen from (docs/SOLVERS.md, "The default").
    const std::vector<std::string> solvers = {"gn", "lm", "nister", "gn+nister"};
    const std::vector<std::pair<std::string, cv::essential::EssentialEngine>> engines = {
        {"adaptive", cv::essential::ENGINE_ADAPTIVE},
        {"preemptive", cv::essential::ENGINE_PREEMPTIVE}};
    for (int ratio : {90, 70, 50, 30})
        for (const auto& solver : solvers)
            for (const auto& engine : engines)
                registerEstimate("essential:" + solver + ":" + engine.first,
                                 essentialWith(solver, engine.second), 500, ratio);
}

} // namespace

// The kernels (perf_essential.cpp, perf_nister.cpp) register themselves statically; the whole
// estimates are registered here, after --problems is known.
int main(int argc, char** argv)
{
    std::vector<char*> args;
    for (int i = 0; i < argc; ++i) {
        if (std::strncmp(argv[i], "--problems=", 11) == 0)
            gProblems = std::max(1, std::atoi(argv[i] + 11));
        else
            args.push_back(argv[i]);
    }
    int count = static_cast<int>(args.size());
    cv::setNumThreads(1);
    registerAll();
    benchmark::Initialize(&count, args.data());
    if (benchmark::ReportUnrecognizedArguments(count, args.data())) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}

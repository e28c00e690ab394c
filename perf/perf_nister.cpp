// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Timings (never pass/fail) of the five-point solver "nister" against OpenCV's five-point solver,
// per call, on the same 2000 noise-free minimal samples of the paper's protocol in the same run.
// OpenCV's solver is reached through cv::findEssentialMat with exactly five points (which runs its
// kernel once and returns every solution), so its time includes that call's Mat overhead: the
// conversion of the points and the camera matrix to CV_64F Mats, the normalisation by K and the
// copy of the 3n x 3 result. BM_FivePoint_CallNister makes the same whole call through the drop-in,
// so that call compares with call and solver with solver is not claimed for OpenCV.
//
//   essential_perf --benchmark_filter=FivePoint --benchmark_repetitions=5
//                  --benchmark_report_aggregates_only=true
//
// Counters: solutions_per_call, and found = fraction of calls whose solutions include the true E
// (within 1e-6 up to scale and sign).

#include "solvers/nister_five_point.hpp"
#include "synthetic_scene.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/essential.hpp>

#include <benchmark/benchmark.h>

namespace {

std::vector<essential_test::SyntheticScene> fivePointSamples()
{
    std::vector<essential_test::SyntheticScene> v;
    for (int i = 0; i < 2000; ++i) {
        essential_test::SceneConfig cfg;
        cfg.numPoints = 5;
        cfg.inlierRatio = 1.0;
        cfg.noiseSigma = 0.0;
        v.push_back(essential_test::makeScene(cfg, 4242 + i));
    }
    return v;
}

bool containsTrue(const cv::Matx33d* E, int n, const cv::Matx33d& truth)
{
    for (int i = 0; i < n; ++i)
        if (essential_test::essentialDistance(E[i], truth) < 1e-6) return true;
    return false;
}

/** The counters, from one untimed pass over the samples: `solve(sample, E)` returns the count. */
template <class Solve>
void countSolutions(benchmark::State& state, const std::vector<essential_test::SyntheticScene>& v,
                    Solve solve)
{
    int64_t solutions = 0, found = 0;
    cv::Matx33d E[10];
    for (const auto& s : v) {
        const int n = solve(s, E);
        solutions += n;
        found += containsTrue(E, n, s.E);
    }
    state.counters["solutions_per_call"] = double(solutions) / double(v.size());
    state.counters["found"] = double(found) / double(v.size());
}

void BM_FivePoint_nister(benchmark::State& state)
{
    const auto samples = fivePointSamples();
    auto solver = cv::essential::createSolver("nister");
    cv::RNG rng(1);
    cv::Matx33d E[10];
    size_t i = 0;
    for (auto _ : state) {
        const auto& s = samples[i++ % samples.size()];
        int solutions = solver->solve(s.x1.data(), s.x2.data(), rng, E);
        benchmark::DoNotOptimize(solutions);
        benchmark::DoNotOptimize(E);
    }
    countSolutions(state, samples, [&](const essential_test::SyntheticScene& s, cv::Matx33d* out) {
        return solver->solve(s.x1.data(), s.x2.data(), rng, out);
    });
}

/** OpenCV's solutions for one sample, at most 10, into `out`; returns the count. */
int openCvFivePoint(const essential_test::SyntheticScene& s, const cv::Mat& K, cv::Matx33d* out)
{
    const cv::Mat E = cv::findEssentialMat(s.x1, s.x2, K, cv::RANSAC, 0.999, 1e-3);
    const int n = std::min(E.rows / 3, 10);
    for (int k = 0; k < n; ++k)
        out[k] = cv::Matx33d(E.rowRange(3 * k, 3 * k + 3));
    return n;
}

void BM_FivePoint_OpenCV(benchmark::State& state)
{
    const auto samples = fivePointSamples();
    const cv::Mat K = cv::Mat::eye(3, 3, CV_64F);
    size_t i = 0;
    for (auto _ : state) {
        const auto& s = samples[i++ % samples.size()];
        cv::Mat E = cv::findEssentialMat(s.x1, s.x2, K, cv::RANSAC, 0.999, 1e-3);
        benchmark::DoNotOptimize(E.data);
    }
    countSolutions(state, samples, [&](const essential_test::SyntheticScene& s, cv::Matx33d* out) {
        return openCvFivePoint(s, K, out);
    });
}

/** The same whole call as BM_FivePoint_OpenCV through the drop-in with the nister solver: the
like-for-like comparison (both include their Mat handling), since OpenCV's five-point kernel is
not exported and cannot be timed alone. */
void BM_FivePoint_CallNister(benchmark::State& state)
{
    const auto samples = fivePointSamples();
    const cv::Mat K = cv::Mat::eye(3, 3, CV_64F);
    cv::essential::EssentialParams params;
    params.solver = "nister";
    params.threshold = 1e-3;
    size_t i = 0;
    for (auto _ : state) {
        const auto& s = samples[i++ % samples.size()];
        cv::Mat E = cv::essential::findEssentialMatIter(s.x1, s.x2, K, params);
        benchmark::DoNotOptimize(E.data);
    }
}

BENCHMARK(BM_FivePoint_nister)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FivePoint_OpenCV)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FivePoint_CallNister)->Unit(benchmark::kMicrosecond);

} // namespace

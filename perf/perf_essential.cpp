// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Timings (never pass/fail): per-call cost of the minimal solvers, per-point cost of MSAC scoring,
// and whole estimates against cv::findEssentialMat on the same problems in the same run.
// Names follow OpenCV's perf tests: what, then the parameters (N, inlier ratio in percent).
//
//   essential_perf --benchmark_filter=... --benchmark_repetitions=5
//                  --benchmark_report_aggregates_only=true      (medians are in the aggregates)

#include "problem.hpp"
#include "ransac/msac_score.hpp"
#include "synthetic_scene.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/essential.hpp>

#include <benchmark/benchmark.h>

namespace {

std::vector<essential_test::SyntheticScene> minimalProblems(int count)
{
    std::vector<essential_test::SyntheticScene> v;
    for (int i = 0; i < count; ++i) {
        essential_test::SceneConfig cfg;
        cfg.numPoints = 5;
        cfg.inlierRatio = 1.0;
        v.push_back(essential_test::makeScene(cfg, 4242 + i));
    }
    return v;
}

void solverPerCall(benchmark::State& state, const char* name)
{
    const auto problems = minimalProblems(256);
    auto solver = cv::essential::createSolver(name);
    cv::RNG rng(1);
    cv::Matx33d E[10];
    size_t i = 0;
    int64_t solved = 0;
    for (auto _ : state) {
        const auto& p = problems[i++ % problems.size()];
        solved += solver->solve(p.x1.data(), p.x2.data(), rng, E);
        benchmark::DoNotOptimize(E);
    }
    state.counters["solutions_per_call"] =
        benchmark::Counter(double(solved) / double(state.iterations()));
}

void BM_Solver_gn(benchmark::State& state)
{
    solverPerCall(state, "gn");
}
void BM_Solver_lm(benchmark::State& state)
{
    solverPerCall(state, "lm");
}
BENCHMARK(BM_Solver_gn);
BENCHMARK(BM_Solver_lm);

void BM_ScoreMsac(benchmark::State& state)
{
    essential_test::SceneConfig cfg;
    cfg.numPoints = static_cast<int>(state.range(0));
    const auto s = essential_test::makeScene(cfg, 7);
    const cv::essential::Problem problem = cv::essential::makeProblem(s.x1, s.x2, 0.002);
    for (auto _ : state) {
        benchmark::DoNotOptimize(cv::essential::ransac::scoreMsac(s.E, problem));
    }
    state.SetItemsProcessed(state.iterations() * state.range(0)); // items = points scored
}
BENCHMARK(BM_ScoreMsac)->Arg(500)->Arg(1000);

std::vector<essential_test::SyntheticScene> scenes(int n, double ratio)
{
    std::vector<essential_test::SyntheticScene> v;
    for (int i = 0; i < 16; ++i) {
        essential_test::SceneConfig cfg;
        cfg.numPoints = n;
        cfg.inlierRatio = ratio;
        v.push_back(essential_test::makeScene(cfg, 100 + i));
    }
    return v;
}

/** Runs `estimate(scene)` on 16 scenes in turn; args: N, inlier ratio in percent. */
template <class F> void estimateLoop(benchmark::State& state, F estimate)
{
    const auto problems = scenes(int(state.range(0)), state.range(1) / 100.0);
    size_t i = 0;
    for (auto _ : state)
        estimate(problems[i++ % problems.size()]);
}

/** findEssentialMatIter (drop-in defaults) + recoverPose. */
void BM_FindEssentialMatIter(benchmark::State& state)
{
    estimateLoop(state, [](const essential_test::SyntheticScene& s) {
        cv::Mat mask, R, t;
        cv::Mat E = cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), cv::RANSAC,
                                                        0.999, 1.0, 1000, mask);
        if (!E.empty()) cv::essential::recoverPose(E, s.px1, s.px2, cv::Mat(s.K), R, t, mask);
    });
}

/** The same with cv::findEssentialMat (RANSAC) + cv::recoverPose, for the ratio. */
void BM_OpenCV_FindEssentialMat(benchmark::State& state)
{
    estimateLoop(state, [](const essential_test::SyntheticScene& s) {
        cv::Mat mask, R, t;
        cv::Mat E =
            cv::findEssentialMat(s.px1, s.px2, cv::Mat(s.K), cv::RANSAC, 0.999, 1.0, 1000, mask);
        if (E.rows == 3) cv::recoverPose(E, s.px1, s.px2, cv::Mat(s.K), R, t, mask);
    });
}

BENCHMARK(BM_FindEssentialMatIter)
    ->Args({500, 90})
    ->Args({500, 50})
    ->Args({500, 30})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OpenCV_FindEssentialMat)
    ->Args({500, 90})
    ->Args({500, 50})
    ->Args({500, 30})
    ->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();

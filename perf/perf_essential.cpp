// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Timings (never pass/fail) of the kernels of one estimate: a solver call (one hypothesis), MSAC
// and SPRT scoring per point, the inlier mask, the IRLS refinement per point and iteration, pose
// recovery against cv::recoverPose, and the per-stage times of a whole estimate (EssentialReport).
// Names follow OpenCV's perf tests: what, then the parameters.
//
//   essential_perf --benchmark_filter='Solver|Score|Mask|Refine|RecoverPose|Stages'
//                  --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

#include "input/problem.hpp"
#include "refine/irls_refinement.hpp"
#include "scoring/msac_score.hpp"
#include "scoring/sprt.hpp"
#include "synthetic_scene.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/essential.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

namespace {

/** Counter whose value is nanoseconds per `items` (items counted over all iterations). */
benchmark::Counter nsPer(double items)
{
    return benchmark::Counter(items * 1e-9,
                              benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

/** Outlier-free samples of `size` correspondences with the protocol's noise. */
std::vector<essential_test::SyntheticScene> inlierSamples(int size, int count)
{
    std::vector<essential_test::SyntheticScene> v;
    for (int i = 0; i < count; ++i) {
        essential_test::SceneConfig cfg;
        cfg.numPoints = size;
        cfg.inlierRatio = 1.0;
        v.push_back(essential_test::makeScene(cfg, 4242 + i));
    }
    return v;
}

/** One solver call = one hypothesis (gn, lm: one root; nister: all roots; robust: one root from
its larger sample). Counter: solutions_per_call. */
void BM_Solver(benchmark::State& state, const char* name)
{
    auto solver = cv::essential::createSolver(name);
    const auto samples = inlierSamples(solver->sampleSize(), 256);
    cv::RNG rng(1);
    std::vector<cv::Matx33d> E(static_cast<size_t>(solver->maxSolutions()));
    size_t i = 0;
    int64_t solved = 0;
    for (auto _ : state) {
        const auto& p = samples[i++ % samples.size()];
        solved += solver->solve(p.x1.data(), p.x2.data(), rng, E.data());
        cv::Matx33d* out = E.data();
        benchmark::DoNotOptimize(out);
    }
    state.counters["solutions_per_call"] = double(solved) / double(state.iterations());
}
BENCHMARK_CAPTURE(BM_Solver, gn, "gn")->Unit(benchmark::kNanosecond);
BENCHMARK_CAPTURE(BM_Solver, lm, "lm")->Unit(benchmark::kNanosecond);
BENCHMARK_CAPTURE(BM_Solver, nister, "nister")->Unit(benchmark::kNanosecond);
BENCHMARK_CAPTURE(BM_Solver, robust, "robust")->Unit(benchmark::kNanosecond);
BENCHMARK_CAPTURE(BM_Solver, gn_nister, "gn+nister")->Unit(benchmark::kNanosecond);

/** The scoring benchmarks' inlier test: 1 px at the scenes' focal length (500). */
const cv::essential::InlierTest kScoringTest{1.0 / essential_test::SceneConfig().focal};

/** A normalised problem of N points, 50% inliers, focal 500. */
cv::essential::Problem scoringProblem(int n, cv::Matx33d& E)
{
    essential_test::SceneConfig cfg;
    cfg.numPoints = n;
    cfg.inlierRatio = 0.5;
    const auto s = essential_test::makeScene(cfg, 7);
    E = s.E;
    return cv::essential::makeProblem(s.x1, s.x2);
}

/** Full MSAC score of the true E on all N points (no early exit). Counter: ns_per_point. */
void BM_ScoreMsac(benchmark::State& state)
{
    cv::Matx33d E;
    const cv::essential::Problem problem = scoringProblem(int(state.range(0)), E);
    for (auto _ : state) {
        auto score = cv::essential::scoring::scoreMsac(E, problem, kScoringTest);
        benchmark::DoNotOptimize(score);
    }
    state.counters["ns_per_point"] = nsPer(double(state.iterations()) * double(state.range(0)));
}
BENCHMARK(BM_ScoreMsac)->Arg(500)->Arg(1000)->Arg(4000);

/** SPRT scoring of the true E with a test that never rejects it: the point-by-point path. */
void BM_ScoreSprt(benchmark::State& state)
{
    cv::Matx33d E;
    const cv::essential::Problem problem = scoringProblem(int(state.range(0)), E);
    cv::essential::scoring::SprtTest test; // A = infinity: no rejection, every point checked
    test.logIn = -1.0;
    test.logOut = 0.1;
    bool rejected = false;
    for (auto _ : state) {
        auto score = cv::essential::scoring::scoreMsacSprt(E, problem, kScoringTest, HUGE_VAL, test,
                                                           rejected);
        benchmark::DoNotOptimize(score);
    }
    state.counters["ns_per_point"] = nsPer(double(state.iterations()) * double(state.range(0)));
}
BENCHMARK(BM_ScoreSprt)->Arg(500)->Arg(1000);

void BM_InlierMask(benchmark::State& state)
{
    cv::Matx33d E;
    const cv::essential::Problem problem = scoringProblem(int(state.range(0)), E);
    std::vector<uchar> mask(problem.x1.size());
    for (auto _ : state) {
        auto count = cv::essential::scoring::inlierMask(E, problem, kScoringTest, mask.data());
        benchmark::DoNotOptimize(count);
    }
    state.counters["ns_per_point"] = nsPer(double(state.iterations()) * double(state.range(0)));
}
BENCHMARK(BM_InlierMask)->Arg(500);

/** The final refinement from the true E turned by about half a degree, on N points with 90%
inliers. Counters: iterations per call, ns_per_point_iteration. */
void BM_RefineIrls(benchmark::State& state)
{
    const int n = int(state.range(0));
    essential_test::SceneConfig cfg;
    cfg.numPoints = n;
    cfg.inlierRatio = 0.9;
    const auto s = essential_test::makeScene(cfg, 11);
    const auto problem = cv::essential::makeProblem(s.x1, s.x2);
    const cv::Matx33d E0 = s.E * essential_test::axisAngle(cv::Vec3d(0, 0.6, 0.8), 0.01);
    int64_t iterations = 0;
    for (auto _ : state) {
        auto r = cv::essential::refine::refineIrls(problem, E0, 0.5 / cfg.focal);
        iterations += r.iterations;
        benchmark::DoNotOptimize(r.E);
    }
    state.counters["iterations"] = double(iterations) / double(state.iterations());
    state.counters["ns_per_point_iteration"] = nsPer(double(iterations) * double(n));
}
BENCHMARK(BM_RefineIrls)->Arg(500)->Arg(1000)->Unit(benchmark::kMicrosecond);

/** Pose recovery on the same E (the true one), pixel points and inlier mask: the module's
recoverPose against cv::recoverPose. */
template <bool Ours> void BM_RecoverPose(benchmark::State& state)
{
    essential_test::SceneConfig cfg;
    cfg.numPoints = int(state.range(0));
    cfg.inlierRatio = 0.5;
    const auto s = essential_test::makeScene(cfg, 13);
    const cv::Mat K(s.K), E(s.E);
    cv::Mat mask0(cfg.numPoints, 1, CV_8U);
    for (int i = 0; i < cfg.numPoints; ++i)
        mask0.at<uchar>(i) = s.inlier[static_cast<size_t>(i)] ? 1 : 0;
    cv::Mat R, t, mask;
    for (auto _ : state) {
        mask0.copyTo(mask);
        int inFront = Ours ? cv::essential::recoverPoseIter(E, s.px1, s.px2, K, R, t, mask)
                           : cv::recoverPose(E, s.px1, s.px2, K, R, t, mask);
        benchmark::DoNotOptimize(inFront);
    }
}
BENCHMARK_TEMPLATE(BM_RecoverPose, true)
    ->Name("RecoverPose/essential")
    ->Arg(500)
    ->Arg(1000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_RecoverPose, false)
    ->Name("RecoverPose/cv")
    ->Arg(500)
    ->Arg(1000)
    ->Unit(benchmark::kMicrosecond);

/** The stages of a whole estimate with default EssentialParams (the drop-in's settings), from
EssentialReport, averaged over 16 scenes: where the fixed costs go. Args: N, inlier percent. */
void BM_Stages(benchmark::State& state)
{
    std::vector<essential_test::SyntheticScene> scenes;
    for (int i = 0; i < 16; ++i) {
        essential_test::SceneConfig cfg;
        cfg.numPoints = int(state.range(0));
        cfg.inlierRatio = state.range(1) / 100.0;
        scenes.push_back(essential_test::makeScene(cfg, 100 + i));
    }
    double setup = 0, search = 0, refine = 0, pose = 0, samples = 0, lo = 0;
    size_t i = 0;
    for (auto _ : state) {
        const auto& s = scenes[i++ % scenes.size()];
        cv::essential::EssentialReport report;
        cv::Mat mask;
        cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K),
                                            cv::essential::EssentialParams(), mask, &report);
        setup += report.timeSetupMs;
        search += report.timeSearchMs;
        refine += report.timeRefineMs;
        pose += report.timePoseMs;
        samples += report.iterations;
        lo += report.localOptimisations;
    }
    const double k = 1.0 / double(state.iterations());
    state.counters["setup_ms"] = setup * k;
    state.counters["search_ms"] = search * k;
    state.counters["refine_ms"] = refine * k;
    state.counters["pose_ms"] = pose * k;
    state.counters["samples"] = samples * k;
    state.counters["lo_runs"] = lo * k;
}
BENCHMARK(BM_Stages)->Args({500, 90})->Args({500, 70})->Args({500, 50})->Args({500, 30})->Unit(
    benchmark::kMillisecond);

} // namespace

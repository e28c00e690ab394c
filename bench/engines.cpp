// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The search engines on the paper's synthetic protocol (public API only):
//  1. preemptive RANSAC: reliability against time as M grows, for each solver and block size B;
//  2. time budgets: the overshoot of the whole call over its budget T, for both engines;
//  3. local optimisation (--part lo): the adaptive engine with loIterations = each of --lo;
//  4. SPRT (--part sprt): the adaptive engine without and with EssentialParams::sprt;
//  5. PROSAC (--part prosac): uniform against PROSAC sampling, the points sorted by a quality that
//     is perfect (inliers first) or noisy (inlier 1 + N(0, 1), outlier N(0, 1), best first).
//
//   essential_engines [--n 500] [--ratios 0.5,0.3] [--problems 100] [--solvers gn,lm,nister]
//                     [--hypotheses 50,100,200,500,1000,2000] [--blocks 25,50,100,200]
//                     [--budgets-ms 5,10,20,50] [--lo 0,5,10] [--lo-default K]
//                     [--reliable-deg 2,5] [--part curves|overshoot|lo|sprt|prosac|all]
//
// Parts lo, sprt and prosac are not in "all" (they are run on their own, with their own N).
//
// Reliable (the project's definition, docs/EXPERIMENTS.md): rotation error < 2 degrees and
// translation direction error < 5 degrees; --reliable-deg 1,3 gives the stricter criterion some
// older tables used. Times: median thread CPU time of a whole call (pose included), with the
// median wall time beside it; the time budgets (part overshoot) are wall-clock, so that part
// reports wall time.

#include "synthetic_scene.hpp"

#include "bench_common.hpp"
#include "bench_options.hpp"
#include <opencv2/essential.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace essential_bench;

namespace {

/** Rotation and translation-direction thresholds (degrees) of a reliable result. */
struct Criterion
{
    double rotDeg = 2.0, transDeg = 5.0;
};

struct Outcome
{
    std::vector<double> ms;               //!< wall time per call, sorted
    std::vector<double> cpuMs;            //!< thread CPU time per call, sorted
    std::vector<double> rotErr, transErr; //!< degrees, for the problems with a pose
    int reliable = 0;
    double iterations = 0, pointsScored = 0, hypothesesScored = 0, lo = 0, loKept = 0,
           rejections = 0; //!< sums over the problems
};

Outcome runAll(const std::vector<essential_test::SyntheticScene>& scenes,
               const cv::essential::EssentialParams& params, const Criterion& criterion)
{
    Outcome o;
    for (const auto& s : scenes) {
        cv::essential::EssentialReport report;
        const double cpu0 = threadCpuMs();
        const auto t0 = std::chrono::steady_clock::now();
        const cv::Mat E = cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), params,
                                                              cv::noArray(), &report);
        o.ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count());
        o.cpuMs.push_back(threadCpuMs() - cpu0);
        o.reliable += !E.empty() && report.poseRecovered &&
                      essential_test::rotationErrorDeg(report.R, s.R) < criterion.rotDeg &&
                      essential_test::translationErrorDeg(report.t, s.t) < criterion.transDeg;
        if (!E.empty() && report.poseRecovered) {
            o.rotErr.push_back(essential_test::rotationErrorDeg(report.R, s.R));
            o.transErr.push_back(essential_test::translationErrorDeg(report.t, s.t));
        }
        o.iterations += report.iterations;
        o.pointsScored += double(report.pointsScored);
        o.hypothesesScored += report.hypothesesScored;
        o.lo += report.localOptimisations;
        o.loKept += report.localOptimisationsKept;
        o.rejections += report.sprtRejections;
    }
    std::sort(o.ms.begin(), o.ms.end());
    std::sort(o.cpuMs.begin(), o.cpuMs.end());
    std::sort(o.rotErr.begin(), o.rotErr.end());
    std::sort(o.transErr.begin(), o.transErr.end());
    return o;
}

/** The scene with its correspondences reordered best first by a quality score: with `noisy`
false the inliers come first (in the scene's shuffled order), with `noisy` true an inlier scores
1 + N(0, 1) and an outlier N(0, 1), so the order is informative but imperfect, as descriptor
distances are. */
essential_test::SyntheticScene sortedByQuality(const essential_test::SyntheticScene& s, bool noisy,
                                               uint64_t seed)
{
    std::mt19937_64 gen(seed);
    std::normal_distribution<double> gauss(0.0, 1.0);
    std::vector<double> quality(s.px1.size());
    for (size_t i = 0; i < quality.size(); ++i)
        quality[i] = (s.inlier[i] ? 1.0 : 0.0) + (noisy ? gauss(gen) : 0.0);
    std::vector<size_t> order(quality.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return quality[a] > quality[b]; });
    essential_test::SyntheticScene sorted = s;
    for (size_t k = 0; k < order.size(); ++k) {
        sorted.x1[k] = s.x1[order[k]];
        sorted.x2[k] = s.x2[order[k]];
        sorted.px1[k] = s.px1[order[k]];
        sorted.px2[k] = s.px2[order[k]];
        sorted.inlier[k] = s.inlier[order[k]];
    }
    return sorted;
}

} // namespace

int main(int argc, char** argv)
{
    int n = 500, problems = 100;
    std::vector<double> ratios = {0.5, 0.3}, hyps = {50, 100, 200, 500, 1000, 2000},
                        blocks = {25, 50, 100, 200}, budgets = {5, 10, 20, 50};
    std::vector<std::string> solvers = {"gn", "lm", "nister"};
    std::string part = "all";
    std::vector<double> loIters = {0, 5, 10};
    int loDefault = cv::essential::EssentialParams().loIterations;
    Criterion criterion;
    Options opts("essential_engines");
    opts.add("n", n);
    opts.add("problems", problems);
    opts.add("ratios", ratios);
    opts.add("hypotheses", hyps);
    opts.add("blocks", blocks);
    opts.add("budgets-ms", budgets);
    opts.add("solvers", solvers);
    opts.add("part", part);
    opts.add("lo", loIters);
    opts.add("lo-default", loDefault);
    opts.custom("reliable-deg", "3,6", [&](const std::string& v) {
        const std::vector<double> deg = numbers(v);
        if (deg.size() != 2)
            essential_samples::fail("--reliable-deg takes ROTATION,TRANSLATION", 2);
        criterion = {deg[0], deg[1]};
    });
    opts.parse(argc, argv);
    std::printf("Reliable: rotation error < %g deg and translation direction error < %g deg.\n",
                criterion.rotDeg, criterion.transDeg);
    for (double ratio : ratios) {
        std::vector<essential_test::SyntheticScene> scenes;
        for (int p = 0; p < problems; ++p) {
            essential_test::SceneConfig cfg;
            cfg.numPoints = n;
            cfg.inlierRatio = ratio;
            scenes.push_back(essential_test::makeScene(cfg, 424242 + p));
        }
        if (part == "all" || part == "curves") {
            std::printf("\n### Preemptive RANSAC, N = %d, inlier ratio %.2f, %d problems\n\n", n,
                        ratio, problems);
            std::printf("| solver | B | M | reliable | median CPU ms | median wall ms |\n"
                        "|---|---|---|---|---|---|\n");
            for (const auto& solver : solvers)
                for (double B : blocks)
                    for (double M : hyps) {
                        cv::essential::EssentialParams params;
                        params.solver = solver;
                        params.engine = cv::essential::ENGINE_PREEMPTIVE;
                        params.preemptiveHypotheses = static_cast<int>(M);
                        params.preemptiveBlockSize = static_cast<int>(B);
                        const Outcome o = runAll(scenes, params, criterion);
                        std::printf("| %s | %.0f | %.0f | %.2f | %.2f | %.2f |\n", solver.c_str(),
                                    B, M, o.reliable / double(problems), median(o.cpuMs),
                                    median(o.ms));
                        std::fflush(stdout);
                    }
        }
        if (part == "all" || part == "overshoot") {
            std::printf("\n### Time budgets, N = %d, inlier ratio %.2f, %d problems, solver %s\n\n",
                        n, ratio, problems, cv::essential::EssentialParams().solver.c_str());
            std::printf("| engine | budget ms | reliable | median wall ms | p95 wall ms | p95 / "
                        "budget |\n|---|---|---|---|---|---|\n");
            for (cv::essential::EssentialEngine engine :
                 {cv::essential::ENGINE_ADAPTIVE, cv::essential::ENGINE_PREEMPTIVE})
                for (double T : budgets) {
                    cv::essential::EssentialParams params;
                    params.engine = engine;
                    params.timeBudgetMs = T;
                    // Let the budget, not the confidence or the cap, end the search.
                    params.confidence = 1.0 - 1e-12;
                    params.maxIterations = 100000000;
                    const Outcome o = runAll(scenes, params, criterion);
                    const double p95 = percentile(o.ms, 0.95);
                    std::printf(
                        "| %s | %.0f | %.2f | %.2f | %.2f | %.3f |\n",
                        engine == cv::essential::ENGINE_ADAPTIVE ? "adaptive" : "preemptive", T,
                        o.reliable / double(problems), percentile(o.ms, 0.5), p95, p95 / T);
                    std::fflush(stdout);
                }
        }
        if (part == "lo") {
            std::printf("\n### Local optimisation, N = %d, inlier ratio %.2f, %d problems, "
                        "default solver\n\n",
                        n, ratio, problems);
            std::printf("| loIterations | reliable | median CPU ms | median wall ms | mean samples "
                        "| LO runs (kept) per call | median rot err deg | median t err deg |\n"
                        "|---|---|---|---|---|---|---|---|\n");
            for (double lo : loIters) {
                cv::essential::EssentialParams params;
                params.loIterations = static_cast<int>(lo);
                const Outcome o = runAll(scenes, params, criterion);
                std::printf("| %.0f | %.3f | %.2f | %.2f | %.0f | %.2f (%.2f) | %.4f | %.4f |\n",
                            lo, o.reliable / double(problems), median(o.cpuMs), median(o.ms),
                            o.iterations / problems, o.lo / problems, o.loKept / problems,
                            percentile(o.rotErr, 0.5), percentile(o.transErr, 0.5));
                std::fflush(stdout);
            }
        }
        if (part == "sprt") {
            std::printf("\n### SPRT, N = %d, inlier ratio %.2f, %d problems, default solver, "
                        "loIterations %d\n\n",
                        n, ratio, problems, loDefault);
            std::printf(
                "| sprt | reliable | median CPU ms | median wall ms | mean samples | points "
                "scored per hypothesis | SPRT rejections per call |\n"
                "|---|---|---|---|---|---|---|\n");
            for (bool sprt : {false, true}) {
                cv::essential::EssentialParams params;
                params.loIterations = loDefault;
                params.sprt = sprt;
                const Outcome o = runAll(scenes, params, criterion);
                std::printf("| %s | %.3f | %.2f | %.2f | %.0f | %.1f | %.0f |\n",
                            sprt ? "on" : "off", o.reliable / double(problems), median(o.cpuMs),
                            median(o.ms), o.iterations / problems,
                            o.pointsScored / std::max(1.0, o.hypothesesScored),
                            o.rejections / problems);
                std::fflush(stdout);
            }
        }
        if (part == "prosac") {
            std::printf("\n### PROSAC, N = %d, inlier ratio %.2f, %d problems, default solver\n\n",
                        n, ratio, problems);
            std::printf("| order | sampler | reliable | mean samples | median CPU ms | median wall "
                        "ms |\n|---|---|---|---|---|---|\n");
            for (bool noisy : {false, true}) {
                std::vector<essential_test::SyntheticScene> sorted;
                for (int p = 0; p < problems; ++p)
                    sorted.push_back(sortedByQuality(scenes[p], noisy, 777 + p));
                for (cv::SamplingMethod sampler : {cv::SAMPLING_UNIFORM, cv::SAMPLING_PROSAC}) {
                    cv::essential::EssentialParams params;
                    params.sampler = sampler;
                    const Outcome o = runAll(sorted, params, criterion);
                    std::printf("| %s | %s | %.3f | %.0f | %.2f | %.2f |\n",
                                noisy ? "noisy quality" : "inliers first",
                                sampler == cv::SAMPLING_PROSAC ? "PROSAC" : "uniform",
                                o.reliable / double(problems), o.iterations / problems,
                                median(o.cpuMs), median(o.ms));
                    std::fflush(stdout);
                }
            }
        }
    }
    return 0;
}

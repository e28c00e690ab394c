// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The search engines on the paper's synthetic protocol (public API only):
//  1. preemptive RANSAC: reliability against time as M grows, for each solver and block size B;
//  2. time budgets: the overshoot of the whole call over its budget T, for both engines;
//  3. local optimisation (--part lo): the adaptive engine with loIterations = each of --lo;
//  4. SPRT (--part sprt): the adaptive engine without and with EssentialParams::sprt.
//
//   essential_engines [--n 500] [--ratios 0.5,0.3] [--problems 100] [--solvers gn,lm,nister]
//                     [--hypotheses 50,100,200,500,1000,2000] [--blocks 25,50,100,200]
//                     [--budgets-ms 5,10,20,50] [--lo 0,5,10] [--lo-default K]
//                     [--part curves|overshoot|lo|sprt|all]
//
// Parts lo and sprt are not in "all" (they are run on their own, with their own N).
//
// Reliable: rotation error < 1 degree and translation direction error < 3 degrees.

#include "synthetic_scene.hpp"

#include "bench_common.hpp"
#include <opencv2/essential.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

using namespace essential_bench;

namespace {

struct Outcome
{
    std::vector<double> ms;
    std::vector<double> rotErr, transErr; //!< degrees, for the problems with a pose
    int reliable = 0;
    double iterations = 0, pointsScored = 0, hypothesesScored = 0, lo = 0, loKept = 0,
           rejections = 0; //!< sums over the problems
};

Outcome runAll(const std::vector<essential_test::SyntheticScene>& scenes,
               const cv::essential::EssentialParams& params)
{
    Outcome o;
    for (const auto& s : scenes) {
        cv::essential::EssentialReport report;
        const auto t0 = std::chrono::steady_clock::now();
        const cv::Mat E = cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), params,
                                                              cv::noArray(), &report);
        o.ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count());
        o.reliable += !E.empty() && report.poseRecovered &&
                      essential_test::rotationErrorDeg(report.R, s.R) < 1.0 &&
                      essential_test::translationErrorDeg(report.t, s.t) < 3.0;
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
    std::sort(o.rotErr.begin(), o.rotErr.end());
    std::sort(o.transErr.begin(), o.transErr.end());
    return o;
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
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string k = argv[i], v = argv[i + 1];
        if (k == "--n")
            n = std::atoi(v.c_str());
        else if (k == "--problems")
            problems = std::atoi(v.c_str());
        else if (k == "--ratios")
            ratios = numbers(v);
        else if (k == "--hypotheses")
            hyps = numbers(v);
        else if (k == "--blocks")
            blocks = numbers(v);
        else if (k == "--budgets-ms")
            budgets = numbers(v);
        else if (k == "--solvers")
            solvers = split(v);
        else if (k == "--part")
            part = v;
        else if (k == "--lo")
            loIters = numbers(v);
        else if (k == "--lo-default")
            loDefault = std::atoi(v.c_str());
        else {
            std::fprintf(stderr, "unknown option %s\n", k.c_str());
            return 2;
        }
    }
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
            std::printf("| solver | B | M | reliability | median ms |\n|---|---|---|---|---|\n");
            for (const auto& solver : solvers)
                for (double B : blocks)
                    for (double M : hyps) {
                        cv::essential::EssentialParams params;
                        params.solver = solver;
                        params.engine = cv::essential::ENGINE_PREEMPTIVE;
                        params.preemptiveHypotheses = static_cast<int>(M);
                        params.preemptiveBlockSize = static_cast<int>(B);
                        const Outcome o = runAll(scenes, params);
                        std::printf("| %s | %.0f | %.0f | %.2f | %.2f |\n", solver.c_str(), B, M,
                                    o.reliable / double(problems), percentile(o.ms, 0.5));
                        std::fflush(stdout);
                    }
        }
        if (part == "all" || part == "overshoot") {
            std::printf("\n### Time budgets, N = %d, inlier ratio %.2f, %d problems, solver %s\n\n",
                        n, ratio, problems, cv::essential::EssentialParams().solver.c_str());
            std::printf("| engine | budget ms | reliability | median ms | p95 ms | p95 / budget |\n"
                        "|---|---|---|---|---|---|\n");
            for (cv::essential::EssentialEngine engine :
                 {cv::essential::ENGINE_ADAPTIVE, cv::essential::ENGINE_PREEMPTIVE})
                for (double T : budgets) {
                    cv::essential::EssentialParams params;
                    params.engine = engine;
                    params.timeBudgetMs = T;
                    // Let the budget, not the confidence or the cap, end the search.
                    params.confidence = 1.0 - 1e-12;
                    params.maxIterations = 100000000;
                    const Outcome o = runAll(scenes, params);
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
            std::printf("| loIterations | reliability | median ms | mean ms | mean samples | "
                        "LO runs (kept) per call | median rot err deg | median t err deg |\n"
                        "|---|---|---|---|---|---|---|---|\n");
            for (double lo : loIters) {
                cv::essential::EssentialParams params;
                params.loIterations = static_cast<int>(lo);
                const Outcome o = runAll(scenes, params);
                double mean = 0;
                for (double t : o.ms)
                    mean += t / problems;
                std::printf("| %.0f | %.3f | %.2f | %.2f | %.0f | %.2f (%.2f) | %.4f | %.4f |\n",
                            lo, o.reliable / double(problems), percentile(o.ms, 0.5), mean,
                            o.iterations / problems, o.lo / problems, o.loKept / problems,
                            percentile(o.rotErr, 0.5), percentile(o.transErr, 0.5));
                std::fflush(stdout);
            }
        }
        if (part == "sprt") {
            std::printf("\n### SPRT, N = %d, inlier ratio %.2f, %d problems, default solver, "
                        "loIterations %d\n\n",
                        n, ratio, problems, loDefault);
            std::printf("| sprt | reliability | median ms | mean ms | mean samples | points "
                        "scored per hypothesis | SPRT rejections per call |\n"
                        "|---|---|---|---|---|---|---|\n");
            for (bool sprt : {false, true}) {
                cv::essential::EssentialParams params;
                params.loIterations = loDefault;
                params.sprt = sprt;
                const Outcome o = runAll(scenes, params);
                double mean = 0;
                for (double t : o.ms)
                    mean += t / problems;
                std::printf("| %s | %.3f | %.2f | %.2f | %.0f | %.1f | %.0f |\n",
                            sprt ? "on" : "off", o.reliable / double(problems),
                            percentile(o.ms, 0.5), mean, o.iterations / problems,
                            o.pointsScored / std::max(1.0, o.hypothesesScored),
                            o.rejections / problems);
                std::fflush(stdout);
            }
        }
    }
    return 0;
}

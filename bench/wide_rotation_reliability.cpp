// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Does the requested confidence hold for every solver at wide rotations? Converging-camera scenes
// (test/converging_scene.hpp) with rotations of 45 to 90 degrees, estimated through
// findEssentialMatIter with EssentialParams{solver = S} (prob 0.999, threshold 1 px, maxIters
// 1000, everything else default); prints the reliability, the median samples drawn and the median
// time per solver and inlier ratio. The same scenes and seeds for every solver.
//
//   essential_wide_rotation_reliability [--problems 200] [--n 500] [--ratios 0.5,0.3]
//       [--solvers gn,lm,gn+nister,nister] [--min-deg 45] [--max-deg 90] [--seed 1]
//
// Reliable: rotation error < 2 degrees and translation direction error < 5 degrees.

#include "converging_scene.hpp"

#include "bench_common.hpp"
#include "bench_options.hpp"
#include <opencv2/essential.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace essential_bench;

int main(int argc, char** argv)
{
    int problems = 200, n = 500;
    uint64_t seed = 1;
    double minDeg = 45, maxDeg = 90;
    std::vector<double> ratios = {0.5, 0.3};
    std::vector<std::string> solvers = {"gn", "lm", "gn+nister", "nister"};
    Options opts("essential_wide_rotation_reliability");
    opts.add("problems", problems);
    opts.add("n", n);
    opts.add("seed", seed);
    opts.add("ratios", ratios);
    opts.add("solvers", solvers);
    opts.add("min-deg", minDeg);
    opts.add("max-deg", maxDeg);
    opts.parse(argc, argv);
    std::printf(
        "converging scenes, rotation %.0f-%.0f deg, N = %d, %d problems per row; reliable = "
        "rotation < 2 deg and translation < 5 deg\n\n",
        minDeg, maxDeg, n, problems);
    std::printf("| inlier ratio | solver | reliable | median samples | median ms |\n"
                "|---|---|---|---|---|\n");
    for (double ratio : ratios) {
        std::vector<essential_test::SyntheticScene> scenes;
        for (int p = 0; p < problems; ++p) {
            essential_test::ConvergingConfig cfg;
            cfg.numPoints = n;
            cfg.inlierRatio = ratio;
            cfg.minRotationDeg = minDeg;
            cfg.maxRotationDeg = maxDeg;
            scenes.push_back(essential_test::makeConvergingScene(cfg, seed * 100003 + p));
        }
        for (const std::string& solver : solvers) {
            int reliable = 0;
            std::vector<double> ms, samples;
            for (int p = 0; p < problems; ++p) {
                const auto& s = scenes[static_cast<size_t>(p)];
                cv::essential::EssentialParams params;
                params.solver = solver;
                params.seed = seed * 7 + static_cast<uint64_t>(p);
                cv::essential::EssentialReport report;
                const auto t0 = std::chrono::steady_clock::now();
                const cv::Mat E = cv::essential::findEssentialMatIter(
                    s.px1, s.px2, cv::Mat(s.K), params, cv::noArray(), &report);
                ms.push_back(
                    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                        .count());
                samples.push_back(report.iterations);
                reliable += !E.empty() && report.poseRecovered &&
                            essential_test::rotationErrorDeg(report.R, s.R) < 2.0 &&
                            essential_test::translationErrorDeg(report.t, s.t) < 5.0;
            }
            std::printf("| %.2f | %s | %.3f | %.0f | %.2f |\n", ratio, solver.c_str(),
                        reliable / double(problems), median(samples), median(ms));
            std::fflush(stdout);
        }
    }
    return 0;
}

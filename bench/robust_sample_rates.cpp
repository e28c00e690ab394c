// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The robust solver (Algorithm 3) on 10-point samples with k inliers and 10 - k outliers: how
// often it returns the true essential matrix, how often it returns anything, and what a call
// costs. Its hitProbability() is built from these rates (docs/SOLVERS.md, "robust").
//
//   essential_robust_sample_rates [--samples 1000] [--focals 500] [--seed 1]
//
// Samples of the paper's protocol (test/synthetic_scene.hpp: 90 degree field of view, rotation up
// to 35 degrees), noise 0.5 px and an inlier threshold of 1 px at each focal length given (so in
// normalised units noise 0.5 / f and threshold 1 / f, passed to the solver by setThreshold, as
// the engine does); outliers are independent random points. Correct: within 0.05 of the true E.
// CPU time of the solver calls only.

#include "synthetic_scene.hpp"

#include "bench_common.hpp"
#include "bench_options.hpp"
#include <opencv2/essential.hpp>

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
    int samples = 1000;
    uint64_t seed = 1;
    std::vector<double> focals = {500.0};
    essential_bench::Options opts("essential_robust_sample_rates");
    opts.add("samples", samples);
    opts.add("focals", focals);
    opts.add("seed", seed);
    opts.parse(argc, argv);
    std::printf("%d samples per row; noise 0.5 px, threshold 1 px; correct = within 0.05 of the "
                "true E\n\n",
                samples);
    std::printf("| focal (px) | inliers in the sample | correct | returned | us / call |\n"
                "|---|---|---|---|---|\n");
    for (double focal : focals) {
        cv::Ptr<cv::essential::EssentialSolver> robust = cv::essential::createSolver("robust");
        robust->setThreshold(1.0 / focal);
        cv::RNG rng(seed);
        for (int k = 10; k >= 5; --k) {
            std::vector<essential_test::SyntheticScene> scenes;
            for (int t = 0; t < samples; ++t) {
                essential_test::SceneConfig cfg;
                cfg.numPoints = 10;
                cfg.inlierRatio = k / 10.0;
                cfg.noiseSigma = 0.5 / focal;
                scenes.push_back(essential_test::makeScene(
                    cfg, seed * 1000003ULL + 7919ULL * static_cast<uint64_t>(k) +
                             static_cast<uint64_t>(t)));
            }
            std::vector<cv::Matx33d> E(static_cast<size_t>(samples));
            std::vector<int> count(static_cast<size_t>(samples));
            const double t0 = essential_bench::threadCpuMs();
            for (size_t t = 0; t < scenes.size(); ++t)
                count[t] = robust->solve(scenes[t].x1.data(), scenes[t].x2.data(), rng, &E[t]);
            const double us = 1000.0 * (essential_bench::threadCpuMs() - t0) / samples;
            int correct = 0, returned = 0;
            for (size_t t = 0; t < scenes.size(); ++t) {
                returned += count[t] == 1;
                correct +=
                    count[t] == 1 && essential_test::essentialDistance(E[t], scenes[t].E) < 0.05;
            }
            std::printf("| %.0f | %d | %.3f | %.3f | %.1f |\n", focal, k, correct / double(samples),
                        returned / double(samples), us);
            std::fflush(stdout);
        }
    }
    return 0;
}

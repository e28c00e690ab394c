// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The cost model behind EssentialParams::sampleBudget = BUDGET_OPENCV_TIME
// (src/termination/opencv_time_budget.hpp): thread CPU time of cv::findEssentialMat (RANSAC, 1000
// iterations) and of the module's default with the confidence cap, on data with 3% inliers, where
// both run to their caps, for a range of N. Prints time per OpenCV iteration and per module sample.
//
//   essential_opencv_time_model [--reps 3] [--sizes 100,250,500,1000,2000,4000,8000]

#include "bench_common.hpp"
#include "bench_options.hpp"
#include "synthetic_scene.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/essential.hpp>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>

int main(int argc, char** argv)
{
    int reps = 3;
    std::vector<double> sizes = {100, 250, 500, 1000, 2000, 4000, 8000};
    essential_bench::Options opts("essential_opencv_time_model");
    opts.add("reps", reps);
    opts.add("sizes", sizes);
    opts.parse(argc, argv);
    std::printf("| N | OpenCV us / iteration | module us / sample | ratio |\n|---|---|---|---|\n");
    for (double size : sizes) {
        const int n = static_cast<int>(size);
        double cvMs = 0, ourMs = 0;
        long samples = 0;
        for (int r = 0; r < reps; ++r) {
            essential_test::SceneConfig cfg;
            cfg.numPoints = n;
            cfg.inlierRatio = 0.03; // neither stopping rule is met: both run to their caps
            const essential_test::SyntheticScene s =
                essential_test::makeScene(cfg, static_cast<uint64_t>(n) * 10 + r);
            cv::Mat mask;
            double t0 = essential_bench::threadCpuMs();
            cv::findEssentialMat(s.px1, s.px2, s.K, cv::RANSAC, 0.999, 1.0, 1000, mask);
            cvMs += essential_bench::threadCpuMs() - t0;
            cv::essential::EssentialParams params;
            params.sampleBudget = cv::essential::BUDGET_CONFIDENCE;
            cv::essential::EssentialReport report;
            t0 = essential_bench::threadCpuMs();
            cv::essential::findEssentialMatIter(s.px1, s.px2, s.K, params, mask, &report);
            ourMs += essential_bench::threadCpuMs() - t0;
            samples += report.iterations;
        }
        const double cvUs = 1000.0 * cvMs / (1000.0 * reps);
        const double ourUs = samples > 0 ? 1000.0 * ourMs / samples : 0.0;
        std::printf("| %d | %.1f | %.2f | %.1f |\n", n, cvUs, ourUs,
                    ourUs > 0 ? cvUs / ourUs : 0.0);
    }
    return 0;
}

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The requested confidence holds for every solver at wide rotations: on converging views rotated by
// 45 to 90 degrees, the iterative solvers (and the default mix) are as reliable as the five-point
// solver, whose success does not depend on the pose. Before the start sequence of gn and lm
// (docs/SOLVERS.md, "Success rate by rotation") they were not: at 30% inliers gn found the pose in
// 53% of these problems and lm in 24%, against 100% for nister.

#include "converging_scene.hpp"

#include <opencv2/essential.hpp>

#include "essential_test.hpp"

#include <string>
#include <tuple>

namespace {

/** Problems per inlier ratio: at 100, "within one point of nister" allows one failure more than
nister. Measured on these problems: at 50% inliers every solver finds all 100; at 30% nister and
gn+nister find all 100, gn and lm 99 (each one problem where the sample cap ran out): no margin left
for them, which is what the declared rates give (the cap makes the confidence at the cap equal to
a direct solver's at maxIters; nister's several roots per sample help its local optimisation
beyond that). On 200 other problems (essential_wide_rotation_reliability) gn 1.000 / 0.990, lm
1.000 / 0.995, gn+nister and nister 1.000 / 1.000 at 50% / 30% inliers. 0.6 s (gn+nister, 50%) to
4.8 s (lm, 30%) per case in Release; scripts/test.sh leaves them out of the sanitizer run. */
constexpr int kProblems = 100;

/** Rotation below 2 degrees and translation direction below 5 degrees from the truth. */
bool reliable(const essential_test::SyntheticScene& s, const std::string& solver, uint64_t seed)
{
    cv::essential::EssentialParams params;
    params.solver = solver;
    params.confidence = 0.999;
    params.seed = seed;
    cv::essential::EssentialReport report;
    const cv::Mat E = cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), params,
                                                          cv::noArray(), &report);
    return !E.empty() && report.poseRecovered &&
           essential_test::rotationErrorDeg(report.R, s.R) < 2.0 &&
           essential_test::translationErrorDeg(report.t, s.t) < 5.0;
}

class WideRotation : public ::testing::TestWithParam<std::tuple<std::string, double>>
{
};

TEST_P(WideRotation, AsReliableAsTheFivePointSolver)
{
    const std::string solver = std::get<0>(GetParam());
    const double ratio = std::get<1>(GetParam());
    int found = 0, foundByNister = 0;
    for (int p = 0; p < kProblems; ++p) {
        essential_test::ConvergingConfig cfg;
        cfg.numPoints = 500;
        cfg.inlierRatio = ratio;
        cfg.minRotationDeg = 45.0;
        cfg.maxRotationDeg = 90.0;
        const auto scene =
            essential_test::makeConvergingScene(cfg, 4400 + static_cast<uint64_t>(p));
        found += reliable(scene, solver, 11 + static_cast<uint64_t>(p));
        foundByNister += reliable(scene, "nister", 11 + static_cast<uint64_t>(p));
    }
    RecordProperty("reliability", std::to_string(found / double(kProblems)));
    RecordProperty("nister", std::to_string(foundByNister / double(kProblems)));
    // Reliability at least nister's minus 0.01, in whole problems.
    EXPECT_GE(found, foundByNister - kProblems / 100) << solver << " at " << ratio << " inliers";
    // The comparison is only meaningful if nister itself is reliable here.
    EXPECT_GE(foundByNister, kProblems * 95 / 100);
}

std::string caseName(const ::testing::TestParamInfo<WideRotation::ParamType>& info)
{
    std::string solver = std::get<0>(info.param);
    for (char& c : solver)
        if (c == '+') c = '_';
    return solver + "_" + std::to_string(static_cast<int>(std::get<1>(info.param) * 100)) +
           "percent";
}

INSTANTIATE_TEST_SUITE_P(Solvers, WideRotation,
                         ::testing::Combine(::testing::Values("gn", "lm", "gn+nister"),
                                            ::testing::Values(0.5, 0.3)),
                         caseName);

} // namespace

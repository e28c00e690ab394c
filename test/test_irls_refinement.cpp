// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The IRLS refinement (refine/irls_refinement.hpp) on its own, the kernel of the local
// optimisation and of the final refinement (refine/final_refinement.hpp, whose own tests are in
// test_final_refinement.cpp): it converges to the true E from perturbed starts, its Cauchy weights
// take out most (not all) of the outliers' pull, which is why the final refinement no longer runs
// it on all points, Tukey's biweight takes out all of it, and it stops near its own fixed point.

#include "input/problem.hpp"
#include "refine/irls_refinement.hpp"
#include "refinement_fixtures.hpp"
#include "synthetic_scene.hpp"

#include "essential_test.hpp"

#include <vector>

namespace {

using essential_test::essentialDistance;
using essential_test::makeScene;
using essential_test::perturbed;
using essential_test::problemOf;
using essential_test::SceneConfig;
using essential_test::SyntheticScene;

TEST(IrlsRefinement, ConvergesToTheTrueEFromPerturbedStartsOnExactData)
{
    // Noise-free inliers: the true E is the unique zero of the cost, and LM reaches it to rounding
    // from starts 1-5 degrees off in rotation and 2-10 in translation (the RANSAC winners it gets
    // are within about a degree). Measured on these 20 scenes: at most 7 iterations of the cap of
    // 20, final essential distance at most 2e-10.
    SceneConfig cfg;
    cfg.numPoints = 200;
    cfg.inlierRatio = 1.0;
    cfg.noiseSigma = 0.0;
    for (uint64_t seed = 1; seed <= 20; ++seed) {
        const SyntheticScene s = makeScene(cfg, seed);
        const cv::essential::Problem problem = problemOf(s);
        const double rot = 1.0 + 4.0 * double(seed % 5) / 4.0; // 1 to 5 degrees
        const cv::Matx33d start = perturbed(s, rot, 2.0 * rot, seed);
        ASSERT_GT(essentialDistance(start, s.E), 1e-2);
        const auto result = cv::essential::refine::refineIrls(problem, start, 1.0 / cfg.focal);
        EXPECT_TRUE(result.improved);
        EXPECT_LT(essentialDistance(result.E, s.E), 1e-7)
            << "seed " << seed << ", start " << rot << " deg off";
        EXPECT_LE(result.iterations, cv::essential::refine::IrlsSettings().maxIterations);
    }
}

TEST(IrlsRefinement, CauchyWeightsTakeOutMostOfTheOutliersPull)
{
    // 40% outliers, refined from the true E: the Cauchy weights 1 / (1 + s^2 / sigma^2) must take
    // out most of the outliers' pull, so the result lands near the refinement of the inliers alone,
    // where unweighted least squares (the same code with a scale of 1e3, all weights ~1) is dragged
    // far off. Measured over these seeds (essential distance): robust to inliers-only 1.8e-4 to
    // 1.8e-2, least squares 0.64 to 1.9. The robust result is not the inliers-only one: with the
    // scale at the threshold each outlier still pulls with sigma^2 / s, which leaves up to 10 times
    // the noise-only error on two of these ten scenes.
    SceneConfig cfg;
    cfg.numPoints = 500;
    cfg.inlierRatio = 0.6;
    for (uint64_t seed = 1; seed <= 10; ++seed) {
        const SyntheticScene s = makeScene(cfg, seed);
        const double threshold = 1.0 / cfg.focal;
        const auto all = cv::essential::refine::refineIrls(problemOf(s), s.E, threshold);
        const auto clean = cv::essential::refine::refineIrls(problemOf(s), s.E, threshold);
        const auto leastSquares = cv::essential::refine::refineIrls(problemOf(s), s.E, 1e3);
        const double robustGap = essentialDistance(all.E, clean.E);
        const double leastSquaresGap = essentialDistance(leastSquares.E, clean.E);
        EXPECT_LT(robustGap, 0.03) << "seed " << seed;
        EXPECT_GT(leastSquaresGap, 0.3) << "seed " << seed;
        EXPECT_LT(robustGap, 0.1 * leastSquaresGap) << "seed " << seed;
    }
}

TEST(IrlsRefinement, TukeyLossIgnoresThePointsBeyondItsScale)
{
    // With Tukey's biweight at scale c, a point farther than c from its epipolar line has no
    // weight at all: dropping the points more than 2c from the truth (they stay beyond c along the
    // way from a start 0.05 degrees off) leaves the result unchanged, to the precision at which LM
    // stops (their constant cost c^2/6 each dilutes the last decreases): measured at most 2.3e-9
    // (essential distance) over these seeds. With the Cauchy loss at the same scale the same points
    // still pull: 6e-4 to 3.2e-2 between the two results.
    SceneConfig cfg;
    cfg.numPoints = 500;
    cfg.inlierRatio = 0.6;
    cv::essential::refine::IrlsSettings tukey;
    tukey.loss = cv::essential::refine::RobustLoss::Tukey;
    tukey.maxIterations = 30;
    tukey.relativeTolerance = 0.0; // the full cap: both runs stop at their minimum
    tukey.predictedTolerance = 0.0;
    cv::essential::refine::IrlsSettings cauchy = tukey;
    cauchy.loss = cv::essential::refine::RobustLoss::Cauchy;
    for (uint64_t seed = 1; seed <= 10; ++seed) {
        const SyntheticScene s = makeScene(cfg, seed);
        const double threshold = 1.0 / cfg.focal;
        const double c = 2.0 * threshold;
        std::vector<cv::Point2d> a, b;
        for (size_t i = 0; i < s.x1.size(); ++i) {
            const cv::Vec3d q1(s.x1[i].x, s.x1[i].y, 1.0), q2(s.x2[i].x, s.x2[i].y, 1.0);
            const cv::Vec3d Eq1 = s.E * q1, Etq2 = s.E.t() * q2;
            const double r = q2.dot(Eq1);
            const double d2 =
                Eq1[0] * Eq1[0] + Eq1[1] * Eq1[1] + Etq2[0] * Etq2[0] + Etq2[1] * Etq2[1];
            if (r * r < 4.0 * c * c * d2) {
                a.push_back(s.x1[i]);
                b.push_back(s.x2[i]);
            }
        }
        ASSERT_LT(a.size(), s.x1.size());
        const cv::essential::Problem all = problemOf(s);
        const cv::essential::Problem near = cv::essential::makeProblem(a, b);
        const cv::Matx33d start = perturbed(s, 0.05, 0.1, seed);
        const auto tAll = cv::essential::refine::refineIrls(all, start, c, tukey);
        const auto tNear = cv::essential::refine::refineIrls(near, start, c, tukey);
        EXPECT_LT(essentialDistance(tAll.E, tNear.E), 1e-8) << "seed " << seed;
        const auto cAll = cv::essential::refine::refineIrls(all, start, c, cauchy);
        const auto cNear = cv::essential::refine::refineIrls(near, start, c, cauchy);
        EXPECT_GT(essentialDistance(cAll.E, cNear.E), 1e-4) << "seed " << seed;
    }
}

TEST(IrlsRefinement, StartingAtItsOwnResultMovesLittle)
{
    // A second refinement from the first one's result moves E by far less than the noise moved it
    // from the truth: measured 4e-6 to 3.3e-5 (essential distance) over these seeds with GCC -O3,
    // up to 1.2e-4 with clang -O1, against 1e-3 to 2e-2 from the truth. It moves at all because the
    // stopping rule is a relative decrease of the whole robust cost, which the outliers' terms
    // dominate.
    SceneConfig cfg;
    cfg.numPoints = 500;
    cfg.inlierRatio = 0.6;
    for (uint64_t seed = 1; seed <= 10; ++seed) {
        const SyntheticScene s = makeScene(cfg, seed);
        const cv::essential::Problem problem = problemOf(s);
        const auto first = cv::essential::refine::refineIrls(problem, s.E, 1.0 / cfg.focal);
        const auto second = cv::essential::refine::refineIrls(problem, first.E, 1.0 / cfg.focal);
        EXPECT_LT(essentialDistance(first.E, second.E), 5e-4) << "seed " << seed;
    }
}

TEST(IrlsRefinement, AnInvalidStartIsReturnedUnchanged)
{
    SceneConfig cfg;
    cfg.numPoints = 50;
    const SyntheticScene s = makeScene(cfg, 5);
    const cv::essential::Problem problem = problemOf(s);
    const auto zero = cv::essential::refine::refineIrls(problem, cv::Matx33d::zeros(), 0.002);
    EXPECT_FALSE(zero.improved);
    EXPECT_EQ(cv::norm(zero.E), 0.0);
}

} // namespace

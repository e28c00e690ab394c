// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The final refinement (refine/final_refinement.hpp): it estimates the inliers' noise, it takes
// out the outliers' pull, it converges from perturbed starts, and on noise-free data the pose the
// drop-in pair returns is exact.

#include "input/problem.hpp"
#include "refine/final_refinement.hpp"
#include "refinement_fixtures.hpp"
#include "synthetic_scene.hpp"

#include <opencv2/essential.hpp>

#include "essential_test.hpp"

#include <vector>

namespace {

using essential_test::essentialDistance;
using essential_test::makeScene;
using essential_test::perturbed;
using essential_test::problemOf;
using essential_test::SceneConfig;
using essential_test::SyntheticScene;

TEST(FinalRefinement, EstimatesTheNoiseOfTheInliers)
{
    // From the true E, with noise from a quarter of the threshold to 1.66 times it (the wide-camera
    // variant with a 1 px threshold): measured estimate / true sigma 0.94 to 1.19 over these
    // scenes (the outliers within the window inflate it a little at 50% inliers; a window of 4
    // thresholds cuts a 1.66 px noise at 2.4 sigma, which lowers it a little).
    for (double noisePx : {0.25, 0.5, 1.0, 1.66})
        for (double ratio : {0.9, 0.5})
            for (uint64_t seed = 1; seed <= 5; ++seed) {
                SceneConfig cfg;
                cfg.inlierRatio = ratio;
                cfg.noiseSigma = noisePx / cfg.focal;
                const SyntheticScene s = makeScene(cfg, seed);
                const double threshold = 1.0 / cfg.focal;
                const double sigma =
                    cv::essential::refine::estimateNoise(problemOf(s), s.E, threshold, 4.0, 20);
                EXPECT_GT(sigma, 0.9 * cfg.noiseSigma) << noisePx << " px, seed " << seed;
                EXPECT_LT(sigma, 1.25 * cfg.noiseSigma) << noisePx << " px, seed " << seed;
            }
}

TEST(FinalRefinement, TakesOutTheOutliersPull)
{
    // 40% outliers, from the true E: the result must be that of the same refinement on the true
    // inliers alone, unless wrong matches lie near their epipolar lines and in front of both
    // cameras, where no two-view test can tell them from correct ones (scenes 2, 3, 5 and 7 hold
    // 2, 1, 1 and 1 of them; scene 2 lands 5.2e-3 away, on a short baseline, the others at most
    // 2e-5). Measured: 0 to 1.1e-5 on the other six scenes. The IRLS on all points with a Cauchy
    // loss (the final step before this one; test_irls_refinement.cpp) stays 1.8e-4 to 1.8e-2 away
    // on these scenes.
    SceneConfig cfg;
    cfg.inlierRatio = 0.6;
    int contaminated = 0;
    for (uint64_t seed = 1; seed <= 10; ++seed) {
        const SyntheticScene s = makeScene(cfg, seed);
        const double threshold = 1.0 / cfg.focal;
        const auto all = cv::essential::refine::refineFinal(problemOf(s), s.E,
                                                            cv::essential::InlierTest{threshold});
        const auto clean = cv::essential::refine::refineFinal(problemOf(s, true), s.E,
                                                              cv::essential::InlierTest{threshold});
        EXPECT_TRUE(all.improved);
        const bool wrongMatchesUsed = all.pointsUsed > clean.pointsUsed;
        contaminated += wrongMatchesUsed;
        EXPECT_LT(essentialDistance(all.E, clean.E), wrongMatchesUsed ? 1e-2 : 1e-4)
            << "seed " << seed;
    }
    EXPECT_LE(contaminated, 4);
}

TEST(FinalRefinement, ConvergesFromPerturbedStarts)
{
    // Starts 0.1 to 0.3 degrees off in rotation and three times that in translation (the search
    // winners it gets are 0.05 to 0.2 degrees off), 2e-3 to 1.5e-2 from the truth (essential
    // distance): the result is the refinement from the truth to within 1e-3 (the noise puts these
    // scenes' estimates 7e-4 to 6e-3 from the truth) on all but scene 4, a short baseline (0.15)
    // with a second minimum 1e-2 away, which the starts 0.2 and 0.3 degrees off reach. A start that
    // is off inflates the noise estimate; the second round, set up around the first one's result,
    // runs on 27 of these 30 starts. Measured: at most 9e-4 on the 28 others.
    SceneConfig cfg;
    cfg.inlierRatio = 0.6;
    int agree = 0, runs = 0;
    for (uint64_t seed = 1; seed <= 10; ++seed) {
        const SyntheticScene s = makeScene(cfg, seed);
        const double threshold = 1.0 / cfg.focal;
        const cv::essential::Problem problem = problemOf(s);
        const auto fromTruth =
            cv::essential::refine::refineFinal(problem, s.E, cv::essential::InlierTest{threshold});
        for (double rot : {0.1, 0.2, 0.3}) {
            const cv::Matx33d start = perturbed(s, rot, 3.0 * rot, seed);
            ASSERT_GT(essentialDistance(start, s.E), 2e-3);
            const auto r = cv::essential::refine::refineFinal(problem, start,
                                                              cv::essential::InlierTest{threshold});
            const double d = essentialDistance(r.E, fromTruth.E);
            ++runs;
            agree += d < 1e-3;
            EXPECT_LT(d, 2.5e-2) << "seed " << seed << ", start " << rot << " deg off";
        }
    }
    EXPECT_GE(agree, runs - 2);
}

TEST(FinalRefinement, NoiseFreeDataGiveTheExactPose)
{
    // Noise-free correct matches, alone or among wrong ones, through the drop-in pair
    // (findEssentialMatIter then recoverPose). Tukey's biweight gives the wrong matches farther
    // than its scale (one threshold here: the noise estimate is 0, the floor binds) from their
    // epipolar lines no pull, so the pose is the true one to the precision of the error measure
    // (acos near 1 cannot resolve angles below about 2e-6 degrees) unless a wrong match lies within
    // one threshold of its epipolar line and in front of both cameras. Measured: exact on 10 / 8 /
    // 9 of the 10 scenes at 100 / 70 / 40% correct matches, the others at most 0.016 degrees of
    // rotation and 0.2 of translation (a short baseline); the final step before this one was exact
    // on 10 / 0 / 0 of them, up to 0.019 and 0.24 degrees off.
    for (double ratio : {1.0, 0.7, 0.4}) {
        int exact = 0;
        for (uint64_t seed = 1; seed <= 10; ++seed) {
            SceneConfig cfg;
            cfg.noiseSigma = 0.0;
            cfg.inlierRatio = ratio;
            cfg.numPoints = 300;
            const SyntheticScene s = makeScene(cfg, seed);
            const cv::Mat K(s.K);
            cv::Mat mask, R, t;
            const cv::Mat E = cv::essential::findEssentialMatIter(s.px1, s.px2, K, cv::RANSAC,
                                                                  0.999, 1.0, 1000, mask);
            ASSERT_FALSE(E.empty());
            ASSERT_GT(cv::essential::recoverPoseIter(E, s.px1, s.px2, K, R, t, mask), 0);
            const double rot = essential_test::rotationErrorDeg(cv::Matx33d(R), s.R);
            const double trans = essential_test::translationErrorDeg(cv::Vec3d(t), s.t);
            exact += rot < 1e-5 && trans < 1e-5;
            EXPECT_LT(rot, 0.03) << "ratio " << ratio << ", seed " << seed;
            EXPECT_LT(trans, 0.3) << "ratio " << ratio << ", seed " << seed;
        }
        EXPECT_GE(exact, ratio == 1.0 ? 10 : 8) << "ratio " << ratio;
    }
}

TEST(FinalRefinement, TooFewPointsNearTheStartLeaveItUnchanged)
{
    // A start far from every point's epipolar geometry: fewer than 5 points in the band, nothing
    // to refine on.
    SceneConfig cfg;
    cfg.numPoints = 40;
    cfg.noiseSigma = 0.0;
    const SyntheticScene s = makeScene(cfg, 3);
    const cv::essential::Problem problem = problemOf(s);
    const cv::Matx33d far = perturbed(s, 30.0, 60.0, 3);
    const auto r =
        cv::essential::refine::refineFinal(problem, far, cv::essential::InlierTest{1e-9});
    EXPECT_FALSE(r.improved);
    EXPECT_EQ(cv::norm(r.E - far), 0.0);
}

} // namespace

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The in-front MSAC score (scoring/in_front_score) and the in-front check of the pipeline
// (EssentialParams::inFrontCheck): inliers behind a camera cost as outliers, the score is never
// below the plain one, and data that really hold points behind the cameras keep the true model.

#include "input/problem.hpp"
#include "scoring/in_front_score.hpp"
#include "scoring/msac_score.hpp"

#include <opencv2/essential.hpp>

#include "essential_test.hpp"
#include "synthetic_scene.hpp"

#include <random>
#include <vector>

namespace {

using cv::essential::Problem;
using cv::essential::scoring::inliersInFront;
using cv::essential::scoring::Score;
using cv::essential::scoring::scoreMsac;
using cv::essential::scoring::scoreMsacInFront;
using essential_test::makeScene;
using essential_test::SceneConfig;
using essential_test::SyntheticScene;

/** Near points (depth 2 to 5 for a baseline of 0.5 to 1, so that every one has parallax well above
the undecided level), with the given fraction of them true (the rest are uniform outliers, some of
which fall within the threshold by chance, in front or behind). */
SceneConfig nearConfig(double inlierRatio)
{
    SceneConfig cfg;
    cfg.numPoints = 300;
    cfg.inlierRatio = inlierRatio;
    cfg.noiseSigma = 0.0005;
    cfg.minDepth = 2.0;
    cfg.maxDepth = 5.0;
    cfg.minTranslation = 0.5;
    cfg.maxTranslation = 1.0;
    return cfg;
}

/** Appends `count` exact correspondences of points behind both cameras (negative depth in each),
which fit s.E like any inlier; returns how many were added. */
int addPointsBehind(SyntheticScene& s, int count, uint64_t seed)
{
    std::mt19937_64 g(seed);
    std::uniform_real_distribution<double> uni(-0.8, 0.8), depth(2.0, 5.0);
    int added = 0;
    for (int tries = 0; added < count && tries < 100000; ++tries) {
        const double z = depth(g);
        const cv::Vec3d X1(uni(g) * z, uni(g) * z, z);
        const cv::Vec3d behind1 = -X1; // depth -z in view 1
        const cv::Vec3d X2 = s.R * behind1 + s.baseline * s.t;
        if (X2[2] > -0.5) continue; // behind view 2 as well, and clearly so
        const cv::Point2d a(behind1[0] / behind1[2], behind1[1] / behind1[2]);
        const cv::Point2d b(X2[0] / X2[2], X2[1] / X2[2]);
        if (std::abs(b.x) > 1.0 || std::abs(b.y) > 1.0) continue;
        s.x1.push_back(a);
        s.x2.push_back(b);
        s.px1.push_back(cv::Point2d(s.K(0, 0) * a.x + s.K(0, 2), s.K(1, 1) * a.y + s.K(1, 2)));
        s.px2.push_back(cv::Point2d(s.K(0, 0) * b.x + s.K(0, 2), s.K(1, 1) * b.y + s.K(1, 2)));
        s.inlier.push_back(true);
        ++added;
    }
    return added;
}

constexpr double kThreshold = 0.002; // normalised: 4 noise sigmas
const cv::essential::InlierTest kTest{kThreshold};

TEST(InFrontScore, EqualsThePlainScoreWhenEveryInlierIsInFront)
{
    for (uint64_t seed = 1; seed <= 10; ++seed) {
        const SyntheticScene s = makeScene(nearConfig(1.0), seed);
        const Problem problem = cv::essential::makeProblem(s.x1, s.x2);
        const Score plain = scoreMsac(s.E, problem, kTest);
        const Score front = scoreMsacInFront(s.E, problem, kTest);
        EXPECT_GT(plain.inliers, 290) << "seed " << seed; // 4 sigmas: all but a few
        EXPECT_EQ(front.inliers, plain.inliers) << "seed " << seed;
        // Same terms summed in another order.
        EXPECT_NEAR(front.cost, plain.cost, 1e-12 * plain.cost) << "seed " << seed;
        EXPECT_EQ(inliersInFront(s.E, problem, kTest), plain.inliers) << "seed " << seed;
    }
}

TEST(InFrontScore, InliersBehindTheCamerasCostAsOutliers)
{
    const double t2 = kThreshold * kThreshold;
    for (uint64_t seed = 1; seed <= 10; ++seed) {
        SyntheticScene s = makeScene(nearConfig(1.0), seed);
        const int behind = addPointsBehind(s, 40, seed + 100);
        ASSERT_EQ(behind, 40) << "seed " << seed;
        const Problem problem = cv::essential::makeProblem(s.x1, s.x2);
        const Score plain = scoreMsac(s.E, problem, kTest);
        const Score front = scoreMsacInFront(s.E, problem, kTest);
        // The exact points behind are inliers of the plain score at zero distance; the in-front
        // score charges each threshold^2.
        EXPECT_EQ(front.inliers, plain.inliers - behind) << "seed " << seed;
        EXPECT_NEAR(front.cost, plain.cost + behind * t2, 1e-9 * t2) << "seed " << seed;
        EXPECT_EQ(inliersInFront(s.E, problem, kTest), plain.inliers - behind);
    }
}

TEST(InFrontScore, NeverBelowThePlainScoreAndKeepsTheEarlyExit)
{
    std::mt19937_64 g(7);
    for (uint64_t seed = 1; seed <= 20; ++seed) {
        SyntheticScene s = makeScene(nearConfig(0.5), seed);
        addPointsBehind(s, 20, seed + 200);
        const Problem problem = cv::essential::makeProblem(s.x1, s.x2);
        // Wrong models near the true one, where both scores have many inliers.
        const cv::Matx33d dR = essential_test::axisAngle(essential_test::randomUnit(g), 0.01);
        const cv::Matx33d E = essential_test::skewMatrix(s.t) * dR * s.R;
        const Score plain = scoreMsac(E, problem, kTest);
        const Score front = scoreMsacInFront(E, problem, kTest);
        EXPECT_GE(front.cost, plain.cost * (1 - 1e-12)) << "seed " << seed;
        EXPECT_LE(front.inliers, plain.inliers) << "seed " << seed;
        // A bound the plain cost reaches: returned without decomposition, at or above the bound.
        const Score exited = scoreMsacInFront(E, problem, kTest, 0.5 * plain.cost);
        EXPECT_GE(exited.cost, 0.5 * plain.cost) << "seed " << seed;
    }
    // A matrix with no decomposition costs N threshold^2.
    const SyntheticScene s = makeScene(nearConfig(0.5), 1);
    const Problem problem = cv::essential::makeProblem(s.x1, s.x2);
    const Score zero = scoreMsacInFront(cv::Matx33d::zeros(), problem, kTest);
    EXPECT_EQ(zero.inliers, 0);
    EXPECT_DOUBLE_EQ(zero.cost, problem.size() * kThreshold * kThreshold);
}

TEST(InFrontCheck, DataWithPointsBehindTheCamerasKeepTheTrueModel)
{
    // 12% of the correspondences (21% of the true ones) behind both cameras, consistent with the
    // true pose: the check searches again (more than 5% of the winner's inliers are behind), and
    // the true model, whose plain cost no other approaches, stays the answer.
    for (uint64_t seed = 1; seed <= 5; ++seed) {
        SyntheticScene s = makeScene(nearConfig(0.5), seed);
        addPointsBehind(s, 40, seed + 300);
        cv::essential::EssentialParams params;
        params.threshold = 1.0; // px; the scene's focal length is 500
        params.seed = seed;
        cv::essential::EssentialReport on, off;
        const cv::Mat Eon =
            cv::essential::findEssentialMatIter(s.px1, s.px2, s.K, params, cv::noArray(), &on);
        params.inFrontCheck = false;
        const cv::Mat Eoff =
            cv::essential::findEssentialMatIter(s.px1, s.px2, s.K, params, cv::noArray(), &off);
        ASSERT_FALSE(Eon.empty()) << "seed " << seed;
        ASSERT_FALSE(Eoff.empty()) << "seed " << seed;
        EXPECT_TRUE(on.inFrontSearch) << "seed " << seed;
        EXPECT_FALSE(off.inFrontSearch) << "seed " << seed;
        EXPECT_FALSE(off.inFrontSearchKept) << "seed " << seed;
        EXPECT_LT(essential_test::essentialDistance(cv::Matx33d(Eon), s.E), 0.01)
            << "seed " << seed;
        EXPECT_LT(essential_test::essentialDistance(cv::Matx33d(Eoff), s.E), 0.01)
            << "seed " << seed;
    }
    // A clean scene: nothing behind, no second search.
    const SyntheticScene clean = makeScene(nearConfig(0.5), 11);
    cv::essential::EssentialReport report;
    cv::essential::EssentialParams params;
    cv::essential::findEssentialMatIter(clean.px1, clean.px2, clean.K, params, cv::noArray(),
                                        &report);
    EXPECT_TRUE(report.success);
    EXPECT_FALSE(report.inFrontSearch);
}

} // namespace

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The search's two guards against wrong basins on real pairs: the cheirality check of a
// hypothesis on its own sample (solvers/sample_cheirality), and the pool of distinct runners-up
// polished at the end of the search (local_optimisation/candidate_pool).

#include "local_optimisation/candidate_pool.hpp"
#include "solvers/sample_cheirality.hpp"

#include "essential_test.hpp"
#include "synthetic_scene.hpp"

#include <opencv2/calib3d.hpp>

#include <limits>
#include <random>
#include <vector>

namespace {

using cv::essential::local_optimisation::CandidatePool;
using cv::essential::solvers::essentialSampleIsInFront;
using cv::essential::solvers::keepSolutionsInFront;
using essential_test::makeScene;
using essential_test::SceneConfig;
using essential_test::skewMatrix;

/** The first n true correspondences of a clean scene. */
void truePoints(const essential_test::SyntheticScene& s, int n, std::vector<cv::Point2d>& a,
                std::vector<cv::Point2d>& b)
{
    a.clear();
    b.clear();
    for (size_t i = 0; i < s.x1.size() && static_cast<int>(a.size()) < n; ++i)
        if (s.inlier[i]) {
            a.push_back(s.x1[i]);
            b.push_back(s.x2[i]);
        }
}

TEST(SampleCheirality, TrueModelPassesAtAnySignAndScale)
{
    SceneConfig cfg;
    cfg.inlierRatio = 1.0;
    cfg.numPoints = 50;
    for (uint64_t seed = 1; seed <= 200; ++seed) {
        const auto s = makeScene(cfg, seed);
        std::vector<cv::Point2d> a, b;
        truePoints(s, 10, a, b);
        ASSERT_EQ(a.size(), 10u);
        for (double scale : {1.0, -1.0, 3.7, -0.02})
            EXPECT_TRUE(essentialSampleIsInFront(scale * s.E, a.data(), b.data(), 10))
                << "seed " << seed << " scale " << scale;
    }
}

TEST(SampleCheirality, PointsBehindBothCamerasFail)
{
    // X2 = R X1 + c t satisfies the epipolar constraint of E = [t]x R for any c, so every solver
    // fits such points; but with c = -4 and depth 3 the point is behind the second camera. Its
    // rays are then explained, in front of both cameras, only by the twisted pose of E, while the
    // points with c = 1 are explained only by (R, t): no one pose holds both groups.
    std::mt19937_64 g(7);
    std::uniform_real_distribution<double> u(-0.5, 0.5);
    const cv::Matx33d R = essential_test::axisAngle(cv::Vec3d(0, 1, 0), 0.1);
    const cv::Vec3d t(0, 0, 1);
    const cv::Matx33d E = skewMatrix(t) * R;
    std::vector<cv::Point2d> a, b;
    for (int i = 0; i < 5; ++i) {
        const cv::Vec3d X1(u(g) * 3.0, u(g) * 3.0, 3.0);
        const cv::Vec3d X2 = R * X1 + (i < 2 ? 1.0 : -4.0) * t;
        ASSERT_NEAR(cv::Vec3d(X2[0] / X2[2], X2[1] / X2[2], 1.0)
                        .dot(E * cv::Vec3d(X1[0] / X1[2], X1[1] / X1[2], 1.0)),
                    0.0, 1e-12);
        a.emplace_back(X1[0] / X1[2], X1[1] / X1[2]);
        b.emplace_back(X2[0] / X2[2], X2[1] / X2[2]);
    }
    EXPECT_FALSE(essentialSampleIsInFront(E, a.data(), b.data(), 5));
    // Each group alone is consistent.
    EXPECT_TRUE(essentialSampleIsInFront(E, a.data(), b.data(), 2));
    EXPECT_TRUE(essentialSampleIsInFront(E, a.data() + 2, b.data() + 2, 3));
}

TEST(SampleCheirality, RejectsNonEssentialAndKeepsOrder)
{
    SceneConfig cfg;
    cfg.inlierRatio = 1.0;
    cfg.numPoints = 20;
    const auto s = makeScene(cfg, 3);
    std::vector<cv::Point2d> a, b;
    truePoints(s, 5, a, b);
    EXPECT_FALSE(essentialSampleIsInFront(cv::Matx33d::zeros(), a.data(), b.data(), 5));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(essentialSampleIsInFront(cv::Matx33d::all(nan), a.data(), b.data(), 5));

    // Solutions [zero, E, -2E, zero] keep E and -2E, in that order.
    cv::Matx33d sols[4] = {cv::Matx33d::zeros(), s.E, -2.0 * s.E, cv::Matx33d::zeros()};
    ASSERT_EQ(keepSolutionsInFront(sols, 4, a.data(), b.data(), 5), 2);
    EXPECT_LT(cv::norm(sols[0] - s.E), 1e-15);
    EXPECT_LT(cv::norm(sols[1] + 2.0 * s.E), 1e-15);
}

TEST(SampleCheirality, RandomModelsAreMostlyRejected)
{
    // A random model (a random rotation and translation) explains a clean sample's depth signs
    // only by chance: over many random models the check must reject most. This is the property
    // that makes it worth running before scoring.
    SceneConfig cfg;
    cfg.inlierRatio = 1.0;
    cfg.numPoints = 20;
    std::mt19937_64 g(11);
    int rejected = 0, trials = 400;
    for (int k = 0; k < trials; ++k) {
        const auto s = makeScene(cfg, 100 + static_cast<uint64_t>(k));
        std::vector<cv::Point2d> a, b;
        truePoints(s, 5, a, b);
        const cv::Matx33d E = skewMatrix(essential_test::randomUnit(g)) *
                              essential_test::axisAngle(essential_test::randomUnit(g), 1.0);
        if (!essentialSampleIsInFront(E, a.data(), b.data(), 5)) ++rejected;
    }
    EXPECT_GT(rejected, trials / 2);
}

/** Depth signs of one correspondence under (R, t) by a different route from the check's: the
least-squares depths of lambda2 q2 = lambda1 R q1 + t (exact for a correspondence on the epipolar
geometry of [t]x R). Returns +1 (both positive), -1 (both negative), 0 (mixed) or 2 (parallax below
the check's limit: undecided); `margin` is set when the point is within 1% of that limit or a depth
is within 1e-9 of zero, where round-off may decide either way. */
int referenceSigns(const cv::Matx33d& R, const cv::Vec3d& t, const cv::Point2d& p1,
                   const cv::Point2d& p2, bool& margin)
{
    const cv::Vec3d a = R * cv::Vec3d(p1.x, p1.y, 1.0), b(p2.x, p2.y, 1.0);
    const double sine = cv::norm(a.cross(b)) / (cv::norm(a) * cv::norm(b));
    const double limit = cv::essential::solvers::kMinCheiralityParallax;
    // [a, -b] (lambda1, lambda2)^T = -t by the normal equations.
    const double aa = a.dot(a), ab = a.dot(b), bb = b.dot(b), det = aa * bb - ab * ab;
    const double l1 = (-t.dot(a) * bb + ab * t.dot(b)) / det;
    const double l2 = (aa * t.dot(b) + ab * (-t.dot(a))) / det;
    margin |= std::abs(sine - limit) < 0.01 * limit || std::abs(l1) < 1e-9 || std::abs(l2) < 1e-9;
    if (sine <= limit) return 2;
    if (l1 > 0 && l2 > 0) return 1;
    if (l1 < 0 && l2 < 0) return -1;
    return 0;
}

TEST(SampleCheirality, EqualsTheFourPosesOfOpenCvDecomposition)
{
    // The check derives the four poses' depth signs from dot products of one rotated ray a point
    // (sample_cheirality.hpp). Reference: cv::decomposeEssentialMat's rotations and translation,
    // and each point's least-squares depths under each of the four poses. Points are placed on the
    // epipolar geometry with random depth signs in either view, so every outcome occurs; some sit
    // near the epipole or at infinity (parallax below the limit), where the point must not count.
    std::mt19937_64 g(2024);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int compared = 0, agreed = 0, inFront = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const cv::Matx33d R =
            essential_test::axisAngle(essential_test::randomUnit(g), CV_PI * std::abs(u(g)));
        const cv::Vec3d t = essential_test::randomUnit(g);
        const int n = 2 + trial % 9;
        std::vector<cv::Point2d> a, b;
        const bool allFront = trial % 3 == 0; // a third of the samples fully in front of (R, t)
        for (int i = 0; i < n; ++i) {
            const double depth =
                (allFront || u(g) > -0.6 ? 1.0 : -1.0) * (0.5 + 4.0 * std::abs(u(g)));
            const cv::Vec3d X1(u(g) * depth, u(g) * depth, depth);
            // Far points (depth 1e4) have parallax below the limit.
            const cv::Vec3d X = trial % 7 == 0 && i == 0 ? X1 * 1e4 : X1;
            const cv::Vec3d X2 = R * X + t;
            if (allFront && X2[2] <= 0) continue;
            a.emplace_back(X[0] / X[2], X[1] / X[2]);
            b.emplace_back(X2[0] / X2[2], X2[1] / X2[2]);
        }
        if (a.empty()) continue;
        const cv::Matx33d E = skewMatrix(t) * R;
        cv::Mat R1, R2, tt;
        cv::decomposeEssentialMat(E, R1, R2, tt);
        const cv::Matx33d rotations[2] = {cv::Matx33d(R1), cv::Matx33d(R2)};
        const cv::Vec3d t0(tt.at<double>(0), tt.at<double>(1), tt.at<double>(2));
        bool expected = false, margin = false;
        for (const auto& Ri : rotations)
            for (double sign : {1.0, -1.0}) {
                bool ok = true;
                for (size_t i = 0; i < a.size(); ++i) {
                    const int v = referenceSigns(Ri, sign * t0, a[i], b[i], margin);
                    ok &= v == 1 || v == 2;
                }
                expected |= ok;
            }
        if (margin) continue;
        ++compared;
        inFront += expected;
        const double scale = trial % 2 ? 1.0 : -2.5; // any scale and sign of E
        const bool got =
            essentialSampleIsInFront(scale * E, a.data(), b.data(), static_cast<int>(a.size()));
        agreed += got == expected;
        if (got != expected) ADD_FAILURE() << "trial " << trial << ": expected " << expected;
    }
    EXPECT_GT(compared, 18000);
    EXPECT_EQ(agreed, compared);
    // Both outcomes are well represented.
    EXPECT_GT(inFront, compared / 4);
    EXPECT_LT(inFront, compared * 3 / 4);
}

TEST(CandidatePool, KeepsTheCheapestDistinctModels)
{
    SceneConfig cfg;
    CandidatePool pool;
    EXPECT_EQ(pool.size(), 0);
    EXPECT_EQ(pool.entryCost(), HUGE_VAL);
    std::vector<cv::Matx33d> models;
    for (uint64_t seed = 1; seed <= 6; ++seed)
        models.push_back(makeScene(cfg, seed).E);
    // Costs 6, 5, ..., 1: the pool keeps the four cheapest (models 2..5).
    for (int i = 0; i < 6; ++i)
        pool.offer(models[i], 6.0 - i);
    ASSERT_EQ(pool.size(), CandidatePool::kSize);
    EXPECT_DOUBLE_EQ(pool.entryCost(), 4.0);
    std::vector<bool> seen(6, false);
    for (int k = 0; k < pool.size(); ++k)
        for (int i = 0; i < 6; ++i)
            if (CandidatePool::same(pool[k].E, models[i] * (1.0 / cv::norm(models[i])))) {
                seen[i] = true;
                EXPECT_DOUBLE_EQ(pool[k].cost, 6.0 - i);
            }
    EXPECT_FALSE(seen[0]);
    EXPECT_FALSE(seen[1]);
    for (int i = 2; i < 6; ++i)
        EXPECT_TRUE(seen[i]) << i;

    // The same model again (negated, rescaled, nudged below kSameModel) at a lower cost replaces
    // its entry rather than taking a slot; at a higher cost it changes nothing.
    const cv::Matx33d nudged = -5.0 * (models[2] + cv::Matx33d::all(1e-3));
    pool.offer(nudged, 0.5);
    EXPECT_EQ(pool.size(), CandidatePool::kSize);
    EXPECT_DOUBLE_EQ(pool.entryCost(), 3.0);
    pool.offer(models[5], 100.0);
    bool found05 = false;
    for (int k = 0; k < pool.size(); ++k)
        found05 = found05 || pool[k].cost == 0.5;
    EXPECT_TRUE(found05);
    // A costlier new model does not enter a full pool.
    pool.offer(models[0], 3.5);
    for (int k = 0; k < pool.size(); ++k)
        EXPECT_NE(pool[k].cost, 3.5);
}

} // namespace

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The search engines: preemptive breadth-first RANSAC, the adaptive loop, time budgets and the
// checks on their parameters. (Timings are measured by bench/engines.cpp, never asserted here.)

#include "synthetic_scene.hpp"

#include <opencv2/essential.hpp>

#include "essential_test.hpp"

namespace {

using essential_test::makeScene;
using essential_test::SceneConfig;

cv::Mat run(const essential_test::SyntheticScene& s, const cv::essential::EssentialParams& params,
            cv::essential::EssentialReport& report, cv::Mat& mask)
{
    return cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), params, mask, &report);
}

TEST(PreemptiveEngine, FindsThePoseWithDefaultHypotheses)
{
    SceneConfig cfg;
    cfg.inlierRatio = 0.6;
    int good = 0;
    for (uint64_t seed = 1; seed <= 20; ++seed) {
        const auto s = makeScene(cfg, seed);
        cv::essential::EssentialParams params;
        params.engine = cv::essential::ENGINE_PREEMPTIVE;
        params.solver = "gn"; // one hypothesis per call at most, so the counts below are exact
        cv::essential::EssentialReport report;
        cv::Mat mask;
        const cv::Mat E = run(s, params, report, mask);
        ASSERT_FALSE(E.empty());
        // M = 500 hypotheses scored, each solver call adds at most one for gn.
        EXPECT_EQ(report.hypothesesScored, 500);
        EXPECT_GE(report.hypothesesGenerated, 500);
        EXPECT_EQ(report.hypothesesConverged, 500);
        EXPECT_EQ(cv::countNonZero(mask), report.inliers);
        good += essential_test::rotationErrorDeg(report.R, s.R) < 1.0 &&
                essential_test::translationErrorDeg(report.t, s.t) < 3.0;
    }
    // At 60% inliers 500 gn hypotheses hold about 500 * 0.35 * 0.6^5 = 14 true ones.
    EXPECT_GE(good, 19);
}

TEST(PreemptiveEngine, HonoursMAndBlockSizeAtTheExtremes)
{
    SceneConfig cfg;
    cfg.numPoints = 200;
    cfg.inlierRatio = 0.9;
    const auto s = makeScene(cfg, 3);
    cv::essential::EssentialParams params;
    params.engine = cv::essential::ENGINE_PREEMPTIVE;
    cv::essential::EssentialReport report;
    cv::Mat mask;
    params.preemptiveHypotheses = 1;
    run(s, params, report, mask);
    EXPECT_EQ(report.hypothesesScored, 1);
    params.preemptiveHypotheses = 64;
    params.preemptiveBlockSize = 1000; // larger than the data: one block, then the best of all
    const cv::Mat E = run(s, params, report, mask);
    EXPECT_EQ(report.hypothesesScored, 64);
    ASSERT_FALSE(E.empty());
    EXPECT_LT(essential_test::rotationErrorDeg(report.R, s.R), 1.0);
    params.preemptiveBlockSize = 1; // halving after every point
    EXPECT_FALSE(run(s, params, report, mask).empty());
}

TEST(TimeBudget, AnExhaustedBudgetStopsTheSearchAtOnce)
{
    // A budget smaller than the time the refinement needs leaves the search no time at all: the
    // adaptive loop checks its deadline every 8 samples, the preemptive one before generating.
    SceneConfig cfg;
    cfg.inlierRatio = 0.9;
    const auto s = makeScene(cfg, 5);
    cv::essential::EssentialParams params;
    params.timeBudgetMs = 1e-6;
    cv::essential::EssentialReport report;
    cv::Mat mask;
    run(s, params, report, mask);
    EXPECT_LE(report.iterations, 8);
    params.engine = cv::essential::ENGINE_PREEMPTIVE;
    const cv::Mat E = run(s, params, report, mask);
    EXPECT_TRUE(E.empty());
    EXPECT_EQ(report.hypothesesGenerated, 0);
    EXPECT_EQ(cv::countNonZero(mask), 0);
}

TEST(TimeBudget, AGenerousBudgetChangesNothingForTheAdaptiveEngine)
{
    // The adaptive engine stops on its confidence long before 10 s: the budget never binds and the
    // result is the same as without it.
    SceneConfig cfg;
    cfg.inlierRatio = 0.7;
    const auto s = makeScene(cfg, 9);
    cv::essential::EssentialParams params;
    cv::essential::EssentialReport a, b;
    cv::Mat maskA, maskB;
    const cv::Mat E1 = run(s, params, a, maskA);
    params.timeBudgetMs = 10000;
    const cv::Mat E2 = run(s, params, b, maskB);
    EXPECT_EQ(a.iterations, b.iterations);
    EXPECT_LT(cv::norm(E1 - E2), 1e-12);
}

TEST(EngineParameters, InvalidSettingsRaise)
{
    SceneConfig cfg;
    cfg.numPoints = 50;
    const auto s = makeScene(cfg, 1);
    auto expectThrow = [&](const cv::essential::EssentialParams& p, int code) {
        cv::essential::EssentialReport r;
        cv::Mat m;
        try {
            run(s, p, r, m);
            ADD_FAILURE() << "no exception";
        } catch (const cv::Exception& e) {
            EXPECT_EQ(e.code, code) << e.what();
        }
    };
    cv::essential::EssentialParams p;
    p.engine = static_cast<cv::essential::EssentialEngine>(7); // only a cast can make one
    expectThrow(p, cv::Error::StsBadArg);
    p = cv::essential::EssentialParams();
    p.engine = cv::essential::ENGINE_PREEMPTIVE;
    p.score = cv::SCORE_METHOD_LMEDS;
    expectThrow(p, cv::Error::StsNotImplemented);
    p = cv::essential::EssentialParams();
    p.timeBudgetMs = -1;
    expectThrow(p, cv::Error::StsBadArg);
    p.timeBudgetMs = std::nan("");
    expectThrow(p, cv::Error::StsBadArg);
    p = cv::essential::EssentialParams();
    p.engine = cv::essential::ENGINE_OPENCV;
    p.timeBudgetMs = 5;
    expectThrow(p, cv::Error::StsNotImplemented);
    p = cv::essential::EssentialParams();
    p.preemptiveBlockSize = 0;
    expectThrow(p, cv::Error::StsBadArg);
    p = cv::essential::EssentialParams();
    p.preemptiveHypotheses = -3;
    expectThrow(p, cv::Error::StsBadArg);
}

} // namespace

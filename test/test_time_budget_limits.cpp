// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The range of EssentialParams::timeBudgetMs: 0 and +inf mean no budget; a positive finite budget
// beyond the clock's range (about 9e12 ms, 292 years of nanoseconds) saturates at a deadline that
// never passes, instead of overflowing the conversion to the clock's 64-bit count (undefined
// behaviour, which UBSan reports); NaN and negative budgets raise.

#include "synthetic_scene.hpp"
#include "termination/deadline.hpp"

#include <opencv2/essential.hpp>

#include "essential_test.hpp"

#include <limits>

namespace {

using cv::essential::termination::Deadline;
using essential_test::makeScene;
using essential_test::SceneConfig;

const double kInf = std::numeric_limits<double>::infinity();

TEST(TimeBudgetLimits, DeadlinesBeyondTheClockSaturate)
{
    for (const double ms : {9.3e12, 1e13, 1e18, 1e300, std::numeric_limits<double>::max(), kInf}) {
        SCOPED_TRACE(ms);
        const Deadline d = Deadline::after(ms);
        EXPECT_TRUE(d.active);
        EXPECT_FALSE(d.passed());
        EXPECT_EQ(d.end, Deadline::Clock::time_point::max());
        EXPECT_GT(d.remainingMs(), 1e12); // the clock's range left, not a wrapped negative time
    }
    // Ordinary and spent budgets are unchanged.
    const Deadline hour = Deadline::after(3.6e6);
    EXPECT_FALSE(hour.passed());
    EXPECT_GT(hour.remainingMs(), 3.5e6);
    EXPECT_LE(hour.remainingMs(), 3.6e6);
    for (const double ms : {0.0, -1.0, -kInf, std::numeric_limits<double>::quiet_NaN()}) {
        SCOPED_TRACE(ms);
        EXPECT_TRUE(Deadline::after(ms).passed());
    }
}

TEST(TimeBudgetLimits, HugeAndInfiniteBudgetsChangeNothing)
{
    SceneConfig cfg;
    cfg.numPoints = 200;
    cfg.inlierRatio = 0.7;
    const auto s = makeScene(cfg, 21);
    const cv::Mat K(s.K);
    for (const cv::essential::EssentialEngine engine :
         {cv::essential::ENGINE_ADAPTIVE, cv::essential::ENGINE_PREEMPTIVE}) {
        SCOPED_TRACE(engine);
        cv::essential::EssentialParams params;
        params.engine = engine;
        params.preemptiveHypotheses = 100; // a budget would otherwise size M (up to 1e6)
        cv::Mat mask0;
        cv::essential::EssentialReport r0;
        const cv::Mat E0 = cv::essential::findEssentialMatIter(s.px1, s.px2, K, params, mask0, &r0);
        ASSERT_FALSE(E0.empty());
        for (const double budget : {1e13, 1e300, kInf}) {
            SCOPED_TRACE(budget);
            params.timeBudgetMs = budget;
            cv::Mat mask;
            cv::essential::EssentialReport r;
            const cv::Mat E =
                cv::essential::findEssentialMatIter(s.px1, s.px2, K, params, mask, &r);
            // The deadline never passes: the same samples, the same result.
            EXPECT_EQ(r.iterations, r0.iterations);
            EXPECT_EQ(cv::norm(E, E0, cv::NORM_INF), 0.0);
            EXPECT_EQ(cv::countNonZero(mask != mask0), 0);
        }
    }
}

TEST(TimeBudgetLimits, InfinityIsNoBudgetEvenForOpenCVsLoop)
{
    if (!cv::essential::isOpenCvLoopAvailable())
        GTEST_SKIP() << "ENGINE_OPENCV is not available in this build";
    SceneConfig cfg;
    cfg.numPoints = 100;
    const auto s = makeScene(cfg, 22);
    cv::essential::EssentialParams params;
    params.engine = cv::essential::ENGINE_OPENCV;
    params.timeBudgetMs = kInf; // no budget: accepted
    cv::Mat mask;
    EXPECT_FALSE(
        cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), params, mask).empty());
    params.timeBudgetMs = 1e300; // a budget, which OpenCV's loop cannot honour
    try {
        cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), params, mask);
        ADD_FAILURE() << "a finite budget was accepted by ENGINE_OPENCV";
    } catch (const cv::Exception& e) {
        EXPECT_EQ(e.code, cv::Error::StsNotImplemented);
    }
}

TEST(TimeBudgetLimits, NegativeAndNaNBudgetsRaise)
{
    SceneConfig cfg;
    cfg.numPoints = 50;
    const auto s = makeScene(cfg, 23);
    for (const double budget : {-1.0, -kInf, std::numeric_limits<double>::quiet_NaN()}) {
        SCOPED_TRACE(budget);
        cv::essential::EssentialParams params;
        params.timeBudgetMs = budget;
        cv::Mat mask;
        try {
            cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), params, mask);
            ADD_FAILURE() << "accepted";
        } catch (const cv::Exception& e) {
            EXPECT_EQ(e.code, cv::Error::StsBadArg);
            EXPECT_NE(e.err.find("timeBudgetMs"), std::string::npos) << e.err;
        }
    }
}

} // namespace

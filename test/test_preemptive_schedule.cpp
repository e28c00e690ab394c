// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The preemption schedule of the breadth-first search, f(i) = floor(M 2^-floor(i / B)): the
// function itself, and the search following it (the points it scores are exactly what the
// schedule implies).

#include "input/problem.hpp"
#include "search/search.hpp"
#include "synthetic_scene.hpp"

#include <opencv2/essential.hpp>

#include "essential_test.hpp"

#include <cmath>

namespace {

using cv::essential::search::preemptiveSurvivors;

TEST(PreemptiveSchedule, HalvesAfterEveryBlock)
{
    // Reference values written out by hand for M = 500, B = 100.
    EXPECT_EQ(preemptiveSurvivors(500, 0, 100), 500);
    EXPECT_EQ(preemptiveSurvivors(500, 99, 100), 500);
    EXPECT_EQ(preemptiveSurvivors(500, 100, 100), 250);
    EXPECT_EQ(preemptiveSurvivors(500, 250, 100), 125);
    EXPECT_EQ(preemptiveSurvivors(500, 300, 100), 62);
    EXPECT_EQ(preemptiveSurvivors(500, 800, 100), 1);
    EXPECT_EQ(preemptiveSurvivors(500, 900, 100), 1); // never below one
    // Far past the point where the shift would exceed the width of the type.
    EXPECT_EQ(preemptiveSurvivors(1 << 30, int64_t(1) << 40, 1), 1);
}

TEST(PreemptiveSchedule, MatchesTheFormulaEverywhere)
{
    for (int M : {1, 2, 3, 7, 64, 500, 1000, 4097})
        for (int B : {1, 2, 10, 100, 333})
            for (int i = 0; i < 40 * B; i += std::max(1, B / 3)) {
                const double f = std::floor(M * std::pow(2.0, -std::floor(double(i) / B)));
                EXPECT_EQ(preemptiveSurvivors(M, i, B), std::max(1, int(f)))
                    << "M " << M << " B " << B << " i " << i;
            }
}

/** Points the breadth-first scoring must score for M hypotheses, n points and blocks of B: every
block is scored by the hypotheses alive when it starts, f(start of the block), and the scoring
stops at the first block that starts with one survivor. */
int64_t expectedPointsScored(int M, int n, int B)
{
    int64_t total = 0;
    for (int begin = 0; begin < n; begin += B) {
        const int alive = std::max(1, int(std::floor(M * std::pow(2.0, -begin / B))));
        if (alive <= 1) break;
        total += int64_t(std::min(n, begin + B) - begin) * alive;
    }
    return total;
}

TEST(PreemptiveSchedule, TheSearchScoresWhatTheScheduleSays)
{
    essential_test::SceneConfig cfg;
    cfg.numPoints = 350;
    cfg.inlierRatio = 0.8;
    const auto scene = essential_test::makeScene(cfg, 17);
    const cv::essential::Problem problem = cv::essential::makeProblem(scene.x1, scene.x2);
    for (int M : {1, 5, 64, 300})
        for (int B : {1, 20, 100, 1000}) {
            SCOPED_TRACE("M " + std::to_string(M) + " B " + std::to_string(B));
            // gn returns at most one matrix per call, so the search holds exactly M hypotheses.
            cv::Ptr<cv::essential::EssentialSolver> solver = cv::essential::createSolver("gn");
            cv::RNG rng(3);
            cv::essential::search::SearchSettings settings;
            settings.test.threshold = 1.0 / cfg.focal;
            settings.preemptiveHypotheses = M;
            settings.preemptiveBlockSize = B;
            const auto result =
                cv::essential::search::searchPreemptive(problem, *solver, rng, settings);
            ASSERT_EQ(result.hypothesesScored, M);
            EXPECT_EQ(result.pointsScored, expectedPointsScored(M, cfg.numPoints, B));
        }
}

} // namespace

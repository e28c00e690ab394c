// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Composite solver names ("gn+nister", "gn:3+lm:1"): parsing, the proportion of calls, the
// combined rates, and use through findEssentialMatIter.

#include "synthetic_scene.hpp"

#include <opencv2/essential.hpp>

#include "essential_test.hpp"

#include <atomic>

namespace {

std::atomic<int> callsA{0}, callsB{0};

/** A solver that counts its calls and returns nothing; sample size and rate are chosen per test. */
class Counting : public cv::essential::EssentialSolver
{
public:
    Counting(std::atomic<int>* calls, int sampleSize, double rate)
        : calls_(calls), sampleSize_(sampleSize), rate_(rate)
    {
    }
    int sampleSize() const override { return sampleSize_; }
    int maxSolutions() const override { return 1; }
    int solve(const cv::Point2d*, const cv::Point2d*, cv::RNG&, cv::Matx33d*) override
    {
        ++*calls_;
        return 0;
    }
    double successRate() const override { return rate_; }

private:
    std::atomic<int>* calls_;
    int sampleSize_;
    double rate_;
};

void registerCounters()
{
    cv::essential::registerSolver("count_a", [] { return cv::makePtr<Counting>(&callsA, 5, 0.2); });
    cv::essential::registerSolver("count_b", [] { return cv::makePtr<Counting>(&callsB, 7, 0.8); });
}

TEST(CompositeSolver, TakesTurnsInTheGivenProportion)
{
    registerCounters();
    auto solver = cv::essential::createSolver("count_a:3+count_b");
    EXPECT_EQ(solver->sampleSize(), 7);
    EXPECT_NEAR(solver->successRate(), (3 * 0.2 + 0.8) / 4, 1e-12);
    EXPECT_NEAR(solver->hitProbability(0.5),
                (3 * 0.2 * std::pow(0.5, 5) + 0.8 * std::pow(0.5, 7)) / 4, 1e-12);
    callsA = 0;
    callsB = 0;
    cv::RNG rng;
    cv::Point2d p[7];
    cv::Matx33d E[1];
    int maxRunOfA = 0, run = 0;
    for (int i = 0; i < 400; ++i) {
        const int before = callsA;
        solver->solve(p, p, rng, E);
        run = callsA > before ? run + 1 : 0;
        maxRunOfA = std::max(maxRunOfA, run);
    }
    EXPECT_EQ(callsA, 300);
    EXPECT_EQ(callsB, 100);
    EXPECT_LE(maxRunOfA, 3); // interleaved, not in blocks
}

TEST(CompositeSolver, RejectsMalformedNames)
{
    for (const char* bad : {"gn+", "+gn", "gn:0+lm", "gn:x+lm", "gn:+lm", "gn+no_such_solver"}) {
        SCOPED_TRACE(bad);
        EXPECT_THROW(cv::essential::createSolver(bad), cv::Exception);
    }
    EXPECT_THROW(
        cv::essential::registerSolver("a+b", [] { return cv::essential::createSolver("gn"); }),
        cv::Exception);
}

TEST(CompositeSolver, EstimatesThroughFindEssentialMatIter)
{
    essential_test::SceneConfig cfg;
    cfg.numPoints = 400;
    cfg.inlierRatio = 0.5;
    for (const char* name : {"gn+lm", "gn:3+robust:1"}) {
        SCOPED_TRACE(name);
        const auto s = essential_test::makeScene(cfg, 11);
        cv::essential::EssentialParams params;
        params.solver = name;
        cv::essential::EssentialReport report;
        cv::Mat mask;
        const cv::Mat E =
            cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), params, mask, &report);
        ASSERT_FALSE(E.empty());
        EXPECT_LT(essential_test::rotationErrorDeg(report.R, s.R), 1.0);
        EXPECT_LT(essential_test::translationErrorDeg(report.t, s.t), 3.0);
    }
}

} // namespace

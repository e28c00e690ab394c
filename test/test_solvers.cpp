// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The minimal-set solvers gn and lm on outlier-free samples of the paper's synthetic protocol:
// how often they reach the true essential matrix, and that whatever they return is exact.

#include "solvers/gauss_newton.hpp"
#include "solvers/levenberg_marquardt.hpp"
#include "synthetic_scene.hpp"

#include <opencv2/essential.hpp>

#include <gtest/gtest.h>

namespace {

using essential_test::essentialDistance;
using essential_test::makeScene;
using essential_test::SceneConfig;

struct Rates
{
    double converged = 0, correct = 0;
};

/** Runs `solver` once on each of `trials` five-point problems. A returned E is checked to fit its
sample (every squared residual below 1e-12) and counted correct when it is the true E (distance
below `tolerance` up to scale and sign). */
Rates measure(cv::essential::EssentialSolver& solver, int trials, double noise, double tolerance)
{
    cv::RNG rng(7);
    int converged = 0, correct = 0;
    for (int t = 0; t < trials; ++t) {
        SceneConfig cfg;
        cfg.numPoints = 5;
        cfg.inlierRatio = 1.0;
        cfg.noiseSigma = noise;
        const auto scene = makeScene(cfg, 90000 + t);
        cv::Matx33d E[1];
        if (solver.solve(scene.x1.data(), scene.x2.data(), rng, E) != 1) continue;
        ++converged;
        for (int i = 0; i < 5; ++i) {
            const cv::Vec3d q1(scene.x1[i].x, scene.x1[i].y, 1),
                q2(scene.x2[i].x, scene.x2[i].y, 1);
            const double r = q2.dot(E[0] * q1);
            EXPECT_LT(r * r, 1e-12) << "returned E does not fit its sample (problem " << t << ")";
        }
        correct += essentialDistance(E[0], scene.E) < tolerance;
    }
    return {converged / double(trials), correct / double(trials)};
}

// Measured with 2000 problems: gn converges on 76.7% and finds the true E on 35.7%, lm 79.3% and
// 40.1% (noise-free; the remaining converged calls find one of the other real roots). The bounds
// leave about 3 standard errors (sqrt(p(1-p)/2000) ~ 1.1%) of margin, and each solver's
// successRate() must not promise more than it delivers.
void expectRates(cv::essential::EssentialSolver& solver, double minConverged, double minCorrect)
{
    const Rates r = measure(solver, 2000, 0.0, 1e-6);
    ::testing::Test::RecordProperty("converged", std::to_string(r.converged));
    ::testing::Test::RecordProperty("correct", std::to_string(r.correct));
    EXPECT_GT(r.converged, minConverged);
    EXPECT_GT(r.correct, minCorrect);
    EXPECT_LE(solver.successRate(), r.correct + 0.03);
}

TEST(Solvers, GaussNewtonConvergesOnNoiseFreeMinimalSets)
{
    cv::essential::solvers::GaussNewtonSolver gn;
    expectRates(gn, 0.72, 0.32);
}

TEST(Solvers, LevenbergMarquardtConvergesOnNoiseFreeMinimalSets)
{
    cv::essential::solvers::LevenbergMarquardtSolver lm;
    expectRates(lm, 0.74, 0.36);
}

// With the protocol's noise (0.001) a minimal set still has exact solutions, now near the true E:
// measured 24.5% (gn) and 28.7% (lm) within 0.05 of it.
TEST(Solvers, BothFindNearTrueSolutionsWithNoise)
{
    cv::essential::solvers::GaussNewtonSolver gn;
    cv::essential::solvers::LevenbergMarquardtSolver lm;
    EXPECT_GT(measure(gn, 1000, 0.001, 0.05).correct, 0.20);
    EXPECT_GT(measure(lm, 1000, 0.001, 0.05).correct, 0.24);
}

TEST(Solvers, DegenerateSamplesGiveNoSolution)
{
    cv::RNG rng(1);
    cv::Matx33d E[1];
    // five copies of one correspondence: J has rank 1
    std::vector<cv::Point2d> same1(5, cv::Point2d(0.1, 0.2)), same2(5, cv::Point2d(0.15, 0.22));
    for (const char* name : {"gn", "lm"}) {
        auto solver = cv::essential::createSolver(name);
        const int n = solver->solve(same1.data(), same2.data(), rng, E);
        // A rank-1 system may still drive the single distinct residual to zero; any E returned
        // must then fit it. What must not happen is a crash or a non-finite matrix.
        if (n == 1) {
            for (int i = 0; i < 9; ++i)
                EXPECT_TRUE(std::isfinite(E[0].val[i])) << name;
        }
        EXPECT_GE(n, 0);
        EXPECT_LE(n, 1);
    }
}

TEST(Solvers, BuiltInsAreRegistered)
{
    const auto names = cv::essential::listSolvers();
    EXPECT_NE(std::find(names.begin(), names.end(), "gn"), names.end());
    EXPECT_NE(std::find(names.begin(), names.end(), "lm"), names.end());
    for (const char* name : {"gn", "lm"}) {
        auto s = cv::essential::createSolver(name);
        EXPECT_EQ(s->sampleSize(), 5);
        EXPECT_EQ(s->maxSolutions(), 1);
    }
}

} // namespace

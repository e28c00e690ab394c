// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The solver registry as a user outside the module sees it: a solver defined here, registered by
// name, listed, and used by findEssentialMatIter; and the registry's argument checks.

#include "opencv2/essential.hpp"
#include "synthetic_scene.hpp"

#include "essential_test.hpp"

#include <algorithm>
#include <atomic>
#include <string>
#include <vector>

namespace {

using essential_test::essentialDistance;
using essential_test::makeScene;
using essential_test::SceneConfig;
using essential_test::SyntheticScene;

/** Calls of CountingSolver::solve across all instances. */
std::atomic<int> gSolveCalls{0};
/** Instances the factory made. */
std::atomic<int> gInstances{0};

/** A user-defined solver: delegates to the built-in "gn" solver and counts its calls. */
class CountingSolver : public cv::essential::EssentialSolver
{
public:
    CountingSolver() : inner_(cv::essential::createSolver("gn")) { ++gInstances; }

    int sampleSize() const override { return inner_->sampleSize(); }
    int maxSolutions() const override { return inner_->maxSolutions(); }
    double successRate() const override { return inner_->successRate(); }
    double hitProbabilityAt(double w, const cv::Matx33d& model) const override
    {
        return inner_->hitProbabilityAt(w, model);
    }
    void setThreshold(double t) override { inner_->setThreshold(t); }

    int solve(const cv::Point2d* x1, const cv::Point2d* x2, cv::RNG& rng,
              cv::Matx33d* solutions) override
    {
        ++gSolveCalls;
        return inner_->solve(x1, x2, rng, solutions);
    }

private:
    cv::Ptr<cv::essential::EssentialSolver> inner_;
};

/** A solver that never finds anything, to show the engine really uses the named solver. */
class NeverSolver : public cv::essential::EssentialSolver
{
public:
    int sampleSize() const override { return 5; }
    int maxSolutions() const override { return 1; }
    int solve(const cv::Point2d*, const cv::Point2d*, cv::RNG&, cv::Matx33d*) override
    {
        ++gSolveCalls;
        return 0;
    }
};

SyntheticScene scene(uint64_t seed)
{
    SceneConfig cfg;
    cfg.numPoints = 300;
    cfg.inlierRatio = 0.6;
    return makeScene(cfg, seed);
}

bool listed(const std::string& name)
{
    const std::vector<std::string> names = cv::essential::listSolvers();
    return std::find(names.begin(), names.end(), name) != names.end();
}

TEST(Registry, BuiltInSolversListedSorted)
{
    const std::vector<std::string> names = cv::essential::listSolvers();
    EXPECT_TRUE(listed("gn"));
    EXPECT_TRUE(listed("lm"));
    EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
    for (const char* name : {"gn", "lm"}) {
        const cv::Ptr<cv::essential::EssentialSolver> s = cv::essential::createSolver(name);
        ASSERT_FALSE(s.empty());
        EXPECT_EQ(s->sampleSize(), 5);
        EXPECT_GE(s->maxSolutions(), 1);
        EXPECT_GT(s->successRate(), 0.0);
        EXPECT_LE(s->successRate(), 1.0);
    }
}

TEST(Registry, CustomSolverIsListedAndUsed)
{
    const std::string name = "test-counting-gn";
    cv::essential::registerSolver(name, [] { return cv::makePtr<CountingSolver>(); });
    EXPECT_TRUE(listed(name));
    const std::vector<std::string> names = cv::essential::listSolvers();
    EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));

    for (const uint64_t seed : {11ULL, 12ULL, 13ULL}) {
        SCOPED_TRACE(seed);
        const SyntheticScene s = scene(seed);
        gSolveCalls = 0;
        gInstances = 0;
        cv::essential::EssentialParams params;
        params.solver = name;
        cv::essential::EssentialReport report;
        cv::Mat mask;
        const cv::Mat E =
            cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), params, mask, &report);
        EXPECT_GT(gSolveCalls.load(), 0);
        EXPECT_GE(gInstances.load(), 1);
        // Every solver call the engine reports went through our solver.
        EXPECT_EQ(report.hypothesesGenerated, gSolveCalls.load());
        ASSERT_EQ(E.rows, 3);
        EXPECT_LT(essentialDistance(cv::Matx33d(E), s.E), 0.05);
        EXPECT_GE(cv::countNonZero(mask), static_cast<int>(0.9 * s.numInliers));

        // Delegating to gn with the same seed gives exactly gn's result.
        params.solver = "gn";
        cv::Mat maskGn;
        const cv::Mat Egn =
            cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), params, maskGn);
        ASSERT_EQ(Egn.rows, 3);
        EXPECT_EQ(cv::norm(E, Egn, cv::NORM_INF), 0.0);
        EXPECT_EQ(cv::countNonZero(mask != maskGn), 0);
    }
}

TEST(Registry, ReplacingASolverTakesEffect)
{
    const std::string name = "test-replaceable";
    const SyntheticScene s = scene(21);
    cv::essential::EssentialParams params;
    params.solver = name;

    cv::essential::registerSolver(name, [] { return cv::makePtr<NeverSolver>(); });
    gSolveCalls = 0;
    cv::Mat mask;
    const cv::Mat none =
        cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), params, mask);
    EXPECT_TRUE(none.empty());
    EXPECT_GT(gSolveCalls.load(), 0);
    EXPECT_EQ(cv::countNonZero(mask), 0);

    cv::essential::registerSolver(name, [] { return cv::makePtr<CountingSolver>(); });
    gSolveCalls = 0;
    const cv::Mat E = cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), params, mask);
    ASSERT_EQ(E.rows, 3);
    EXPECT_GT(gSolveCalls.load(), 0);
    EXPECT_LT(essentialDistance(cv::Matx33d(E), s.E), 0.05);
}

TEST(Registry, UnknownNameThrowsNamingIt)
{
    try {
        cv::essential::createSolver("definitely-not-registered");
        ADD_FAILURE() << "no exception";
    } catch (const cv::Exception& e) {
        EXPECT_EQ(e.code, cv::Error::StsBadArg);
        EXPECT_NE(e.err.find("definitely-not-registered"), std::string::npos) << e.err;
        EXPECT_NE(e.err.find("gn"), std::string::npos) << "should list the known solvers";
    }
}

TEST(Registry, EmptyNameOrFactoryThrows)
{
    const size_t before = cv::essential::listSolvers().size();
    try {
        cv::essential::registerSolver("", [] { return cv::makePtr<CountingSolver>(); });
        ADD_FAILURE() << "empty name accepted";
    } catch (const cv::Exception& e) {
        EXPECT_EQ(e.code, cv::Error::StsBadArg);
        EXPECT_NE(e.err.find("name"), std::string::npos) << e.err;
    }
    try {
        cv::essential::registerSolver("test-empty-factory",
                                      cv::essential::EssentialSolverFactory());
        ADD_FAILURE() << "empty factory accepted";
    } catch (const cv::Exception& e) {
        EXPECT_EQ(e.code, cv::Error::StsBadArg);
        EXPECT_NE(e.err.find("factory"), std::string::npos) << e.err;
        EXPECT_NE(e.err.find("test-empty-factory"), std::string::npos) << e.err;
    }
    EXPECT_EQ(cv::essential::listSolvers().size(), before);
    EXPECT_FALSE(listed("test-empty-factory"));
}

} // namespace

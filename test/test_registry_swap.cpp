// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The registry rule of docs/ROBUSTNESS.md: an estimate takes a copy of its solver's factory under
// the registry's lock when it starts and owns the solver it makes, so that replacing the very
// solver that running estimates use is safe: each estimate runs with the factory registered when
// it started. (test_concurrency.cpp re-registers a name no estimate uses; here the name in use is
// swapped between two factories that make equivalent solvers, so every result must equal the
// sequential one bit for bit.)

#include "synthetic_scene.hpp"

#include <opencv2/essential.hpp>

#include "essential_test.hpp"

#include <atomic>
#include <cstring>
#include <thread>
#include <vector>

namespace {

bool identical(const cv::Mat& a, const cv::Mat& b)
{
    if (a.size() != b.size() || a.type() != b.type()) return false;
    return a.empty() || std::memcmp(a.data, b.data, a.total() * a.elemSize()) == 0;
}

TEST(RegistrySwap, ReplacingTheSolverInUseWhileEightThreadsEstimate)
{
    const char* name = "registry_swap_in_use";
    // Two different factories of the same solver.
    const cv::essential::EssentialSolverFactory first = [] {
        return cv::essential::createSolver("gn");
    };
    const cv::essential::EssentialSolverFactory second = [] {
        cv::Ptr<cv::essential::EssentialSolver> s = cv::essential::createSolver("gn");
        return s;
    };
    cv::essential::registerSolver(name, first);

    std::vector<essential_test::SyntheticScene> data;
    for (int i = 0; i < 16; ++i) {
        essential_test::SceneConfig cfg;
        cfg.numPoints = 200;
        cfg.inlierRatio = 0.6;
        data.push_back(essential_test::makeScene(cfg, 900 + i));
    }
    cv::essential::EssentialParams params;
    params.solver = name;
    auto estimate = [&](const essential_test::SyntheticScene& s, cv::Mat& mask) {
        return cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), params, mask);
    };
    std::vector<cv::Mat> seqE(data.size()), seqMask(data.size());
    for (size_t i = 0; i < data.size(); ++i)
        seqE[i] = estimate(data[i], seqMask[i]);

    std::atomic<bool> stop{false};
    std::atomic<int> swaps{0};
    std::thread registrar([&] {
        for (int i = 0; !stop; ++i, ++swaps)
            cv::essential::registerSolver(name, i % 2 ? first : second);
    });
    std::vector<cv::Mat> parE(data.size()), parMask(data.size());
    std::atomic<size_t> next{0};
    std::vector<std::thread> workers;
    for (int t = 0; t < 8; ++t)
        workers.emplace_back([&] {
            for (size_t i = next++; i < data.size(); i = next++)
                parE[i] = estimate(data[i], parMask[i]);
        });
    for (auto& w : workers)
        w.join();
    stop = true;
    registrar.join();
    EXPECT_GT(swaps.load(), 0);
    for (size_t i = 0; i < data.size(); ++i) {
        SCOPED_TRACE(i);
        ASSERT_FALSE(seqE[i].empty());
        EXPECT_TRUE(identical(seqE[i], parE[i]));
        EXPECT_TRUE(identical(seqMask[i], parMask[i]));
    }
}

} // namespace

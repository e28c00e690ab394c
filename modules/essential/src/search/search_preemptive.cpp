// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "sampling/sample_buffer.hpp"
#include "scoring/msac_score.hpp"
#include "search/search.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <vector>

namespace cv {
namespace essential {
namespace search {

namespace {

typedef std::chrono::steady_clock Clock;

double msBetween(Clock::time_point a, Clock::time_point b)
{
    return std::chrono::duration<double, std::milli>(b - a).count();
}

/** Hypotheses drawn before the run-time cost measurement that sizes M under a deadline. */
constexpr int kCalibrationHypotheses = 16;

} // namespace

Problem shuffledCopy(const Problem& problem, RNG& rng)
{
    const int n = problem.size();
    std::vector<int> order(static_cast<size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    for (int i = n - 1; i > 0; --i)
        std::swap(order[i], order[rng.uniform(0, i + 1)]);
    return subsetProblem(problem, order.data(), n);
}

SearchResult searchPreemptive(const Problem& problem, EssentialSolver& solver, RNG& rng,
                              const SearchSettings& settings)
{
    SearchResult result = beginSearch(solver, settings);
    const int n = problem.size();
    sampling::SampleBuffer buffer(solver, settings.sampleCheirality);
    if (n < buffer.sampleSize) return result;
    const int B = std::max(1, settings.preemptiveBlockSize);
    const Problem data = shuffledCopy(problem, rng);

    int M = settings.preemptiveHypotheses;
    const bool sizeFromDeadline = M <= 0 && settings.deadline.active;
    if (M <= 0) M = sizeFromDeadline ? kCalibrationHypotheses : kDefaultPreemptiveHypotheses;
    // Degenerate data may make every solver call fail; never try more than this many calls.
    long callCap = 50L * std::max(M, 1) + 1000L;

    std::vector<Matx33d> hypotheses;
    hypotheses.reserve(static_cast<size_t>(M));
    const Clock::time_point genStart = Clock::now();
    auto generate = [&](int target) {
        while (static_cast<int>(hypotheses.size()) < target &&
               result.hypothesesGenerated < callCap) {
            if ((result.hypothesesGenerated & 7) == 0 && settings.deadline.passed()) return;
            const int count = buffer.drawAndSolve(data, solver, rng);
            ++result.iterations;
            ++result.hypothesesGenerated;
            result.hypothesesConverged += count;
            for (int h = 0; h < count && static_cast<int>(hypotheses.size()) < target; ++h)
                hypotheses.push_back(buffer.solutions[h]);
        }
    };
    generate(M);

    if (sizeFromDeadline && !hypotheses.empty()) {
        // Cost model: generation costs tGen per hypothesis; scoring halves the survivors every B
        // points, so it scores about min(2 B, n) points per hypothesis at tPoint each.
        const double tGen = msBetween(genStart, Clock::now()) / hypotheses.size();
        const int probePoints = std::min(n, 4 * B);
        const Clock::time_point scoreStart = Clock::now();
        for (const Matx33d& E : hypotheses)
            result.pointsScored +=
                scoring::scoreMsacRange(E, data, settings.test, 0, probePoints).scored;
        const double tPoint =
            msBetween(scoreStart, Clock::now()) / (double(hypotheses.size()) * probePoints);
        const double perHypothesis = tGen + std::min(2.0 * B, double(n)) * tPoint;
        const double more = settings.deadline.remainingMs() / std::max(perHypothesis, 1e-6);
        M = static_cast<int>(std::min<double>(hypotheses.size() + std::max(0.0, more), 1e6));
        callCap = 50L * M + 1000L;
        hypotheses.reserve(static_cast<size_t>(M));
        generate(M);
    }
    M = static_cast<int>(hypotheses.size());
    if (M == 0) return result;

    // Breadth-first scoring: every survivor on the next block, then keep the best half.
    std::vector<double> cost(static_cast<size_t>(M), 0.0);
    std::vector<int> alive(static_cast<size_t>(M));
    std::iota(alive.begin(), alive.end(), 0);
    result.hypothesesScored = M;
    for (int begin = 0; begin < n && alive.size() > 1; begin += B) {
        const int end = std::min(n, begin + B);
        for (int h : alive)
            cost[h] += scoring::scoreMsacRange(hypotheses[h], data, settings.test, begin, end).cost;
        result.pointsScored += int64(end - begin) * int64(alive.size());
        const size_t keep = static_cast<size_t>(preemptiveSurvivors(M, end, B));
        if (alive.size() > keep) {
            std::nth_element(alive.begin(), alive.begin() + static_cast<long>(keep), alive.end(),
                             [&](int a, int b) { return cost[a] < cost[b]; });
            alive.resize(keep);
        }
        if (settings.deadline.passed()) break;
    }
    const int best = *std::min_element(alive.begin(), alive.end(),
                                       [&](int a, int b) { return cost[a] < cost[b]; });
    result.E = hypotheses[best];
    result.inliers = scoring::scoreMsac(result.E, problem, settings.test).inliers;
    result.found = result.inliers >= buffer.sampleSize;
    return result;
}

} // namespace search
} // namespace essential
} // namespace cv

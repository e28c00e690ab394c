// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "local_optimisation/local_optimisation.hpp"

#include "geometry/same_model.hpp"
#include "refine/irls_refinement.hpp"
#include "sampling/uniform_sampler.hpp"
#include "termination/termination.hpp"

#include <cmath>
#include <utility>

namespace cv {
namespace essential {
namespace local_optimisation {

namespace {

/** Inner sampling (LO-RANSAC's inner RANSAC): a new best model whose inlier ratio is below
kInnerMaxRatio is usually a model from a contaminated sample, close to the truth but off by more
than the threshold; minimal samples drawn among the points within kInnerThresholdFactor thresholds
of it are then mostly true inliers, and solving them often reaches the true model that the search's
uniform samples have not hit yet. */
constexpr double kInnerMaxRatio = 0.5;
constexpr double kInnerThresholdFactor = 3.0;
constexpr int kInnerSamples = 10;

/** Inner sampling waits until the search has drawn this many samples: at high inlier ratios the
first best models may be wrong roots with little support, and inner samples around them are wasted
(at 90% inliers, N = 500, they cost 20% of the call when run at once). By 50 samples a good sample
has been drawn with probability 0.997 at 70% inliers; a best model still below kInnerMaxRatio then
gets its inner samples. */
constexpr int kInnerMinSamples = 50;

} // namespace

LocalOptimisation::LocalOptimisation(const Problem& problem, EssentialSolver& solver,
                                     const LocalOptimisationSettings& settings,
                                     const scoring::Scorer& score, bool sampleCheirality,
                                     uint64 searchRngState, int minInliers)
    : problem_(problem), solver_(solver), settings_(settings), score_(score),
      minInliers_(minInliers), inner_(solver, sampleCheirality),
      innerRng_(searchRngState ^ 0x5851f42d4c957f2dULL)
{
    if (enabled()) {
        mask_.resize(static_cast<size_t>(problem.size()));
        chosen_.reserve(static_cast<size_t>(problem.size()));
    }
}

int LocalOptimisation::innerMinSamples()
{
    return kInnerMinSamples;
}

bool LocalOptimisation::improveBest(int samplesDrawn, RNG& rng, BestModel& best,
                                    LocalOptimisationCounters& counters)
{
    bool deferred = false;
    if (double(best.score.inliers) / problem_.size() < kInnerMaxRatio) {
        if (samplesDrawn >= kInnerMinSamples)
            innerSampling(best, counters);
        else
            deferred = true;
    }
    polish(best.E, rng, best, counters);
    return deferred;
}

void LocalOptimisation::polishRunnersUp(const CandidatePool& pool, RNG& rng, BestModel& best,
                                        LocalOptimisationCounters& counters)
{
    const Matx33d winner = geometry::unitNorm(best.E);
    for (int i = 0; i < pool.size(); ++i) {
        if (CandidatePool::same(pool[i].E, winner) ||
            !(pool[i].cost < CandidatePool::kCostFactor * best.score.cost))
            continue;
        polish(pool[i].E, rng, best, counters);
    }
}

void LocalOptimisation::innerSampling(BestModel& best, LocalOptimisationCounters& counters)
{
    const int n = problem_.size();
    const InlierTest test = score_.test;
    scoring::inlierMask(best.E, problem_,
                        test.withThreshold(kInnerThresholdFactor * test.threshold), mask_.data());
    chosen_.clear();
    for (int i = 0; i < n; ++i)
        if (mask_[i]) chosen_.push_back(i);
    const int pool = static_cast<int>(chosen_.size());
    if (pool < 2 * inner_.sampleSize) return;
    // kInnerSamples calls of a direct solver; an iterative one that solves a fraction s of clean
    // samples (at the best model's pose) gets kInnerSamples / s, as many expected hits.
    const int innerSamples =
        termination::sampleCap(kInnerSamples, solver_.hitProbabilityAt(1.0, best.E));
    for (int k = 0; k < innerSamples; ++k) {
        sampling::drawUniformSample(innerRng_, pool, inner_.sampleSize, inner_.indices.data());
        for (int i = 0; i < inner_.sampleSize; ++i) {
            inner_.x1[i] = problem_.point1(chosen_[inner_.indices[i]]);
            inner_.x2[i] = problem_.point2(chosen_[inner_.indices[i]]);
        }
        if (inner_.hasCoincidentPoints()) continue;
        const int count = inner_.keepSolved(
            solver_.solve(inner_.x1.data(), inner_.x2.data(), innerRng_, inner_.solutions.data()));
        ++counters.hypothesesGenerated;
        counters.hypothesesConverged += count;
        for (int h = 0; h < count; ++h) {
            const scoring::Score s = score_(inner_.solutions[h], best.score.cost);
            counters.pointsScored += s.scored;
            if (s.cost < best.score.cost && s.inliers >= minInliers_) {
                best.score = s;
                best.E = inner_.solutions[h];
            }
        }
    }
}

void LocalOptimisation::polish(const Matx33d& start, RNG& rng, BestModel& best,
                               LocalOptimisationCounters& counters)
{
    const int n = problem_.size();
    const InlierTest test = score_.test;
    scoring::inlierMask(start, problem_, test.withThreshold(settings_.band * test.threshold),
                        mask_.data());
    chosen_.clear();
    for (int i = 0; i < n; ++i)
        if (mask_[i]) chosen_.push_back(i);
    int k = static_cast<int>(chosen_.size());
    if (settings_.sampleSize > 0 && settings_.sampleSize < k) {
        for (int i = 0; i < settings_.sampleSize; ++i)
            std::swap(chosen_[i], chosen_[rng.uniform(i, k)]);
        k = settings_.sampleSize;
    }
    if (k < 5) return; // IRLS fits 5 degrees of freedom
    gatherProblem(problem_, chosen_.data(), k, subset_);
    refine::IrlsSettings irls;
    irls.maxIterations = settings_.iterations;
    ++counters.polishes;
    const refine::IrlsResult refined = refine::refineIrls(subset_, start, settings_.scale, irls);
    if (!refined.improved) return;
    const scoring::Score s = score_(refined.E, best.score.cost);
    counters.pointsScored += s.scored;
    if (s.cost < best.score.cost && s.inliers >= minInliers_) {
        best.score = s;
        best.E = refined.E;
        ++counters.polishesKept;
    }
}

} // namespace local_optimisation
} // namespace essential
} // namespace cv

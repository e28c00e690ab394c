// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "degeneracy/support_test.hpp"
#include "local_optimisation/candidate_pool.hpp"
#include "local_optimisation/local_optimisation.hpp"
#include "sampling/prosac_sampler.hpp"
#include "sampling/sample_buffer.hpp"
#include "sampling/uniform_sampler.hpp"
#include "scoring/msac_score.hpp"
#include "scoring/scorer.hpp"
#include "scoring/sprt.hpp"
#include "search/search.hpp"
#include "termination/basin_confirmation.hpp"
#include "termination/noise_adapted_ratio.hpp"
#include "termination/termination.hpp"

#include <cmath>
#include <memory>
#include <utility>
#include <vector>

namespace cv {
namespace essential {
namespace search {

namespace {

/** The SPRT's t_M: the time to generate the models of one sample in units of the time to check one
point. From essential_engines --part sprt at N = 1000 (SPRT on and off, the same samples): a
ratio near 3000 (docs/TUNING.md, "SPRT constants"). A depends on it only through
K = t_M C / m_S + 1 and A = K + log A: doubling it moves the rejection by about one point check. */
constexpr double kSprtHypothesisCost = 2500.0;

/** The SPRT's delta before any bad model was rejected: a random point lies within the threshold of
a wrong epipolar line with probability about 2 t / (image size), 0.002 to 0.005 for a 1 pixel
threshold; starting higher only makes the first tests more lenient. */
constexpr double kSprtInitialDelta = 0.01;

/** The confidence the stopping rule asks for in the extended budget (SearchSettings::minSampleCap)
once the best model's basin is confirmed (termination::BasinConfirmation; before, it asks that
class's kUnconfirmedConfidence): 1 - 1/e, one expected good sample at the best model's inlier ratio.
Measured on the synthetic protocol at N = 500 (perf suite): with the full confidence of 0.999 there,
the extension made 30% inliers 4.4 and 25% about 10 times slower (docs/TUNING.md, "Extended
confidence") for a reliability of 0.993 / 0.983 -> 1.000, where the hard sets (docs/HARD_PAIRS.md)
need the extension only when the best ratio is far lower. */
constexpr double kExtendedConfidence = 0.6321205588285577;

/** Every k-th point of `problem`, k the least step that leaves at most `count` of them. */
Problem stridedSubset(const Problem& problem, int count)
{
    const int n = problem.size();
    const int step = (n + count - 1) / count;
    std::vector<int> indices;
    for (int i = 0; i < n; i += step)
        indices.push_back(i);
    return subsetProblem(problem, indices.data(), static_cast<int>(indices.size()));
}

} // namespace

SearchResult searchMsac(const Problem& problem, EssentialSolver& solver, RNG& rng,
                        const SearchSettings& settings)
{
    SearchResult result = beginSearch(solver, settings);
    const int n = problem.size();
    sampling::SampleBuffer buffer(solver, settings.sampleCheirality);
    if (n < buffer.sampleSize) return result;
    // The sample cap: from the solver's rate at any pose until there is a model, then from its
    // rate at the model's pose (EssentialSolver::hitProbabilityAt).
    // settings.sampleLimit, when set, bounds it whatever the rule.
    auto limited = [&](int samples) {
        return settings.sampleLimit > 0 ? std::min(samples, settings.sampleLimit) : samples;
    };
    // The confidence cap at any pose (before there is a model): the first cap, PROSAC's T_N and
    // where the local samples of the extended budget begin.
    const int confidenceCap = termination::sampleCap(settings.maxIters, solver.successRate());
    int cap = limited(std::max(confidenceCap, settings.minSampleCap));

    // PROSAC: the samples follow the growth schedule with T_N = the confidence cap, so that the
    // pool covers every point by the time that cap is reached.
    std::unique_ptr<sampling::ProsacSampler> prosac;
    std::unique_ptr<sampling::ProsacTermination> prosacStop;
    if (settings.prosac) {
        // T_N from the confidence cap alone, not the OpenCV-time budget (settings.minSampleCap,
        // about 20 times larger): the pool then grows at the pace PROSAC's schedule was set for,
        // and past T_N the sampler is uniform for the rest of the budget.
        prosac.reset(new sampling::ProsacSampler(n, buffer.sampleSize, confidenceCap));
        prosacStop.reset(new sampling::ProsacTermination(n, buffer.sampleSize));
        buffer.prosac = prosac.get();
    }
    std::unique_ptr<sampling::NapsacSampler> napsac;
    if (settings.napsacEvery > 0) {
        napsac.reset(new sampling::NapsacSampler(problem, buffer.sampleSize));
        buffer.napsac = napsac.get();
        buffer.localEvery = settings.napsacEvery;
    }
    // SPRT checks the points in a random order (the data may be sorted, by PROSAC's quality or by
    // anything else): it scores a shuffled copy. Samples and local optimisation use `problem`.
    Problem shuffled;
    const Problem* scoringPoints = &problem;
    if (settings.sprt) {
        // Its own generator, seeded from the search's without advancing it: the samples are then
        // the same with and without SPRT.
        RNG shuffleRng(rng.state ^ 0x9e3779b97f4a7c15ULL);
        shuffled = shuffledCopy(problem, shuffleRng);
        scoringPoints = &shuffled;
    }
    scoring::Sprt sprt(kSprtHypothesisCost, kSprtInitialDelta);
    const scoring::Scorer score{scoringPoints, settings.test, settings.scoreInFront};
    local_optimisation::LocalOptimisation lo(problem, solver, settings.lo, score,
                                             settings.sampleCheirality, rng.state,
                                             buffer.sampleSize);
    std::vector<uchar> mask; // PROSAC's termination length
    if (prosac) mask.resize(static_cast<size_t>(n));
    local_optimisation::LocalOptimisationCounters loCounters;

    local_optimisation::BestModel best;
    local_optimisation::CandidatePool pool;
    // Until there is a model, the confidence cap: a search that has solved no sample by then has
    // degenerate data (coincident or collinear points), and the extended budget (settings.
    // minSampleCap) is only for data whose best model is weak, decided with the first model.
    int needed = std::min(cap, confidenceCap);

    bool innerPending = false; // the best model waits for its inner samples
    auto localOptimise = [&]() {
        innerPending = lo.improveBest(result.iterations, rng, best, loCounters);
        result.addWork(loCounters);
        loCounters = local_optimisation::LocalOptimisationCounters();
    };

    // The stopping rule for the current best model: the standard one on all points and, with
    // PROSAC, the least over the termination lengths n >= the current pool that pass PROSAC's
    // non-randomness test (every sample so far was drawn from the best n points, and the pool is
    // then held at the chosen length so that all further ones are too).
    //
    // The extension can only pay when the model it may find would pass the final support test: it
    // looks for models at inlier ratios the confidence cap has not covered, below
    // w_max = (1 / (s cap))^(1/m) (one expected good sample at the cap), so such a model has at
    // most w_max N inliers; when that is below the least significant count (the chance level of
    // the best model so far, with the whole budget's hypotheses), nothing the extension finds
    // could be accepted. That is small N: no-geometry data of a few dozen points would otherwise
    // draw 20 maxIters samples for nothing (the fuzzer's replay went from 20 s to 256 s under the
    // sanitizers). Decided once, for the best model when the question first arises.
    int extensionVerdict = -1; // -1 undecided, 0 no, 1 yes
    auto extensionCanPay = [&](int modelCap) {
        if (extensionVerdict >= 0) return extensionVerdict == 1;
        if (!result.found) return true; // nothing to judge by yet; decided with the first model
        const double s = std::max(1e-3, solver.hitProbabilityAt(1.0, best.E));
        const double wMax = std::min(1.0, std::pow(1.0 / (s * modelCap), 1.0 / buffer.sampleSize));
        const int inliersNeeded = degeneracy::significantInliers(
            best.E, problem, settings.test, buffer.sampleSize, std::max(cap, 1));
        extensionVerdict = inliersNeeded >= 0 && wMax * n >= inliersNeeded ? 1 : 0;
        return extensionVerdict == 1;
    };
    // The confidence cap at the best model's pose (the solver's rate there).
    auto confidenceCapAtBest = [&]() {
        return termination::sampleCap(settings.maxIters, solver.hitProbabilityAt(1.0, best.E));
    };
    // Past the confidence cap (the extended budget of settings.minSampleCap) the rule asks only for
    // kExtendedConfidence: the extension is there for data whose best model so far is so weakly
    // supported that the cap does not even buy one expected good sample at its inlier ratio (a
    // wrong model on hard data, or none), not for raising 0.9 to 0.999 at a moderate ratio. Until
    // the best model's basin has been drawn again (`basin`), it asks more: a model seen once on
    // such data is as likely a wrong one.
    termination::BasinConfirmation basin;
    // The best model's noise-adapted inlier ratio (termination::NoiseAdaptedRatio), computed only
    // when the stopping rule would extend the budget, once per best model, on at most
    // NoiseAdaptedRatio::kMaxPoints of the points (every k-th, copied on first use).
    Problem bandSubset;
    Matx33d adaptedFor = Matx33d::zeros();
    double adaptedRatio = 0.0;
    auto noiseAdaptedRatio = [&]() {
        if (best.E == adaptedFor) return adaptedRatio;
        const Problem* points = &problem;
        if (n > termination::NoiseAdaptedRatio::kMaxPoints) {
            if (bandSubset.size() == 0)
                bandSubset = stridedSubset(problem, termination::NoiseAdaptedRatio::kMaxPoints);
            points = &bandSubset;
        }
        int bands[termination::NoiseAdaptedRatio::kBands];
        scoring::distanceBands(best.E, *points, settings.test,
                               termination::NoiseAdaptedRatio::kBands, bands);
        adaptedRatio = termination::NoiseAdaptedRatio::ratio(bands, points->size(),
                                                             double(best.score.inliers) / n);
        adaptedFor = best.E;
        return adaptedRatio;
    };
    // `wholeSet`: the ratio is the best model's on all points (not one of PROSAC's lengths).
    auto stopRule = [&](double inlierRatio, bool wholeSet) {
        auto rule = [&](double ratio, double confidence) {
            const double p = solver.hitProbabilityAt(ratio, best.E);
            return settings.sprt ? sprt.samplesNeeded(p, confidence, cap)
                                 : termination::requiredIterations(confidence, p, cap);
        };
        const int need = rule(inlierRatio, settings.confidence);
        const int modelCap = confidenceCapAtBest();
        if (settings.minSampleCap <= modelCap || need <= modelCap) return need;
        // The rule would extend the budget: first ask whether the ratio is low only because the
        // threshold lies below the noise, where the correct matches' ratio (at least the apparent
        // one) is the one to sample for.
        const double adapted =
            wholeSet && settings.noiseAdaptedStop ? noiseAdaptedRatio() : inlierRatio;
        if (adapted > inlierRatio) {
            const int adaptedNeed = rule(adapted, settings.confidence);
            if (adaptedNeed <= modelCap) return adaptedNeed;
        }
        if (!extensionCanPay(modelCap)) return modelCap;
        // The extension reads that ratio too, but only once the best model's basin is confirmed:
        // a model off by its own error spreads its correct matches over the bands as noise does,
        // and a model drawn once may be such a one (docs/TUNING.md, "Noise-adapted stop").
        const double extensionRatio = basin.confirmed() ? adapted : inlierRatio;
        return std::max(
            modelCap,
            std::min(need, rule(extensionRatio, basin.extendedConfidence(kExtendedConfidence,
                                                                         settings.confidence))));
    };
    auto samplesNeeded = [&]() {
        cap = limited(std::max(confidenceCapAtBest(), settings.minSampleCap));
        int need = stopRule(double(best.score.inliers) / n, true);
        if (!prosac || prosac->isUniform()) return need;
        scoring::inlierMask(best.E, problem, settings.test, mask.data());
        const int from = std::max(prosac->poolSize(), prosacStop->minLength());
        int length = n, inliers = 0;
        for (int k = 0; k < n - 1; ++k) {
            inliers += mask[k];
            const int len = k + 1;
            if (len < from || !mask[k] || inliers < prosacStop->minInliers(len)) continue;
            // A PROSAC length is never the whole set (k < n - 1).
            const int k_n = stopRule(double(inliers) / len, false);
            if (k_n < need) {
                need = k_n;
                length = len;
            }
        }
        prosac->setTerminationLength(length);
        return need;
    };

    // Local samples in the extended budget: once the confidence cap is passed (the data are hard:
    // the stopping rule has not been met), every other sample is spatially local, built here so
    // that easy calls never pay for the grid.
    while (result.iterations < needed) {
        if ((result.iterations & 7) == 7 && settings.deadline.passed()) break;
        if (settings.localSamplesInBudget && !napsac && result.iterations >= confidenceCap) {
            napsac.reset(new sampling::NapsacSampler(problem, buffer.sampleSize));
            buffer.napsac = napsac.get();
            buffer.localEvery = 2;
        }
        if (innerPending &&
            result.iterations >= local_optimisation::LocalOptimisation::innerMinSamples()) {
            localOptimise();
            if (settings.sprt)
                sprt.accepted(double(best.score.inliers) / n,
                              double(result.hypothesesConverged) / result.hypothesesGenerated);
            needed = samplesNeeded();
            if (result.iterations >= needed) break;
        }
        ++result.iterations;
        if (settings.sprt) sprt.sampleDrawn();
        const int count = buffer.drawAndSolve(problem, solver, rng);
        ++result.hypothesesGenerated;
        result.hypothesesConverged += count;
        for (int h = 0; h < count; ++h) {
            ++result.hypothesesScored;
            scoring::Score s;
            // Scored exactly up to the pool's entry cost (within CandidatePool::kCostFactor of the
            // best), so that near-best models of another basin are kept (CandidatePool).
            const double bound =
                lo.enabled()
                    ? std::min(pool.entryCost(),
                               local_optimisation::CandidatePool::kCostFactor * best.score.cost)
                    : best.score.cost;
            if (sprt.active()) {
                bool rejected = false;
                s = scoring::scoreMsacSprt(buffer.solutions[h], *scoringPoints, settings.test,
                                           bound, sprt.test(), rejected);
                result.pointsScored += s.scored;
                if (rejected) {
                    ++result.sprtRejections;
                    if (sprt.rejected(s.inliers, s.scored) && result.found)
                        needed = samplesNeeded();
                    continue;
                }
            } else {
                s = score(buffer.solutions[h], bound);
                result.pointsScored += s.scored;
            }
            if (lo.enabled() && s.cost < bound && s.inliers >= buffer.sampleSize)
                pool.offer(buffer.solutions[h], s.cost);
            // Scored exactly (below the bound): a draw of the best model's basin or not.
            bool sameBasin = false;
            if (result.found && s.cost < bound) {
                const bool wasConfirmed = basin.confirmed();
                sameBasin = basin.offer(buffer.solutions[h], best.E);
                if (!wasConfirmed && basin.confirmed()) needed = samplesNeeded();
            }
            if (s.cost < best.score.cost && s.inliers >= buffer.sampleSize) {
                if (!sameBasin) basin.newBasin();
                best.score = s;
                best.E = buffer.solutions[h];
                result.found = true;
                if (lo.enabled()) localOptimise();
                if (settings.sprt)
                    sprt.accepted(double(best.score.inliers) / n,
                                  double(result.hypothesesConverged) / result.hypothesesGenerated);
                needed = samplesNeeded();
            }
        }
    }
    // The runners-up of other basins, polished: one may descend below the winner.
    if (lo.enabled() && result.found) {
        lo.polishRunnersUp(pool, rng, best, loCounters);
        result.addWork(loCounters);
        loCounters = local_optimisation::LocalOptimisationCounters();
    }
    result.E = best.E;
    result.inliers = best.score.inliers;
    return result;
}

} // namespace search
} // namespace essential
} // namespace cv

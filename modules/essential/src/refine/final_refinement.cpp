// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "refine/final_refinement.hpp"

#include "pose/pose_recovery.hpp"
#include "scoring/msac_score.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace cv {
namespace essential {
namespace refine {

namespace {

/** IRLS fits the five degrees of freedom of E: fewer points leave it undetermined. */
constexpr int kMinPoints = 5;

/** 1 / Phi^-1(3/4): the median of |s| for s ~ N(0, sigma^2) is sigma / this. */
constexpr double kMadToSigma = 1.4826;

} // namespace

double estimateNoise(const Problem& problem, const Matx33d& E, double threshold, double window,
                     int minPoints)
{
    const int n = problem.size();
    // Written in full by sampsonErrors: no zeroing first.
    std::vector<double, UninitialisedAllocator<double>> squared(static_cast<size_t>(n));
    scoring::sampsonErrors(E, problem, squared.data());
    const double limit = window * window * threshold * threshold;
    size_t kept = 0;
    for (int i = 0; i < n; ++i)
        if (squared[i] <= limit) squared[kept++] = squared[i]; // NaN (no distance) is dropped
    if (static_cast<int>(kept) < minPoints) return 0.0;
    const size_t middle = kept / 2;
    std::nth_element(squared.begin(), squared.begin() + middle, squared.begin() + kept);
    return kMadToSigma * std::sqrt(squared[middle]);
}

FinalRefinementResult refineFinal(const Problem& problem, const Matx33d& E0, InlierTest test,
                                  const FinalRefinementSettings& settings)
{
    const double threshold = test.threshold;
    FinalRefinementResult result;
    result.E = E0;
    const int n = problem.size();
    auto noiseAt = [&](const Matx33d& E) {
        double sigma = 0.0;
        if (settings.noiseWindow > 0.0)
            sigma =
                estimateNoise(problem, E, threshold, settings.noiseWindow, settings.minNoisePoints);
        return sigma > 0.0 ? sigma : settings.assumedNoise * threshold;
    };
    std::vector<uchar> use(static_cast<size_t>(n)), inFront(static_cast<size_t>(n));
    Matx33d E = E0;
    double sigma = noiseAt(E);
    for (int round = 0; round < settings.maxRounds; ++round) {
        result.noise = sigma;
        const bool tukey = round >= settings.firstTukeyRound && settings.tukeyInSigmas > 0.0;
        const double scale =
            tukey ? std::max(settings.tukeyInSigmas * sigma, settings.minTukeyScale * threshold)
                  : std::max(settings.minScale * threshold, settings.scaleInSigmas * sigma);
        double band = std::max(settings.minBand * threshold, settings.bandInSigmas * sigma);
        if (tukey) band = std::max(band, scale);
        IrlsSettings irls = settings.irls;
        irls.loss = tukey ? RobustLoss::Tukey : RobustLoss::Cauchy;
        int count = scoring::inlierMask(E, problem, test.withThreshold(band), use.data());
        if (settings.inFrontOnly && count >= kMinPoints) {
            // An E with no decomposition (it cannot happen for a search winner, which has one)
            // keeps the band's points.
            pose::PoseResult pose;
            if (pose::recoverPoseNormalised(E, problem, use.data(), inFront.data(), pose)) {
                use.swap(inFront);
                count = pose.inFront;
            }
        }
        if (count < kMinPoints) break;
        const Problem selected = maskedProblem(problem, use.data());
        const IrlsResult refined = refineIrls(selected, E, scale, irls);
        result.iterations += refined.iterations;
        result.pointsUsed = count;
        ++result.rounds;
        // A round that cannot improve (the start is already the minimum of its loss, as after a
        // local optimisation with the same loss) still leaves the next round its own loss.
        if (refined.improved) {
            E = refined.E;
            result.improved = true;
        }
        if (round + 1 == settings.maxRounds) break;
        // Another round only if the noise around the result is clearly below the noise the round
        // was set up with: the start was off, and its band and scale were too wide.
        const double next = noiseAt(E);
        if (!(next < settings.nextRoundBelow * sigma)) break;
        sigma = next;
    }
    result.E = E;
    return result;
}

} // namespace refine
} // namespace essential
} // namespace cv

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "sampling/prosac_sampler.hpp"
#include "sampling/sample_buffer.hpp"
#include "scoring/msac_score.hpp"
#include "search/search.hpp"
#include "termination/termination.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace cv {
namespace essential {
namespace search {

namespace {

/** OpenCV 4.6's floor on the LMedS threshold, in normalised units. */
constexpr double kLmedsMinThreshold = 0.001;

/** Squared medians below this (errors under 1e-6 normalised units, a thousandth of the threshold
floor) are the same fit: round-off. It matters on noise-free data with N <= 9, where any solution of
a sample fits its five points exactly and so has a median of zero, right or wrong: OpenCV's own
accuracy test (Calib3d_FindEssentialMat) draws such problems (N = 6 and 9 among them), and a wrong
root there left five inliers. Ties at this level go to the model that fits more points to round-off:
the true E fits all of them, a wrong root its sample. */
constexpr double kTiedMedian = 1e-12;

} // namespace

SearchResult searchLmeds(const Problem& problem, EssentialSolver& solver, RNG& rng,
                         const SearchSettings& settings)
{
    SearchResult result;
    const int n = problem.size();
    // No setThreshold(): LMedS has no inlier threshold of its own (it derives one from the data).
    sampling::SampleBuffer buffer(solver, settings.sampleCheirality);
    if (n < buffer.sampleSize) return result;

    // OpenCV's LMeDS assumes 45% outliers to fix the number of samples (at least 3).
    const double assumedInlierRatio = 0.55;
    const int samples =
        std::max(3, termination::requiredIterations(
                        settings.confidence, solver.hitProbability(assumedInlierRatio),
                        termination::sampleCap(settings.maxIters, solver.successRate())));
    // PROSAC: its growth schedule over the fixed number of samples (LMedS has no adaptive stopping
    // rule, so PROSAC only changes the order in which the points are tried).
    std::unique_ptr<sampling::ProsacSampler> prosac;
    if (settings.prosac) {
        prosac.reset(new sampling::ProsacSampler(n, buffer.sampleSize, samples));
        buffer.prosac = prosac.get();
    }
    std::vector<double> errors(static_cast<size_t>(n));
    double bestMedian = HUGE_VAL;
    int bestExact = 0;
    for (; result.iterations < samples; ++result.iterations) {
        if ((result.iterations & 7) == 7 && settings.deadline.passed()) break;
        const int count = buffer.drawAndSolve(problem, solver, rng);
        ++result.hypothesesGenerated;
        result.hypothesesConverged += count;
        for (int h = 0; h < count; ++h) {
            ++result.hypothesesScored;
            result.pointsScored += n;
            scoring::sampsonErrors(buffer.solutions[h], problem, errors.data());
            for (double& e : errors)
                if (std::isnan(e)) e = HUGE_VAL;
            std::nth_element(errors.begin(), errors.begin() + n / 2, errors.end());
            const double median = std::max(errors[static_cast<size_t>(n / 2)], kTiedMedian);
            if (median > bestMedian) continue;
            // Ties at the round-off level are broken by how many points fit to round-off (counted
            // only for a model that may win).
            int exact = 0;
            for (double e : errors)
                exact += e <= kTiedMedian;
            if (median == bestMedian && exact <= bestExact) continue;
            bestMedian = median;
            bestExact = exact;
            result.E = buffer.solutions[h];
            result.found = true;
        }
    }
    if (!result.found) return result;
    // Rousseeuw's robust standard deviation from the median, with the finite-sample correction
    // 1 + 5 / (n - p), p the sample size, and OpenCV's 2.5 sigma cut. With n == p (a solver whose
    // sample is every point, e.g. robust on 10 points) the correction is undefined; it is taken at
    // its largest finite value, that of n - p = 1.
    const int surplus = std::max(1, n - buffer.sampleSize);
    const double sigma = 2.5 * 1.4826 * (1.0 + 5.0 / surplus) * std::sqrt(bestMedian);
    // As cv::findEssentialMat's LMedS (ptsetreg.cpp): the threshold is never below 0.001
    // normalised units (half a pixel at f = 500), so that a near-perfect fit on noise-free data
    // does not leave a threshold at the round-off level that rejects true inliers.
    result.threshold = std::max(sigma, kLmedsMinThreshold);
    std::vector<uchar> mask(static_cast<size_t>(n));
    result.inliers = scoring::inlierMask(
        result.E, problem, settings.test.withThreshold(result.threshold), mask.data());
    return result;
}

} // namespace search
} // namespace essential
} // namespace cv

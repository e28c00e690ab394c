// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "degeneracy/support_test.hpp"

#include "geometry/sampson.hpp"
#include "geometry/symmetric_epipolar.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace cv {
namespace essential {
namespace degeneracy {

namespace {

/** Shifts used to build wrong pairs, as fractions of N: q1[i] is paired with q2[i + f N]. Fractions
rather than small constant offsets because callers often pass correspondences sorted by image
position (detectors that scan rows, grids) or by match quality: a small shift would pair each point
with a neighbour in that order, which in a position-sorted set is nearly its true partner, and the
rate would come out too high. 0.382 and 0.618 (golden-ratio offsets) and 0.5 keep every wrong pair
at least a third of the data apart in the input order. 3 x N wrong pairs give the rate to about
+-sqrt(p / 3N). */
constexpr double kShiftFractions[] = {0.382, 0.5, 0.618};

/** Significance level of the test before the Bonferroni division by the number of hypotheses. */
constexpr double kAlpha = 0.01;

/** Smallest m with P(Poisson(lambda) >= m) <= level. */
int poissonQuantile(double lambda, double level)
{
    double pmf = std::exp(-lambda); // P(X = 0)
    double tail = 1.0;              // P(X >= 0)
    int m = 0;
    while (tail > level && m < 100000) {
        tail -= pmf; // now P(X >= m + 1)
        ++m;
        pmf *= lambda / m;
    }
    return m;
}

} // namespace

double chanceInlierRate(const Matx33d& E, const Problem& problem, InlierTest test)
{
    const int n = problem.size();
    if (n < 2) return 0.0;
    const geometry::EssentialEntries e(E);
    const bool symmetric = test.distance == DISTANCE_SYMMETRIC_EPIPOLAR;
    const double t2 = test.threshold * test.threshold;
    long hits = 0, pairs = 0;
    for (double fraction : kShiftFractions) {
        const int s = static_cast<int>(fraction * n) % n;
        if (s == 0) continue;
        for (int i = 0; i < n; ++i) {
            const int j = (i + s) % n;
            // The wrong pair is judged by the same distance as the inliers it is compared with.
            const geometry::SampsonTerms terms = geometry::sampsonTerms(
                e, problem.x1[i], problem.y1[i], problem.x2[j], problem.y2[j]);
            const double d2 = symmetric ? geometry::symmetricEpipolarSquared(terms)
                                        : geometry::sampsonSquared(terms);
            hits += d2 <= t2;
            ++pairs;
        }
    }
    // One pseudo-hit keeps the rate positive when no wrong pair happened to fit.
    return (hits + 1.0) / (pairs + 1.0);
}

int significantInliers(const Matx33d& E, const Problem& problem, InlierTest test, int sampleSize,
                       int hypotheses)
{
    const int n = problem.size();
    const int others = n - sampleSize;
    if (others <= 0) return -1;
    const double lambda = others * chanceInlierRate(E, problem, test);
    const int needed = poissonQuantile(lambda, kAlpha / std::max(1, hypotheses));
    if (needed > others) return -1; // no power: cannot tell luck from geometry
    return sampleSize + needed;
}

bool supportIsSignificant(const Matx33d& E, const Problem& problem, InlierTest test, int inliers,
                          int sampleSize, int hypotheses)
{
    const int needed = significantInliers(E, problem, test, sampleSize, hypotheses);
    return needed < 0 || inliers >= needed;
}

bool moreDistinctInliersThan(const Problem& problem, const std::vector<uchar>& mask, int count)
{
    std::array<size_t, kMinimalSample + 1> distinct{};
    int found = 0;
    for (size_t i = 0; i < mask.size(); ++i) {
        if (!mask[i]) continue;
        bool repeated = false;
        for (int k = 0; k < found && !repeated; ++k) {
            const size_t j = distinct[static_cast<size_t>(k)];
            repeated = problem.x1[i] == problem.x1[j] && problem.y1[i] == problem.y1[j] &&
                       problem.x2[i] == problem.x2[j] && problem.y2[i] == problem.y2[j];
        }
        if (repeated) continue;
        distinct[static_cast<size_t>(found++)] = i;
        if (found > count) return true;
    }
    return false;
}

} // namespace degeneracy
} // namespace essential
} // namespace cv

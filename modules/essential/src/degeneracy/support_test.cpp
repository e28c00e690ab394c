// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "degeneracy/support_test.hpp"

#include "geometry/sampson.hpp"
#include "geometry/symmetric_epipolar.hpp"
#include "simd_dispatch.hpp"

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

/** How many of the count pairs (x1[i], y1[i]; x2[i], y2[i]) pass the inlier test: a loop with no
wrap-around index and no branch, which the compiler vectorises in each clone. */
ESSENTIAL_SIMD_CLONES long pairHits(const geometry::EssentialEntries& e, const double* x1,
                                    const double* y1, const double* x2, const double* y2, int count,
                                    bool symmetric, double t2)
{
    long hits = 0;
    if (symmetric) {
        for (int i = 0; i < count; ++i)
            hits += geometry::symmetricEpipolarSquared(
                        geometry::sampsonTerms(e, x1[i], y1[i], x2[i], y2[i])) <= t2;
    } else {
        for (int i = 0; i < count; ++i)
            hits += geometry::sampsonSquared(
                        geometry::sampsonTerms(e, x1[i], y1[i], x2[i], y2[i])) <= t2;
    }
    return hits;
}

} // namespace

double chanceInlierRate(const Matx33d& E, const Problem& problem, InlierTest test)
{
    const int n = problem.size();
    if (n < 2) return 0.0;
    const geometry::EssentialEntries e(E);
    // The wrong pair is judged by the same distance as the inliers it is compared with.
    const bool symmetric = test.distance == DISTANCE_SYMMETRIC_EPIPOLAR;
    const double t2 = test.threshold * test.threshold;
    long hits = 0, pairs = 0;
    for (double fraction : kShiftFractions) {
        const int s = static_cast<int>(fraction * n) % n;
        if (s == 0) continue;
        // q1[i] with q2[(i + s) mod n]: q2[i + s] up to n - s, then q2[i + s - n].
        const double *x1 = problem.x1.data(), *y1 = problem.y1.data();
        const double *x2 = problem.x2.data(), *y2 = problem.y2.data();
        hits += pairHits(e, x1, y1, x2 + s, y2 + s, n - s, symmetric, t2);
        hits += pairHits(e, x1 + (n - s), y1 + (n - s), x2, y2, s, symmetric, t2);
        pairs += n;
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

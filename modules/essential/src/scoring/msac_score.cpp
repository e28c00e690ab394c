// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "scoring/msac_score.hpp"

#include "geometry/sampson.hpp"
#include "geometry/symmetric_epipolar.hpp"
#include "simd_dispatch.hpp"

#include <algorithm>
#include <cmath>

namespace cv {
namespace essential {
namespace scoring {

namespace {

/** Squared inlier distances of points [begin, end) written to err: the Sampson distance
(geometry/sampson.hpp) or the symmetric epipolar distance (geometry/symmetric_epipolar.hpp), as the
problem says. The choice is made once per block, outside the loops; each loop runs over plain
arrays with the nine entries of E in registers, and the compiler vectorises it (two doubles per
SSE2 register, four with AVX). A point on the epipoles gives NaN or +inf, which never passes the
`<=` tests below, so it counts as an outlier at full truncated cost. */
inline void distanceBlock(const Matx33d& E, const Problem& problem, EssentialDistance distance,
                          int begin, int end, double* err)
{
    const geometry::EssentialEntries e(E);
    const double* x1 = problem.x1.data();
    const double* y1 = problem.y1.data();
    const double* x2 = problem.x2.data();
    const double* y2 = problem.y2.data();
    if (distance == DISTANCE_SYMMETRIC_EPIPOLAR) {
        for (int i = begin; i < end; ++i)
            err[i - begin] = geometry::symmetricEpipolarSquared(e, x1[i], y1[i], x2[i], y2[i]);
    } else {
        for (int i = begin; i < end; ++i)
            err[i - begin] = geometry::sampsonSquared(e, x1[i], y1[i], x2[i], y2[i]);
    }
}

/** Block length of the partial scoring: long enough to vectorise and amortise the early-exit test,
short enough that a losing hypothesis stops early and that the buffer stays on the stack. */
constexpr int kBlock = 64;

} // namespace

Score scoreMsac(const Matx33d& E, const Problem& problem, InlierTest test, double bestCost)
{
    return scoreMsacRange(E, problem, test, 0, problem.size(), bestCost);
}

ESSENTIAL_SIMD_CLONES Score scoreMsacRange(const Matx33d& E, const Problem& problem,
                                           InlierTest test, int first, int last, double bestCost)
{
    const double t2 = test.threshold * test.threshold;
    Score s;
    s.cost = 0.0;
    double err[kBlock];
    for (int begin = first; begin < last; begin += kBlock) {
        const int end = std::min(last, begin + kBlock);
        distanceBlock(E, problem, test.distance, begin, end, err);
        double cost = 0.0;
        int inliers = 0;
        for (int i = 0; i < end - begin; ++i) {
            const bool in = err[i] <= t2;
            cost += in ? err[i] : t2;
            inliers += in;
        }
        s.cost += cost;
        s.inliers += inliers;
        s.scored += end - begin;
        if (s.cost >= bestCost) return s;
    }
    return s;
}

/** Block length of the SPRT scoring: the test usually rejects a bad hypothesis after 10 to 20
points, so shorter blocks than kBlock waste less of the vectorised distance computation. */
constexpr int kSprtBlock = 16;

ESSENTIAL_SIMD_CLONES Score scoreMsacSprt(const Matx33d& E, const Problem& problem, InlierTest test,
                                          double bestCost, const SprtTest& sprt, bool& rejected)
{
    const double t2 = test.threshold * test.threshold;
    const int n = problem.size();
    Score s;
    s.cost = 0.0;
    rejected = false;
    double logLambda = 0.0;
    double err[kSprtBlock];
    for (int begin = 0; begin < n; begin += kSprtBlock) {
        const int end = std::min(n, begin + kSprtBlock);
        distanceBlock(E, problem, test.distance, begin, end, err);
        for (int i = 0; i < end - begin; ++i) {
            const bool in = err[i] <= t2;
            s.cost += in ? err[i] : t2;
            s.inliers += in;
            logLambda += in ? sprt.logIn : sprt.logOut;
            if (logLambda > sprt.logA) {
                s.scored = begin + i + 1;
                rejected = true;
                return s;
            }
        }
        s.scored = end;
        if (s.cost >= bestCost) return s;
    }
    return s;
}

ESSENTIAL_SIMD_CLONES void sampsonErrors(const Matx33d& E, const Problem& problem, double* errors)
{
    const geometry::EssentialEntries e(E);
    for (int i = 0; i < problem.size(); ++i)
        errors[i] =
            geometry::sampsonSquared(e, problem.x1[i], problem.y1[i], problem.x2[i], problem.y2[i]);
}

ESSENTIAL_SIMD_CLONES void squaredDistances(const Matx33d& E, const Problem& problem,
                                            InlierTest test, double* errors)
{
    distanceBlock(E, problem, test.distance, 0, problem.size(), errors);
}

ESSENTIAL_SIMD_CLONES void distanceBands(const Matx33d& E, const Problem& problem, InlierTest test,
                                         int bands, int* counts)
{
    for (int k = 0; k < bands; ++k)
        counts[k] = 0;
    const int n = problem.size();
    const double inverse = 1.0 / test.threshold;
    double err[kBlock];
    for (int begin = 0; begin < n; begin += kBlock) {
        const int end = std::min(n, begin + kBlock);
        distanceBlock(E, problem, test.distance, begin, end, err);
        for (int i = 0; i < end - begin; ++i) {
            // A distance of exactly k thresholds belongs to band k - 1, as an inlier (<= t) to 0.
            const double d = std::sqrt(err[i]) * inverse;
            const double band = std::ceil(d) - 1.0;
            if (band < bands) ++counts[band < 0.0 ? 0 : static_cast<int>(band)];
        }
    }
}

ESSENTIAL_SIMD_CLONES int inlierMask(const Matx33d& E, const Problem& problem, InlierTest test,
                                     uchar* mask)
{
    const int n = problem.size();
    const double t2 = test.threshold * test.threshold;
    double err[kBlock];
    int count = 0;
    for (int begin = 0; begin < n; begin += kBlock) {
        const int end = std::min(n, begin + kBlock);
        distanceBlock(E, problem, test.distance, begin, end, err);
        for (int i = 0; i < end - begin; ++i) {
            const bool in = err[i] <= t2;
            mask[begin + i] = in ? 1 : 0;
            count += in;
        }
    }
    return count;
}

} // namespace scoring
} // namespace essential
} // namespace cv

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Where the iterative minimal solvers (gn, lm) start when R = I did not work: a fixed set of
// rotations up to 75 degrees, ranked per sample by how nearly they make the sample's epipolar
// planes share one translation.

#ifndef OPENCV_ESSENTIAL_SOLVERS_START_ROTATIONS_HPP
#define OPENCV_ESSENTIAL_SOLVERS_START_ROTATIONS_HPP

#include "geometry/so3.hpp"
#include "simd_dispatch.hpp"

#include <opencv2/core.hpp>

#include <array>
#include <cmath>

namespace cv {
namespace essential {
namespace solvers {

/** Candidate start rotations: the 12 icosahedral directions as rotation axes, each at 25, 50 and
75 degrees (36 rotations; R = I, the first start, is not among them). Shells at 30 / 60 / 90 and
40 / 80 degrees, and random sets of 30 rotations up to 60, 90 or 180 degrees, gave lower rates
beyond 45 degrees in exploratory runs (docs/SOLVERS.md, "Success rate by rotation"). */
class StartRotations
{
public:
    static constexpr int kCount = 36;

    static const StartRotations& instance()
    {
        static const StartRotations rotations; // thread-safe initialisation (C++11)
        return rotations;
    }

    const Eigen::Matrix3d& operator[](int i) const { return rotations_[static_cast<size_t>(i)]; }
    /** Entry (row, col) of every rotation, contiguous: entry(row, col)[i] = (*this)[i](row, col).
    The layout lets the per-sample ranking run over all rotations at once in vector registers. */
    const double* entry(int row, int col) const { return entries_[3 * row + col].data(); }

private:
    StartRotations()
    {
        const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
        std::array<Eigen::Vector3d, 12> axes;
        int k = 0;
        for (double s1 : {-1.0, 1.0})
            for (double s2 : {-1.0, 1.0}) {
                axes[static_cast<size_t>(k++)] = Eigen::Vector3d(0.0, s1, s2 * phi).normalized();
                axes[static_cast<size_t>(k++)] = Eigen::Vector3d(s1, s2 * phi, 0.0).normalized();
                axes[static_cast<size_t>(k++)] = Eigen::Vector3d(s2 * phi, 0.0, s1).normalized();
            }
        k = 0;
        for (double degrees : {25.0, 50.0, 75.0})
            for (const Eigen::Vector3d& axis : axes)
                rotations_[static_cast<size_t>(k++)] =
                    geometry::expSO3(axis * degrees * CV_PI / 180.0);
        for (int i = 0; i < kCount; ++i)
            for (int e = 0; e < 9; ++e)
                entries_[static_cast<size_t>(e)][static_cast<size_t>(i)] =
                    rotations_[static_cast<size_t>(i)](e / 3, e % 3);
    }

    std::array<Eigen::Matrix3d, kCount> rotations_;
    alignas(32) std::array<std::array<double, kCount>, 9> entries_;
};

/** How far the rotation R is from explaining the sample with some translation: with c_i the unit
normal of the plane through t that (R q1_i, q2_i) must span, c_i = (R q1_i x q2_i) / |...|, the
true R makes the c_i coplanar (all orthogonal to t), so det(sum c_i c_i^T) is zero there. Unit
normals weigh every point alike. Ranking by the smallest eigenvalue instead, or by its ratio to
the middle one, chose worse starts (docs/SOLVERS.md). Scalar code on the six distinct entries of
the sum: it runs 36 times per call that needs extra starts. */
inline double coplanarityCost(const Eigen::Matrix3d& R, const Point2d* x1, const Point2d* x2, int n)
{
    double s00 = 0, s01 = 0, s02 = 0, s11 = 0, s12 = 0, s22 = 0;
    for (int i = 0; i < n; ++i) {
        const double u = x1[i].x, v = x1[i].y, x = x2[i].x, y = x2[i].y;
        const double a0 = R(0, 0) * u + R(0, 1) * v + R(0, 2);
        const double a1 = R(1, 0) * u + R(1, 1) * v + R(1, 2);
        const double a2 = R(2, 0) * u + R(2, 1) * v + R(2, 2);
        // c = a x (x, y, 1)
        const double c0 = a1 - a2 * y, c1 = a2 * x - a0, c2 = a0 * y - a1 * x;
        const double norm2 = c0 * c0 + c1 * c1 + c2 * c2;
        if (!(norm2 > 0.0)) continue;
        const double w = 1.0 / norm2;
        s00 += w * c0 * c0;
        s01 += w * c0 * c1;
        s02 += w * c0 * c2;
        s11 += w * c1 * c1;
        s12 += w * c1 * c2;
        s22 += w * c2 * c2;
    }
    return s00 * (s11 * s22 - s12 * s12) - s01 * (s01 * s22 - s12 * s02) +
           s02 * (s01 * s12 - s11 * s02);
}

/** The coplanarity costs of all StartRotations on a sample of N points: costs[i] is exactly
coplanarityCost(StartRotations::instance()[i], x1, x2, N), the same operations in the same order
(test_solvers checks the equality bit for bit), computed point by point over all rotations at once
so that the compiler keeps the rotations' sums in vector registers. A point whose normal has no
length adds nothing, as there (the input is finite: the module refuses non-finite points). */
template <int N>
ESSENTIAL_INLINE_INTO_CLONES void coplanarityCosts(const Point2d* x1, const Point2d* x2,
                                                   double costs[StartRotations::kCount])
{
    constexpr int K = StartRotations::kCount;
    const StartRotations& rotations = StartRotations::instance();
    const double *r00 = rotations.entry(0, 0), *r01 = rotations.entry(0, 1),
                 *r02 = rotations.entry(0, 2), *r10 = rotations.entry(1, 0),
                 *r11 = rotations.entry(1, 1), *r12 = rotations.entry(1, 2),
                 *r20 = rotations.entry(2, 0), *r21 = rotations.entry(2, 1),
                 *r22 = rotations.entry(2, 2);
    alignas(32) double s00[K] = {}, s01[K] = {}, s02[K] = {}, s11[K] = {}, s12[K] = {}, s22[K] = {};
    for (int p = 0; p < N; ++p) {
        const double u = x1[p].x, v = x1[p].y, x = x2[p].x, y = x2[p].y;
        for (int i = 0; i < K; ++i) {
            const double a0 = r00[i] * u + r01[i] * v + r02[i];
            const double a1 = r10[i] * u + r11[i] * v + r12[i];
            const double a2 = r20[i] * u + r21[i] * v + r22[i];
            const double c0 = a1 - a2 * y, c1 = a2 * x - a0, c2 = a0 * y - a1 * x;
            const double norm2 = c0 * c0 + c1 * c1 + c2 * c2;
            // A zero normal has zero entries, so any finite weight adds exactly nothing, as
            // skipping it does: there the divisor is 1 (norm2 + 1), elsewhere norm2 + 0 = norm2.
            // Arithmetic on the comparison, not a select, keeps the loop vectorised (a select on
            // a floating-point comparison counts as a possible trap and blocks it).
            const double w = 1.0 / (norm2 + static_cast<double>(norm2 == 0.0));
            s00[i] += w * c0 * c0;
            s01[i] += w * c0 * c1;
            s02[i] += w * c0 * c2;
            s11[i] += w * c1 * c1;
            s12[i] += w * c1 * c2;
            s22[i] += w * c2 * c2;
        }
    }
    for (int i = 0; i < K; ++i)
        costs[i] = s00[i] * (s11[i] * s22[i] - s12[i] * s12[i]) -
                   s01[i] * (s01[i] * s22[i] - s12[i] * s02[i]) +
                   s02[i] * (s01[i] * s12[i] - s11[i] * s02[i]);
}

/** coplanarityCosts<5>, compiled into an AVX2 / FMA clone as well (four rotations per vector
instead of two), which the CPU picks at load time (simd_dispatch.hpp); the clone's fused
multiply-adds change the costs in the last bits only (test_solvers bounds the difference). */
void sampleCoplanarityCosts(const Point2d* x1, const Point2d* x2,
                            double costs[StartRotations::kCount]);

/** The candidates of StartRotations in the order of their coplanarity cost on a five-point sample,
lowest first (ties: the lower index first), handed out one at a time: a call of gn or lm rarely
takes more than one or two, so the order is never sorted in full (a full top-8 insertion cost 1 400
instructions a ranked call, callgrind, docs/SOLVERS.md "Cost per call"). */
struct StartRanking
{
    double costs[StartRotations::kCount];

    /** The costs of every candidate on the sample (sampleCoplanarityCosts). */
    void rank(const Point2d* x1, const Point2d* x2) { sampleCoplanarityCosts(x1, x2, costs); }

    /** The index of the lowest cost not yet taken, the first of equal ones, or -1 when none is left
    (a NaN cost is never taken). */
    ESSENTIAL_INLINE_INTO_CLONES int takeNext()
    {
        int best = -1;
        double lowest = HUGE_VAL;
        for (int i = 0; i < StartRotations::kCount; ++i)
            if (costs[i] < lowest) {
                lowest = costs[i];
                best = i;
            }
        if (best >= 0) costs[best] = HUGE_VAL; // taken: no longer below any cost
        return best;
    }
};

} // namespace solvers
} // namespace essential
} // namespace cv

#endif

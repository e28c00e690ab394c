// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "refine/irls_refinement.hpp"

#include "geometry/essential_decomposition.hpp"
#include "geometry/essential_parameterisation.hpp"
#include "geometry/sampson.hpp"
#include "optim/levenberg_marquardt.hpp"
#include "optim/robust_loss.hpp"
#include "simd_dispatch.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace cv {
namespace essential {
namespace refine {

namespace {

using geometry::EssentialPose;
using geometry::Matrix5d;
using geometry::Vector5d;

/** Points per block of the normal equations' two-stage loop (a multiple of kLanes), small enough
for the block's arrays to stay in L1. */
constexpr int kBlock = 64;

/** Interleaved partial sums per entry of A and g: 4 fills one AVX register or two SSE2 ones. */
constexpr int kLanes = 4;

/** kLanes doubles added and multiplied lane by lane: the partial sums of the normal equations.
With GCC's vector extension each operation is one AVX2 instruction (two SSE2 ones) whatever the
loop vectoriser decides (on the plain lane loop it vectorised across blocks, with shuffles and
spills); elsewhere a plain loop per operation. Lane-wise arithmetic is the same IEEE arithmetic per
lane, so both give the same sums. lanesAt() reads kLanes doubles in place (a may_alias type, so
reading a double array through it is defined; returned by reference, so no vector crosses a call
boundary in the SSE2 clone). */
#if defined(__GNUC__)
typedef double Lanes __attribute__((vector_size(kLanes * sizeof(double))));
typedef double LanesInMemory
    __attribute__((vector_size(kLanes * sizeof(double)), may_alias, aligned(sizeof(double))));
inline const LanesInMemory& lanesAt(const double* p)
{
    return *reinterpret_cast<const LanesInMemory*>(p);
}
#else
struct Lanes
{
    double v[kLanes] = {};
    double operator[](int l) const { return v[l]; }
    friend Lanes operator*(const Lanes& a, const Lanes& b)
    {
        Lanes c;
        for (int l = 0; l < kLanes; ++l)
            c.v[l] = a.v[l] * b.v[l];
        return c;
    }
    Lanes& operator+=(const Lanes& b)
    {
        for (int l = 0; l < kLanes; ++l)
            v[l] += b.v[l];
        return *this;
    }
};
inline Lanes lanesAt(const double* p)
{
    Lanes v;
    std::memcpy(v.v, p, sizeof v.v);
    return v;
}
#endif

/** evaluate() for one loss (a compile-time choice, so that the per-point loop has no branch on
it and stays vectorised), inlined into each AVX2 / default clone of its callers. */
template <class Loss>
ESSENTIAL_INLINE_INTO_CLONES double evaluateLoss(const Problem& p, const EssentialPose& pose,
                                                 double sigma2, Matrix5d* A, Vector5d* g)
{
    const geometry::EssentialDerivatives derivatives(pose);
    const int n = p.size();
    const double* x1 = p.x1.data();
    const double* y1 = p.y1.data();
    const double* x2 = p.x2.data();
    const double* y2 = p.y2.data();
    const double invSigma2 = 1.0 / sigma2;
    typename Loss::Sum costSum;
    const geometry::EssentialEntries E(derivatives.E);
    if (!A) {
        for (int i = 0; i < n; ++i) {
            const geometry::SampsonTerms t = geometry::sampsonTerms(E, x1[i], y1[i], x2[i], y2[i]);
            if (!(t.D > 0.0)) continue;
            costSum.add(geometry::sampsonSquared(t) * invSigma2);
        }
        return Loss::scaled(sigma2, costSum.total());
    }
    // Per block of points: first the Sampson residuals, Jacobians and weights into small arrays
    // (a loop without reductions or branches, which the compiler vectorises), then the 15 distinct
    // entries of the symmetric A and the 5 of g summed in kLanes interleaved partial sums (vertical
    // adds the compiler vectorises too, without reassociating a scalar sum).
    double dE[5][9];
    for (int m = 0; m < 5; ++m)
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c)
                dE[m][3 * r + c] = derivatives.dE[m](r, c);
    alignas(32) double S[kBlock], W[kBlock], U[kBlock], J[5][kBlock];
    Lanes acc[20] = {};
    for (int begin = 0; begin < n; begin += kBlock) {
        const int count = std::min(kBlock, n - begin);
        const double* bx1 = x1 + begin;
        const double* by1 = y1 + begin;
        const double* bx2 = x2 + begin;
        const double* by2 = y2 + begin;
        for (int i = 0; i < count; ++i) {
            const geometry::SampsonTerms t =
                geometry::sampsonTerms(E, bx1[i], by1[i], bx2[i], by2[i]);
            // A point with D = 0 gets zero residual, Jacobian and weight: it adds nothing.
            const double valid = t.D > 0.0 ? 1.0 : 0.0;
            const double invSqrtD = valid / std::sqrt(t.D + (1.0 - valid));
            const double sv = t.r * invSqrtD;
            double G[8];
            geometry::sampsonScaledGradient(t, sv * invSqrtD, bx1[i], by1[i], bx2[i], by2[i], G);
            for (int m = 0; m < 5; ++m)
                J[m][i] = invSqrtD * geometry::contractScaledGradient(G, dE[m]);
            const double u = sv * sv * invSigma2;
            S[i] = sv;
            U[i] = t.D > 0.0 ? u : -1.0; // -1: no Sampson distance, not in the cost
            W[i] = Loss::weight(u);      // branch-free for both losses: the loop stays vectorised
        }
        for (int i = count; i < kBlock; ++i) { // pad the block to a multiple of kLanes
            S[i] = W[i] = 0.0;
            for (int m = 0; m < 5; ++m)
                J[m][i] = 0.0;
        }
        for (int i = 0; i < count; ++i) {
            if (U[i] >= 0.0) costSum.add(U[i]);
        }
        const int padded = (count + kLanes - 1) / kLanes * kLanes;
        for (int i = 0; i < padded; i += kLanes) {
            const Lanes w = lanesAt(W + i), sv = lanesAt(S + i);
            const Lanes j0 = lanesAt(J[0] + i), j1 = lanesAt(J[1] + i);
            const Lanes j2 = lanesAt(J[2] + i), j3 = lanesAt(J[3] + i);
            const Lanes j4 = lanesAt(J[4] + i);
            const Lanes w0 = w * j0, w1 = w * j1, w2 = w * j2, w3 = w * j3, w4 = w * j4;
            acc[0] += w0 * j0;
            acc[1] += w0 * j1;
            acc[2] += w0 * j2;
            acc[3] += w0 * j3;
            acc[4] += w0 * j4;
            acc[5] += w1 * j1;
            acc[6] += w1 * j2;
            acc[7] += w1 * j3;
            acc[8] += w1 * j4;
            acc[9] += w2 * j2;
            acc[10] += w2 * j3;
            acc[11] += w2 * j4;
            acc[12] += w3 * j3;
            acc[13] += w3 * j4;
            acc[14] += w4 * j4;
            acc[15] += w0 * sv;
            acc[16] += w1 * sv;
            acc[17] += w2 * sv;
            acc[18] += w3 * sv;
            acc[19] += w4 * sv;
        }
    }
    double sum[20];
    for (int k = 0; k < 20; ++k) {
        sum[k] = 0.0;
        for (int l = 0; l < kLanes; ++l)
            sum[k] += acc[k][l];
    }
    const double a00 = sum[0], a01 = sum[1], a02 = sum[2], a03 = sum[3], a04 = sum[4];
    const double a11 = sum[5], a12 = sum[6], a13 = sum[7], a14 = sum[8], a22 = sum[9];
    const double a23 = sum[10], a24 = sum[11], a33 = sum[12], a34 = sum[13], a44 = sum[14];
    const double g0 = sum[15], g1 = sum[16], g2 = sum[17], g3 = sum[18], g4 = sum[19];
    *A << a00, a01, a02, a03, a04, //
        a01, a11, a12, a13, a14,   //
        a02, a12, a22, a23, a24,   //
        a03, a13, a23, a33, a34,   //
        a04, a14, a24, a34, a44;
    *g << g0, g1, g2, g3, g4;
    return Loss::scaled(sigma2, costSum.total());
}

/** The robust cost of the pose (the loss of `loss` at scale sigma = sqrt(sigma2)) and, when A and g
are given, the IRLS normal equations A d = -g there: Gauss-Newton on the Sampson residuals s_i with
the weights w_i = rho'(s_i) / s_i held fixed, A = sum w J J^T, g = sum w s J. One pass over the
points computes both, so that an accepted step already has the next iteration's equations. Points
with no Sampson distance (D = 0) take no part. */
ESSENTIAL_SIMD_CLONES double evaluateCauchy(const Problem& p, const EssentialPose& pose,
                                            double sigma2, Matrix5d* A, Vector5d* g)
{
    return evaluateLoss<optim::CauchyLoss>(p, pose, sigma2, A, g);
}

ESSENTIAL_SIMD_CLONES double evaluateTukey(const Problem& p, const EssentialPose& pose,
                                           double sigma2, Matrix5d* A, Vector5d* g)
{
    return evaluateLoss<optim::TukeyLoss>(p, pose, sigma2, A, g);
}

double evaluate(const Problem& p, const EssentialPose& pose, double sigma2, RobustLoss loss,
                Matrix5d* A, Vector5d* g)
{
    return loss == RobustLoss::Tukey ? evaluateTukey(p, pose, sigma2, A, g)
                                     : evaluateCauchy(p, pose, sigma2, A, g);
}

/** All the points under the robust loss, as a model of optim::minimise. */
struct SampsonModel
{
    static constexpr bool kCostWithEquations = true;
    const Problem& problem;
    double sigma2;
    RobustLoss loss;

    double linearise(const EssentialPose& pose, optim::NormalEquations& system) const
    {
        return evaluate(problem, pose, sigma2, loss, &system.A, &system.g);
    }
    double cost(const EssentialPose& pose) const
    {
        return evaluate(problem, pose, sigma2, loss, nullptr, nullptr);
    }
};

} // namespace

IrlsResult refineIrls(const Problem& problem, const Matx33d& E0, double scale,
                      const IrlsSettings& settings)
{
    IrlsResult result;
    result.E = E0;
    Eigen::Matrix3d E;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            E(i, j) = E0(i, j);
    EssentialPose pose;
    if (!geometry::poseFromEssential(E, pose)) return result;

    // Up to six damping increases per iteration; a failure at the largest damping means the pose
    // is at a minimum of the robust cost to working precision. The first trial computes the normal
    // equations along with its cost (SampsonModel::kCostWithEquations): they are the next
    // iteration's when it is accepted, as it nearly always is.
    optim::LmSettings lm;
    lm.maxIterations = settings.maxIterations;
    lm.damping.initial = 1e-4;
    lm.damping.floor = 1e-12;
    lm.damping.attempts = 6;
    lm.relativeTolerance = settings.relativeTolerance;
    lm.predictedTolerance = settings.predictedTolerance;
    const SampsonModel model{problem, scale * scale, settings.loss};
    optim::NormalEquations system;
    const optim::LmResult outcome = optim::minimise(model, pose, system, lm);
    result.iterations = outcome.iterations;
    const double cost = outcome.cost, initialCost = outcome.initialCost;
    if (cost < initialCost) {
        geometry::reorthonormalise(pose.R);
        geometry::reorthonormalise(pose.Rt);
        const Eigen::Matrix3d Er = pose.E();
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                result.E(i, j) = Er(i, j);
        result.improved = true;
    }
    return result;
}

} // namespace refine
} // namespace essential
} // namespace cv

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The Sampson distance of a correspondence to an essential matrix: the first-order approximation
// of its geometric (reprojection) error, r^2 / (|(E q1)_xy|^2 + |(E^T q2)_xy|^2). It is the error
// cv::findEssentialMat thresholds, so thresholds mean the same in both.
//
// The one implementation in the module: scoring (scoring/msac_score.cpp), the support test, the
// refinement's normal equations (refine/irls_refinement.cpp) and the 5-DOF Jacobian
// (geometry/essential_parameterisation.hpp) all build on sampsonTerms() and
// sampsonScaledGradient() below. Everything is scalar and inline on purpose: called from a loop
// over structure-of-arrays points with the nine entries of E in registers (EssentialEntries), the
// compiler inlines and vectorises it.

#ifndef OPENCV_ESSENTIAL_GEOMETRY_SAMPSON_HPP
#define OPENCV_ESSENTIAL_GEOMETRY_SAMPSON_HPP

#include <opencv2/core/matx.hpp>

#include <Eigen/Core>

namespace cv {
namespace essential {
namespace geometry {

/** The nine entries of E as scalars, so that a loop over points keeps them in registers instead of
reloading them through a matrix object. */
struct EssentialEntries
{
    double e00, e01, e02, e10, e11, e12, e20, e21, e22;

    explicit EssentialEntries(const Eigen::Matrix3d& E)
        : e00(E(0, 0)), e01(E(0, 1)), e02(E(0, 2)), e10(E(1, 0)), e11(E(1, 1)), e12(E(1, 2)),
          e20(E(2, 0)), e21(E(2, 1)), e22(E(2, 2))
    {
    }
    explicit EssentialEntries(const Matx33d& E)
        : e00(E(0, 0)), e01(E(0, 1)), e02(E(0, 2)), e10(E(1, 0)), e11(E(1, 1)), e12(E(1, 2)),
          e20(E(2, 0)), e21(E(2, 1)), e22(E(2, 2))
    {
    }
};

/** What every Sampson quantity of one correspondence q1 = (x1, y1, 1), q2 = (x2, y2, 1) is built
from: E q1 = (a, b, c), the first two entries (p, q) of E^T q2, the algebraic residual
r = q2^T E q1 and the Sampson denominator D = a^2 + b^2 + p^2 + q^2. */
struct SampsonTerms
{
    double a, b, c, p, q, r, D;
};

inline SampsonTerms sampsonTerms(const EssentialEntries& e, double x1, double y1, double x2,
                                 double y2)
{
    SampsonTerms t;
    t.a = e.e00 * x1 + e.e01 * y1 + e.e02;
    t.b = e.e10 * x1 + e.e11 * y1 + e.e12;
    t.c = e.e20 * x1 + e.e21 * y1 + e.e22;
    t.p = e.e00 * x2 + e.e10 * y2 + e.e20;
    t.q = e.e01 * x2 + e.e11 * y2 + e.e21;
    t.r = x2 * t.a + y2 * t.b + t.c;
    t.D = t.a * t.a + t.b * t.b + t.p * t.p + t.q * t.q;
    return t;
}

/** Squared Sampson distance r^2 / D. A point on both epipoles (D = 0) gives +inf for a non-zero
residual and NaN for a zero one; NaN compares false, so such a point never counts as an inlier of a
`d <= threshold^2` test. */
inline double sampsonSquared(const SampsonTerms& t)
{
    return t.r * t.r / t.D;
}

inline double sampsonSquared(const EssentialEntries& e, double x1, double y1, double x2, double y2)
{
    return sampsonSquared(sampsonTerms(e, x1, y1, x2, y2));
}

inline double sampsonSquared(const Eigen::Matrix3d& E, double x1, double y1, double x2, double y2)
{
    return sampsonSquared(EssentialEntries(E), x1, y1, x2, y2);
}

/** The gradient of the Sampson residual s = r / sqrt(D) with respect to the nine entries of E,
scaled by sqrt(D): G = sqrt(D) ds/dE, G_ij = alpha_i q1_j - q2_i beta_j with k = r / D,
alpha = q2 - k (a, b, 0) and beta = k (p, q, 0). G22 is always 1 and is not stored; the other
eight are written row-major to G[0..7] (G00 G01 G02 G10 G11 G12 G20 G21). `k` is r / D, which the
caller has already computed along with s. */
inline void sampsonScaledGradient(const SampsonTerms& t, double k, double x1, double y1, double x2,
                                  double y2, double G[8])
{
    const double alpha0 = x2 - k * t.a, alpha1 = y2 - k * t.b;
    const double beta0 = k * t.p, beta1 = k * t.q;
    G[0] = alpha0 * x1 - x2 * beta0;
    G[1] = alpha0 * y1 - x2 * beta1;
    G[2] = alpha0;
    G[3] = alpha1 * x1 - y2 * beta0;
    G[4] = alpha1 * y1 - y2 * beta1;
    G[5] = alpha1;
    G[6] = x1 - beta0;
    G[7] = y1 - beta1;
}

/** <G, dE> for a gradient from sampsonScaledGradient() (with the implicit G22 = 1) and the nine
entries of a derivative dE, row-major. */
inline double contractScaledGradient(const double G[8], const double dE[9])
{
    return G[0] * dE[0] + G[1] * dE[1] + G[2] * dE[2] + G[3] * dE[3] + G[4] * dE[4] + G[5] * dE[5] +
           G[6] * dE[6] + G[7] * dE[7] + dE[8];
}

} // namespace geometry
} // namespace essential
} // namespace cv

#endif

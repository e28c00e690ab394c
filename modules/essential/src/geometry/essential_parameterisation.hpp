// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The minimal 5-DOF parameterisation of an essential matrix of Rosten et al. (section 2):
//   E = [t]x R,  t = Rt [1 0 0]^T,
// R updated by left-multiplied exponential-map increments exp(d1 G1 + d2 G2 + d3 G3) R, Rt by
// right-multiplied increments Rt exp(d4 G1 + d5 G2). The residual of a correspondence (q1, q2) is
// the algebraic epipolar error r = q2^T E q1, and its derivatives are the paper's equations (3),
// (4).

#ifndef OPENCV_ESSENTIAL_GEOMETRY_ESSENTIAL_PARAMETERISATION_HPP
#define OPENCV_ESSENTIAL_GEOMETRY_ESSENTIAL_PARAMETERISATION_HPP

#include "geometry/sampson.hpp"
#include "geometry/so3.hpp"
#include "simd_dispatch.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry> // cross products

#include <cmath>

namespace cv {
namespace essential {
namespace geometry {

typedef Eigen::Matrix<double, 5, 1> Vector5d;
typedef Eigen::Matrix<double, 5, 5> Matrix5d;

/** A point of the essential manifold: a rotation R and a rotation Rt whose first column is the unit
translation direction. */
struct EssentialPose
{
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
    Eigen::Matrix3d Rt = Eigen::Matrix3d::Identity();

    Eigen::Vector3d t() const { return Rt.col(0); }
    Eigen::Matrix3d E() const { return skew(Rt.col(0)) * R; }

    /** Moves along the manifold by the increment d (d1..d3 rotate R, d4, d5 turn t). */
    ESSENTIAL_INLINE_INTO_CLONES void update(const Vector5d& d)
    {
        // Eigen's 3 x 3 products stay calls into its default build from the SIMD clones (GCC does
        // not inline them there); written out entry by entry they took more instructions.
        R = expGenerators(d[0], d[1], d[2]) * R;
        Rt = Rt * expGenerators(d[3], d[4], 0.0);
    }
};

/** A rotation whose first column is the unit vector t (any completion of the basis). */
ESSENTIAL_INLINE_INTO_CLONES Eigen::Matrix3d rotationWithFirstColumn(const Eigen::Vector3d& t)
{
    const Eigen::Vector3d x = t.normalized();
    // The axis of x's smallest component is the farthest from parallel to x.
    int k = 0;
    if (std::abs(x.y()) < std::abs(x[k])) k = 1;
    if (std::abs(x.z()) < std::abs(x[k])) k = 2;
    Eigen::Vector3d helper = Eigen::Vector3d::Zero();
    helper[k] = 1.0;
    const Eigen::Vector3d y = x.cross(helper).normalized();
    Eigen::Matrix3d Rt;
    Rt.col(0) = x;
    Rt.col(1) = y;
    Rt.col(2) = x.cross(y);
    return Rt;
}

/** Per-model constants of the residual and its Jacobian, computed once per iteration so that the
per-correspondence work below is a handful of multiply-adds. */
struct ResidualFrame
{
    Eigen::Matrix3d R;
    Eigen::Vector3d t, u, v; // columns of Rt: t and the two directions t may turn towards

    explicit ResidualFrame(const EssentialPose& p)
        : R(p.R), t(p.Rt.col(0)), u(p.Rt.col(1)), v(p.Rt.col(2))
    {
    }
};

/** Residual r = q2^T [t]x R q1 of one correspondence and its 5 derivatives.

With a = R q1, c = a x q2 and b = q2 x t, r = t . c, and
  dr/dd_k = q2^T [t]x G_k a = b . (G_k a)     (k = 1..3, equation 3)
  dr/dd_4 = (Rt G1 e1) . c = -u . c,  dr/dd_5 = (Rt G2 e1) . c = -v . c   (equation 4)
since G1 e1 = -e2 and G2 e1 = -e3. */
ESSENTIAL_INLINE_INTO_CLONES double
residualAndJacobian(const ResidualFrame& f, double x1, double y1, double x2, double y2, double J[5])
{
    // Scalar arithmetic rather than Eigen's 3-vectors: those go into SSE2 pairs plus a lone
    // third entry, and the shuffles between them outnumbered the multiply-adds (callgrind).
    const Eigen::Matrix3d& R = f.R;
    const double a0 = R(0, 0) * x1 + R(0, 1) * y1 + R(0, 2);
    const double a1 = R(1, 0) * x1 + R(1, 1) * y1 + R(1, 2);
    const double a2 = R(2, 0) * x1 + R(2, 1) * y1 + R(2, 2);
    // c = a x q2, b = q2 x t, with q2 = (x2, y2, 1)
    const double c0 = a1 - a2 * y2, c1 = a2 * x2 - a0, c2 = a0 * y2 - a1 * x2;
    const double t0 = f.t.x(), t1 = f.t.y(), t2 = f.t.z();
    const double b0 = y2 * t2 - t1, b1 = t0 - x2 * t2, b2 = x2 * t1 - y2 * t0;
    J[0] = b0 * a1 - b1 * a0;
    J[1] = b0 * a2 - b2 * a0;
    J[2] = b1 * a2 - b2 * a1;
    J[3] = -(f.u.x() * c0 + f.u.y() * c1 + f.u.z() * c2);
    J[4] = -(f.v.x() * c0 + f.v.y() * c1 + f.v.z() * c2);
    return t0 * c0 + t1 * c1 + t2 * c2;
}

/** E and its derivatives dE/dd_k along the five parameter directions, computed once per pose:
dE/dd_k = [t]x G_k R (k = 1..3) and [Rt G_j e1]x R = -[u]x R, -[v]x R (k = 4, 5). */
struct EssentialDerivatives
{
    Eigen::Matrix3d E;
    Eigen::Matrix3d dE[5];

    explicit EssentialDerivatives(const EssentialPose& p)
    {
        const Eigen::Matrix3d T = skew(p.Rt.col(0));
        E = T * p.R;
        Eigen::Matrix3d G[3];
        G[0] << 0, 1, 0, -1, 0, 0, 0, 0, 0;
        G[1] << 0, 0, 1, 0, 0, 0, -1, 0, 0;
        G[2] << 0, 0, 0, 0, 0, 1, 0, -1, 0;
        for (int k = 0; k < 3; ++k)
            dE[k] = T * G[k] * p.R;
        dE[3] = -skew(p.Rt.col(1)) * p.R;
        dE[4] = -skew(p.Rt.col(2)) * p.R;
    }
};

/** The Sampson residual s = r / sqrt(D), D = |(E q1)_xy|^2 + |(E^T q2)_xy|^2, and its 5 derivatives
ds/dd_k = dr_k / sqrt(D) - r dD_k / (2 D^(3/2)), with dr_k = q2^T dE_k q1 and
dD_k = 2 ((E q1)_xy . (dE_k q1)_xy + (E^T q2)_xy . (dE_k^T q2)_xy). Returns false (and leaves s, J
unset) for a point with D = 0, which has no defined Sampson distance.

Computed through the gradient of s with respect to the nine entries of E: with k = r / D,
alpha = q2 - k ((E q1)_x, (E q1)_y, 0) and beta = k ((E^T q2)_x, (E^T q2)_y, 0),
ds/dE_ij = (alpha_i q1_j - q2_i beta_j) / sqrt(D), and ds/dd_k = <ds/dE, dE_k>. That is about 70
multiply-adds per point instead of the ~200 of five matrix-vector products per derivative; the
refinement's inner loop (refine/irls_refinement.cpp) spends most of its time here. */
inline bool sampsonResidualAndJacobian(const EssentialDerivatives& d, double x1, double y1,
                                       double x2, double y2, double& s, double J[5])
{
    const SampsonTerms t = sampsonTerms(EssentialEntries(d.E), x1, y1, x2, y2);
    if (!(t.D > 0.0)) return false;
    const double invSqrtD = 1.0 / std::sqrt(t.D);
    s = t.r * invSqrtD;
    double G[8];
    sampsonScaledGradient(t, s * invSqrtD, x1, y1, x2, y2, G);
    for (int m = 0; m < 5; ++m) {
        const Eigen::Matrix3d& dE = d.dE[m];
        const double dEm[9] = {dE(0, 0), dE(0, 1), dE(0, 2), dE(1, 0), dE(1, 1),
                               dE(1, 2), dE(2, 0), dE(2, 1), dE(2, 2)};
        J[m] = invSqrtD * contractScaledGradient(G, dEm);
    }
    return true;
}

/** The two epipolar distances of the paper's equation (5): g = r / |(E q1)_xy|, the distance of q2
to its epipolar line in view 2, and g' = r / |(E^T q2)_xy|, that of q1 in view 1, with their
derivatives dg/dd_k = (dr_k - r dD1_k / (2 D1)) / sqrt(D1) (D1 = |(E q1)_xy|^2) and likewise for g'.
Returns false for a point on an epipole (D1 or D2 zero). */
inline bool epipolarDistancesAndJacobian(const EssentialDerivatives& d, double x1, double y1,
                                         double x2, double y2, double g[2], double J[2][5])
{
    const Eigen::Vector3d q1(x1, y1, 1.0), q2(x2, y2, 1.0);
    // The Sampson terms split into the two images: D = D1 + D2.
    const SampsonTerms t = sampsonTerms(EssentialEntries(d.E), x1, y1, x2, y2);
    const double D1 = t.a * t.a + t.b * t.b;
    const double D2 = t.p * t.p + t.q * t.q;
    if (!(D1 > 0.0) || !(D2 > 0.0)) return false;
    const double r = t.r;
    const double s1 = 1.0 / std::sqrt(D1), s2 = 1.0 / std::sqrt(D2);
    g[0] = r * s1;
    g[1] = r * s2;
    for (int k = 0; k < 5; ++k) {
        const Eigen::Vector3d dEq1 = d.dE[k] * q1, dEtq2 = d.dE[k].transpose() * q2;
        const double dr = q2.dot(dEq1);
        const double dD1 = 2.0 * (t.a * dEq1.x() + t.b * dEq1.y());
        const double dD2 = 2.0 * (t.p * dEtq2.x() + t.q * dEtq2.y());
        J[0][k] = s1 * (dr - 0.5 * r * dD1 / D1);
        J[1][k] = s2 * (dr - 0.5 * r * dD2 / D2);
    }
    return true;
}

/** The algebraic residual alone, r = q2^T E q1. */
ESSENTIAL_INLINE_INTO_CLONES double algebraicResidual(const Eigen::Matrix3d& E, double x1,
                                                      double y1, double x2, double y2)
{
    return Eigen::Vector3d(x2, y2, 1.0).dot(E * Eigen::Vector3d(x1, y1, 1.0));
}

} // namespace geometry
} // namespace essential
} // namespace cv

#endif

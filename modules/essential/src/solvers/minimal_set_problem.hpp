// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// What the iterative minimal-set solvers (gn, lm) share: the starting pose and the 5x5
// system of residuals and Jacobian of a five-point sample in the 5-DOF parameterisation.

#ifndef OPENCV_ESSENTIAL_SOLVERS_MINIMAL_SET_PROBLEM_HPP
#define OPENCV_ESSENTIAL_SOLVERS_MINIMAL_SET_PROBLEM_HPP

#include "geometry/essential_parameterisation.hpp"
#include "optim/levenberg_marquardt.hpp"
#include "optim/small_linear_solve.hpp"
#include "optim/smallest_eigenvector.hpp"
#include "simd_dispatch.hpp"

#include <opencv2/core.hpp>

namespace cv {
namespace essential {
namespace solvers {

/** The starting point of one optimisation: R = R0 and the translation that best explains the
sample for that rotation. With c_i = (R0 q1_i) x q2_i the residuals are t . c_i, so the unit t
minimising sum (t . c_i)^2 is the eigenvector of sum c_i c_i^T with the smallest eigenvalue (its
sign is free: E and -E are the same model).

The paper starts from a random rotation and translation direction. Measured on noise-free minimal
sets of its synthetic protocol (5000 problems, docs/SOLVERS.md), starting GN from R = I with this
translation reaches the true E in 35.7% of calls with 6.5 iterations on average (cap 10), against
25.4% and 8.2 iterations from a random translation direction; random perturbations of R0 (0.1 and
0.3 rad) lowered the rate to 28% and 20%. Small inter-frame rotations, the common case in video,
favour R0 = I further. */
ESSENTIAL_INLINE_INTO_CLONES geometry::EssentialPose
bestTranslationStart(const Point2d* x1, const Point2d* x2, int n, const Eigen::Matrix3d& R0)
{
    Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
    for (int i = 0; i < n; ++i) {
        const Eigen::Vector3d c = (R0 * Eigen::Vector3d(x1[i].x, x1[i].y, 1.0))
                                      .cross(Eigen::Vector3d(x2[i].x, x2[i].y, 1.0));
        S.noalias() += c * c.transpose();
    }
    geometry::EssentialPose pose;
    pose.R = R0;
    pose.Rt = geometry::rotationWithFirstColumn(optim::smallestEigenvector(S));
    return pose;
}

/** Whether the five epipolar constraints q2_i^T E q1_i = 0 of the sample are linearly dependent,
so that they do not determine E: repeated correspondences (five copies of one, two distinct ones
repeated). The optimisation would then stop on whatever the start already fits exactly (R = I and
a translation orthogonal to the one or two distinct c_i) and return it as a solution.

The test: the Gram matrix of the constraint rows a_i = q2_i (x) q1_i, scaled to unit rows, has
determinant 1 for orthogonal rows and 0 for dependent ones. Its unscaled entries are
G_ij = (q2_i . q2_j)(q1_i . q1_j) (no 9-vectors needed), and the scaled determinant is
det(G) / prod G_ii, so no point is normalised. G is positive semi-definite, so its determinant is
the product of the pivots d_k of G = L D L^T without pivoting, and a pivot that is not positive
(round-off on dependent rows) already decides. Over 100 000 samples of converging views the
smallest scaled determinant was 3.1e-14 (1.7e-13 over the paper's protocol and converging views
with the normalised rows of the earlier form: two points very close together), and samples of one
to four distinct correspondences, repeated, gave a pivot of exactly 0 on the same 100 000 scenes:
the bound 1e-20 is six orders of magnitude below the first. */
ESSENTIAL_INLINE_INTO_CLONES bool constraintsAreDependent(const Point2d* x1, const Point2d* x2)
{
    constexpr double kMinGramDeterminant = 1e-20;
    double G[5][5];
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j <= i; ++j)
            G[i][j] = (x2[i].x * x2[j].x + x2[i].y * x2[j].y + 1.0) *
                      (x1[i].x * x1[j].x + x1[i].y * x1[j].y + 1.0);
    // L D L^T in place below the diagonal: G[i][k] becomes L_ik d_k, then L_ik.
    double scaled = 1.0;
    for (int k = 0; k < 5; ++k) {
        double d = G[k][k];
        for (int m = 0; m < k; ++m)
            d -= G[k][m] * G[k][m] * G[m][m];
        if (!(d > 0.0)) return true;
        scaled *= d / G[k][k];
        G[k][k] = d;
        for (int i = k + 1; i < 5; ++i) {
            double v = G[i][k];
            for (int m = 0; m < k; ++m)
                v -= G[i][m] * G[k][m] * G[m][m];
            G[i][k] = v / d;
        }
    }
    return !(scaled > kMinGramDeterminant);
}

/** Residuals r (5) and Jacobian J (5x5) of the sample at pose. Returns the squared norm of r. */
ESSENTIAL_INLINE_INTO_CLONES double evaluateMinimalSet(const geometry::EssentialPose& pose,
                                                       const Point2d* x1, const Point2d* x2,
                                                       geometry::Vector5d& r, geometry::Matrix5d& J)
{
    const geometry::ResidualFrame frame(pose);
    double row[5];
    for (int i = 0; i < 5; ++i) {
        r[i] = geometry::residualAndJacobian(frame, x1[i].x, x1[i].y, x2[i].x, x2[i].y, row);
        for (int k = 0; k < 5; ++k)
            J(i, k) = row[k];
    }
    return r.squaredNorm();
}

/** Squared norm of the residuals alone (used by LM to judge a trial step). */
ESSENTIAL_INLINE_INTO_CLONES double minimalSetCost(const geometry::EssentialPose& pose,
                                                   const Point2d* x1, const Point2d* x2)
{
    const Eigen::Matrix3d E = pose.E();
    double cost = 0.0;
    for (int i = 0; i < 5; ++i) {
        const double r = geometry::algebraicResidual(E, x1[i].x, x1[i].y, x2[i].x, x2[i].y);
        cost += r * r;
    }
    return cost;
}

/** The five-point sample as a model of optim::minimise: its square system of algebraic residuals
(gn solves it undamped, lm damped) and their cost alone for lm's trial steps. */
struct MinimalSetModel
{
    static constexpr bool kCostWithEquations = false;
    const Point2d* x1;
    const Point2d* x2;

    ESSENTIAL_INLINE_INTO_CLONES double linearise(const geometry::EssentialPose& pose,
                                                  optim::SquareSystem& system) const
    {
        return system.write([&](geometry::Vector5d& r, geometry::Matrix5d& J)
                                ESSENTIAL_LAMBDA_INLINE_INTO_CLONES {
                                    return evaluateMinimalSet(pose, x1, x2, r, J);
                                });
    }
    ESSENTIAL_INLINE_INTO_CLONES double cost(const geometry::EssentialPose& pose) const
    {
        return minimalSetCost(pose, x1, x2);
    }
};

} // namespace solvers
} // namespace essential
} // namespace cv

#endif

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
inline geometry::EssentialPose bestTranslationStart(const Point2d* x1, const Point2d* x2, int n,
                                                    const Eigen::Matrix3d& R0)
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
determinant 1 for orthogonal rows and 0 for dependent ones; its entries are
(q2_i . q2_j)(q1_i . q1_j) / (|q2_i||q1_i||q2_j||q1_j|), no 9-vectors needed. Over 100 000 samples
of the paper's protocol and of converging views the smallest determinant was 1.7e-13 (two points
very close together), and exactly repeated correspondences give 0 (round-off aside): the bound
1e-20 separates them by seven orders of magnitude. */
inline bool constraintsAreDependent(const Point2d* x1, const Point2d* x2)
{
    constexpr double kMinGramDeterminant = 1e-20;
    Eigen::Vector3d q1[5], q2[5];
    for (int i = 0; i < 5; ++i) {
        q1[i] = Eigen::Vector3d(x1[i].x, x1[i].y, 1.0).normalized();
        q2[i] = Eigen::Vector3d(x2[i].x, x2[i].y, 1.0).normalized();
    }
    Eigen::Matrix<double, 5, 5> G;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j <= i; ++j)
            G(i, j) = G(j, i) = q2[i].dot(q2[j]) * q1[i].dot(q1[j]);
    return !(optim::determinantPartialPivot<5>(G) > kMinGramDeterminant);
}

/** Residuals r (5) and Jacobian J (5x5) of the sample at pose. Returns the squared norm of r. */
inline double evaluateMinimalSet(const geometry::EssentialPose& pose, const Point2d* x1,
                                 const Point2d* x2, geometry::Vector5d& r, geometry::Matrix5d& J)
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
inline double minimalSetCost(const geometry::EssentialPose& pose, const Point2d* x1,
                             const Point2d* x2)
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

    double linearise(const geometry::EssentialPose& pose, optim::SquareSystem& system) const
    {
        return system.write([&](geometry::Vector5d& r, geometry::Matrix5d& J) {
            return evaluateMinimalSet(pose, x1, x2, r, J);
        });
    }
    double cost(const geometry::EssentialPose& pose) const { return minimalSetCost(pose, x1, x2); }
};

} // namespace solvers
} // namespace essential
} // namespace cv

#endif

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "solvers/levenberg_marquardt.hpp"

#include "optim/small_linear_solve.hpp"

#include <Eigen/Cholesky>

namespace cv {
namespace essential {
namespace solvers {

bool LevenbergMarquardtSolver::converge(geometry::EssentialPose& pose, const Point2d* x1,
                                        const Point2d* x2)
{
    geometry::Vector5d r;
    geometry::Matrix5d J;
    double cost = evaluateMinimalSet(pose, x1, x2, r, J);
    if (!(cost < HUGE_VAL)) return false;
    geometry::Matrix5d A = J.transpose() * J;
    geometry::Vector5d g = J.transpose() * r;
    double lambda = settings_.initialLambda;
    for (int it = 0; it < settings_.maxIterations; ++it) {
        if (cost < settings_.convergedCost) return true;
        ++lastIterations_;
        geometry::Matrix5d damped = A;
        damped.diagonal() *= 1.0 + lambda;
        geometry::Vector5d step;
        // Not positive definite (a zero column of J): the pivoting LDLT, which treats a zero
        // pivot as a zero component of the step, as before.
        if (!optim::solveCholesky<5>(damped, -g, step)) step = damped.ldlt().solve(-g);
        geometry::EssentialPose trial = pose;
        trial.update(step);
        const double trialCost = minimalSetCost(trial, x1, x2);
        if (step.allFinite() && trialCost < cost) {
            pose = trial;
            cost = evaluateMinimalSet(pose, x1, x2, r, J);
            A = J.transpose() * J;
            g = J.transpose() * r;
            lambda *= 0.1;
        } else {
            lambda *= 10.0;
            if (lambda > settings_.maxLambda) return false;
        }
    }
    return cost < settings_.convergedCost;
}

} // namespace solvers
} // namespace essential
} // namespace cv

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "solvers/gauss_newton.hpp"

#include "optim/small_linear_solve.hpp"

namespace cv {
namespace essential {
namespace solvers {

bool GaussNewtonSolver::converge(geometry::EssentialPose& pose, const Point2d* x1,
                                 const Point2d* x2)
{
    geometry::Vector5d r;
    geometry::Matrix5d J;
    double previousCost = -1.0;
    for (int it = 0; it < settings_.maxIterations; ++it) {
        const double cost = evaluateMinimalSet(pose, x1, x2, r, J);
        ++lastIterations_;
        if (!(cost < HUGE_VAL)) return false;
        if (cost < settings_.convergedCost) return true;
        if (previousCost >= 0.0 && cost > settings_.divergenceFactor * previousCost) return false;
        previousCost = cost;
        geometry::Vector5d step;
        // Singular J: a degenerate sample or start.
        if (!optim::solvePartialPivot<5>(J, -r, step)) return false;
        pose.update(step);
    }
    return evaluateMinimalSet(pose, x1, x2, r, J) < settings_.convergedCost;
}

} // namespace solvers
} // namespace essential
} // namespace cv

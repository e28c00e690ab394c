// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "solvers/gauss_newton.hpp"

#include "solvers/minimal_set_problem.hpp"
#include "solvers/solution_output.hpp"

#include <Eigen/LU>

namespace cv {
namespace essential {
namespace solvers {

int GaussNewtonSolver::solve(const Point2d* x1, const Point2d* x2, RNG& /*rng*/, Matx33d* solutions)
{
    geometry::EssentialPose pose = bestTranslationStart(x1, x2, 5, Eigen::Matrix3d::Identity());
    geometry::Vector5d r;
    geometry::Matrix5d J;
    double previousCost = -1.0;
    for (int it = 0; it < settings_.maxIterations; ++it) {
        const double cost = evaluateMinimalSet(pose, x1, x2, r, J);
        lastIterations_ = it;
        if (!(cost < HUGE_VAL)) return 0;
        if (cost < settings_.convergedCost) return writeSolution(pose, solutions);
        if (previousCost >= 0.0 && cost > settings_.divergenceFactor * previousCost) return 0;
        previousCost = cost;
        const Eigen::PartialPivLU<geometry::Matrix5d> lu(J);
        const geometry::Vector5d step = lu.solve(-r);
        if (!step.allFinite()) return 0; // singular J: degenerate sample or start
        pose.update(step);
    }
    lastIterations_ = settings_.maxIterations;
    geometry::Vector5d rFinal;
    if (evaluateMinimalSet(pose, x1, x2, rFinal, J) < settings_.convergedCost)
        return writeSolution(pose, solutions);
    return 0;
}

} // namespace solvers
} // namespace essential
} // namespace cv

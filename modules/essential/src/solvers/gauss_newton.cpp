// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "solvers/gauss_newton.hpp"

namespace cv {
namespace essential {
namespace solvers {

optim::LmSettings GaussNewtonSolver::optimiserSettings(const GaussNewtonSettings& settings)
{
    optim::LmSettings gn;
    gn.maxIterations = settings.maxIterations;
    gn.damping.initial = 0.0; // undamped: every step taken
    gn.stopCost = settings.convergedCost;
    // A singular J (a degenerate sample or start), divergence or the cap: no solution.
    gn.divergenceFactor = settings.divergenceFactor;
    return gn;
}

} // namespace solvers
} // namespace essential
} // namespace cv

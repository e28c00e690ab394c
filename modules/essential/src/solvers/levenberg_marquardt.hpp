// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// "lm": Levenberg-Marquardt on a minimal set of five correspondences (Rosten et al., Algorithm 1).

#ifndef OPENCV_ESSENTIAL_SOLVERS_LEVENBERG_MARQUARDT_HPP
#define OPENCV_ESSENTIAL_SOLVERS_LEVENBERG_MARQUARDT_HPP

#include "solvers/iterative_minimal_solver.hpp"

#include <vector>

namespace cv {
namespace essential {
namespace solvers {

/** Caps and tolerances of the LM solver; docs/SOLVERS.md records the measurement behind each. */
struct LevenbergMarquardtSettings
{
    /** Trial steps (accepted or not) before a hypothesis is abandoned. Measured as for GN: caps
    10 / 14 / 20 / 30 / 40 reach the true E in 33.4 / 37.2 / 40.1 / 41.9 / 43.0% of calls; 14 and
    20 tie in time per correct hypothesis (docs/TUNING.md, "Solver caps"), and 20 has the higher
    rate, which saves scoring passes. */
    int maxIterations = 20;
    /** Converged when the sum of squared algebraic residuals falls below this (see GN). */
    double convergedCost = 1e-14;
    /** Initial damping, relative to the diagonal of J^T J. 1e-5 rather than 1e-3 (nearer to GN's
    full step) raised the rates with the extra starts by 0.03 to 0.05 on converging views at the
    same cost, and changed those from R = I alone by less than their standard error. */
    double initialLambda = 1e-5;
    /** Give up when the damping grows beyond this: no descent direction left (a local minimum with
    a non-zero residual, which a minimal set only has when the start was bad or the sample is
    contaminated). */
    double maxLambda = 1e6;
    /** See GaussNewtonSettings: the lowest rate of any 15-degree bin with the extra starts (0.287,
    converging views at 15-30 degrees; essential_solver_hit_rates, test_solvers). */
    double successRate = 0.28;
    /** By rotation bin with the extra starts, and from R = I alone (see GaussNewtonSettings). */
    std::vector<double> rateByRotation = {0.34, 0.28, 0.34, 0.42, 0.47, 0.48};
    std::vector<double> identityRateByRotation = {0.28, 0.05, 0.023, 0.018, 0.017, 0.009};
    /** Starts tried after R = I when it gave no solution in front of the cameras (see
    GaussNewtonSettings::extraStarts). From R = I alone lm reaches the true E on 1 to 2% of samples
    beyond 30 degrees, which would need 20 to 50 times the samples; with three extra starts 34 to
    49%. */
    int extraStarts = 3;
    /** See GaussNewtonSettings::requireCheirality. */
    bool requireCheirality = true;
};

/** The LM minimal solver: damped Gauss-Newton steps (J^T J + lambda diag(J^T J)) d = -J^T r, a step
accepted only if it lowers the cost. Slower per iteration than GN, but it converges from more
starting points. Yields 0 or 1 essential matrix. */
class LevenbergMarquardtSolver : public IterativeMinimalSolver<LevenbergMarquardtSettings>
{
public:
    explicit LevenbergMarquardtSolver(
        const LevenbergMarquardtSettings& settings = LevenbergMarquardtSettings())
        : IterativeMinimalSolver<LevenbergMarquardtSettings>(settings, optimiserSettings(settings))
    {
    }

    /** The optimiser's settings from the solver's. */
    static optim::LmSettings optimiserSettings(const LevenbergMarquardtSettings& settings);
};

} // namespace solvers
} // namespace essential
} // namespace cv

#endif

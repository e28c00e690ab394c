// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// "lm": Levenberg-Marquardt on a minimal set of five correspondences (Rosten et al., Algorithm 1).

#ifndef OPENCV_ESSENTIAL_SOLVERS_LEVENBERG_MARQUARDT_HPP
#define OPENCV_ESSENTIAL_SOLVERS_LEVENBERG_MARQUARDT_HPP

#include "solvers/iterative_minimal_solver.hpp"

namespace cv {
namespace essential {
namespace solvers {

/** Caps and tolerances of the LM solver; docs/SOLVERS.md records the measurement behind each. */
struct LevenbergMarquardtSettings
{
    /** Trial steps (accepted or not) before a hypothesis is abandoned. Measured as for GN: caps
    10 / 14 / 20 / 30 / 40 reach the true E in 33.4 / 37.2 / 40.1 / 41.9 / 43.0% of calls at 4.3
    / 4.0 / 4.6 / 5.2 / 5.8 us per call. 14 and 20 tie per correct hypothesis (10.8 and 11.4 us,
    within timing noise); 20 has the higher rate, which saves scoring passes. */
    int maxIterations = 20;
    /** Converged when the sum of squared algebraic residuals falls below this (see GN). */
    double convergedCost = 1e-14;
    /** Initial damping, relative to the diagonal of J^T J. */
    double initialLambda = 1e-5;
    /** Give up when the damping grows beyond this: no descent direction left (a local minimum with
    a non-zero residual, which a minimal set only has when the start was bad or the sample is
    contaminated). */
    double maxLambda = 1e6;
    /** See GaussNewtonSettings::successRate: 0.401 measured noise-free. */
    double successRate = 0.27;
    /** Starts tried after R = I when it gave no solution in front of the cameras: the best of
    StartRotations for the sample (0 to 4). */
    int extraStarts = 3;
    /** Return a solution only if it can put the sample in front of both cameras
    (sampleIsInFront). */
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
        : IterativeMinimalSolver<LevenbergMarquardtSettings>(settings)
    {
    }

protected:
    bool converge(geometry::EssentialPose& pose, const Point2d* x1, const Point2d* x2) override;
};

} // namespace solvers
} // namespace essential
} // namespace cv

#endif

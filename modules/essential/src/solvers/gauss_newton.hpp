// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// "gn": Gauss-Newton on a minimal set of five correspondences (Rosten et al., Algorithm 2).

#ifndef OPENCV_ESSENTIAL_SOLVERS_GAUSS_NEWTON_HPP
#define OPENCV_ESSENTIAL_SOLVERS_GAUSS_NEWTON_HPP

#include "opencv2/essential/solver.hpp"

namespace cv {
namespace essential {
namespace solvers {

/** Caps and tolerances of the Gauss-Newton solver; docs/SOLVERS.md records the measurement that
chose each default. */
struct GaussNewtonSettings
{
    /** Iterations before a hypothesis is abandoned. */
    int maxIterations = 10;
    /** Converged when the sum of squared algebraic residuals falls below this. With unit-norm t and
    normalised points the residuals are O(1) at the start and Newton's method squares the error each
    step, so the cost goes from ~1e-6 to ~1e-12 to below 1e-20 in two more steps. */
    double convergedCost = 1e-20;
    /** Abandon when an iteration makes the cost this many times larger (diverging: a bad start or an
    outlier-contaminated sample). */
    double divergenceFactor = 1e3;
    /** Probability of converging to the true E from one random start on an outlier-free sample; the
    engine uses it for its iteration count. Measured by test_solvers (see docs/SOLVERS.md). */
    double successRate = 0.6;
};

/** The Gauss-Newton minimal solver. With five residuals and five parameters each step solves the
square system J d = -r (a 5x5 LU with partial pivoting). Yields 0 or 1 essential matrix. */
class GaussNewtonSolver : public EssentialSolver
{
public:
    explicit GaussNewtonSolver(const GaussNewtonSettings& settings = GaussNewtonSettings())
        : settings_(settings)
    {
    }
    int sampleSize() const override { return 5; }
    int maxSolutions() const override { return 1; }
    int solve(const Point2d* x1, const Point2d* x2, RNG& rng, Matx33d* solutions) override;
    double successRate() const override { return settings_.successRate; }

    /** Iterations used by the last call of solve() (for measurements). */
    int lastIterations() const { return lastIterations_; }

private:
    GaussNewtonSettings settings_;
    int lastIterations_ = 0;
};

} // namespace solvers
} // namespace essential
} // namespace cv

#endif

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// "gn": Gauss-Newton on a minimal set of five correspondences (Rosten et al., Algorithm 2).

#ifndef OPENCV_ESSENTIAL_SOLVERS_GAUSS_NEWTON_HPP
#define OPENCV_ESSENTIAL_SOLVERS_GAUSS_NEWTON_HPP

#include "solvers/iterative_minimal_solver.hpp"

#include <vector>

namespace cv {
namespace essential {
namespace solvers {

/** Caps and tolerances of the Gauss-Newton solver; docs/SOLVERS.md records the measurement that
chose each default. */
struct GaussNewtonSettings
{
    /** Iterations before a hypothesis is abandoned. Measured (5000 noise-free minimal sets of the
    paper's protocol): caps 5 / 7 / 10 / 15 / 20 reach the true E in 22.9 / 31.9 / 35.7 / 37.9 /
    39.2% of calls; 10 is the knee of time per correct hypothesis (docs/TUNING.md, "Solver
    caps"). */
    int maxIterations = 10;
    /** Converged when the sum of squared algebraic residuals of the five points falls below this,
    i.e. residuals ~1e-7, far below the 1e-3 noise level of image measurements in normalised units;
    1e-20 (machine precision) cost 0.7 more iterations per call for no better hypotheses. */
    double convergedCost = 1e-14;
    /** Abandon when an iteration makes the cost this many times larger (diverging: a bad start or
    an outlier-contaminated sample). */
    double divergenceFactor = 1e3;
    /** Probability of reaching the true E on an outlier-free, noise-free sample, at any rotation
    up to 90 degrees: the lowest of rateByRotation. The engine uses it until it has a model. */
    double successRate = 0.28;
    /** The same by the rotation angle of the model, in bins of 15 degrees (0-15, 15-30, ...,
    75-90 and beyond): the lower of the rates measured on converging views and on the paper's
    protocol (3000 problems per bin, essential_solver_hit_rates; test_solvers asserts them). The
    engine reads the rate at the rotation of its best model (hitProbabilityAt()). */
    std::vector<double> rateByRotation = {0.40, 0.30, 0.28, 0.38, 0.41, 0.40};
    /** The same from R = I alone (extraStarts 0), as in a mix with a direct solver
    (IdentityStartOnly): GN reaches the true E on a third of small-rotation samples and on one in
    25 at 75 to 90 degrees. */
    std::vector<double> identityRateByRotation = {0.33, 0.10, 0.058, 0.053, 0.043, 0.040};
    /** Starts tried after R = I when it gave no solution in front of the cameras: the best of
    StartRotations for the sample that put it in front of the cameras at their start (0 to 8).
    One lifts the rate at 45 to 90 degrees from 0.04-0.05 to 0.39-0.41 for one more optimisation
    per sample that needs it; more starts add less (two: 0.48-0.52) while every contaminated sample
    pays for them too (docs/SOLVERS.md, "Success rate by rotation"). */
    int extraStarts = 1;
    /** Return a solution only if it can put the sample in front of both cameras
    (sampleIsInFront): the junk roots of contaminated samples then cost no scoring. */
    bool requireCheirality = true;
};

/** The Gauss-Newton minimal solver. With five residuals and five parameters each step solves the
square system J d = -r (a 5x5 LU with partial pivoting). Yields 0 or 1 essential matrix. */
class GaussNewtonSolver : public IterativeMinimalSolver<GaussNewtonSettings>
{
public:
    explicit GaussNewtonSolver(const GaussNewtonSettings& settings = GaussNewtonSettings())
        : IterativeMinimalSolver<GaussNewtonSettings>(settings, optimiserSettings(settings))
    {
    }

    /** The optimiser's settings from the solver's. */
    static optim::LmSettings optimiserSettings(const GaussNewtonSettings& settings);
};

} // namespace solvers
} // namespace essential
} // namespace cv

#endif

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The final step of the paper: the best hypothesis optimised on all the data by iteratively
// reweighted least squares (IRLS) with Levenberg-Marquardt, in the 5-DOF parameterisation.

#ifndef OPENCV_ESSENTIAL_REFINE_IRLS_REFINEMENT_HPP
#define OPENCV_ESSENTIAL_REFINE_IRLS_REFINEMENT_HPP

#include "input/problem.hpp"

#include <opencv2/core.hpp>

namespace cv {
namespace essential {
namespace refine {

/** The robust loss of the refinement, with its scale c (optim/robust_loss.hpp): Cauchy keeps some
pull from every point, which converges from a start that is off; Tukey's biweight has none beyond c,
which makes the minimum exact on noise-free inliers whatever the outliers. */
enum class RobustLoss { Cauchy, Tukey };

struct IrlsSettings
{
    RobustLoss loss = RobustLoss::Cauchy;
    /** Outer (reweighting) iterations. Measured on 200 problems of the synthetic protocol (N = 500,
    50% inliers, from the MSAC winner): most refinements stop after 5 or 6 iterations and 7 of 200
    reach this cap; mean pose errors 0.032 deg (rotation) and 0.170 deg (translation direction),
    (docs/TUNING.md, "IRLS cap"). A cap of 200 with a tolerance of 1e-10 gave the same errors to
    0.001 deg at twice the time (IRLS converges linearly as the weights keep changing). */
    int maxIterations = 20;
    /** Stop when an accepted step lowers the robust cost by less than this fraction (see above). */
    double relativeTolerance = 1e-6;
    /** Stop, before evaluating it, at a step the linearisation predicts to lower the robust cost
    by less than this fraction of it: the relative rule above needed one more evaluation to see the
    same small decrease. Relative, not in units of the scale, so that on noise-free inliers (the
    cost going to the outliers' constant part) the minimum is still reached to rounding (an absolute
    1e-5 scale^2 stopped 1e-6 short of the true E there, and a least-squares run at a large scale
    after one step). Measured (docs/TUNING.md, "IRLS cap"): the final refinement's evaluations at
    90% inliers 5.5 -> 3.9 a call, the drop-in's instructions 0.94 of before at 90%, pose errors
    unchanged on 300 scenes at 90 / 50 / 30% (mean 0.060 / 0.078 / 0.117 degrees), the real pairs'
    AUC@5/10/20 unchanged to 1e-4 over four seeds (1e-6: 0.97 of the instructions). 0: the relative
    rule alone. */
    double predictedTolerance = 1e-5;
};

struct IrlsResult
{
    Matx33d E;
    int iterations = 0;
    bool improved = false; //!< the robust cost went down
};

/** Minimises sum_i rho(s_i) over all points, s_i the Sampson distance and rho the Cauchy loss
rho(s) = sigma^2/2 log(1 + s^2/sigma^2) with sigma = scale (the inlier threshold).

Cauchy because its influence s / (1 + s^2/sigma^2) falls off for s >> sigma, so the outliers the
RANSAC stage left in do not pull the solution, while it stays smooth (unlike a truncated loss) so
LM converges from the RANSAC winner. Each iteration fixes the weights w_i = rho'(s_i) / s_i =
1 / (1 + s_i^2 / sigma^2) and takes one LM step on the weighted Sampson residuals, with their exact
Jacobian in the 5-DOF parameterisation (geometry::sampsonResidualAndJacobian: the paper's equations
(3) and (4) for the numerator, plus the derivative of the Sampson denominator); a step is kept only
if the robust cost decreases. */
IrlsResult refineIrls(const Problem& problem, const Matx33d& E0, double scale,
                      const IrlsSettings& settings = IrlsSettings());

} // namespace refine
} // namespace essential
} // namespace cv

#endif

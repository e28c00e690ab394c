// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#ifndef OPENCV_ESSENTIAL_TERMINATION_TERMINATION_HPP
#define OPENCV_ESSENTIAL_TERMINATION_TERMINATION_HPP

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace cv {
namespace essential {
namespace termination {

/** Samples needed so that, with probability `confidence`, at least one sample gave the true model
when each does so with probability `hitProbability` (EssentialSolver::hitProbability for the
current inlier ratio): log(1 - p) / log(1 - hit), capped at maxIters. */
inline int requiredIterations(double confidence, double hitProbability, int maxIters)
{
    const double good = hitProbability;
    if (!(good > 0.0)) return maxIters;
    if (good >= 1.0) return 1;
    const double num = std::log(std::max(1.0 - confidence, DBL_MIN));
    const double den = std::log1p(-good);
    if (!(den < 0.0)) return maxIters;
    const double needed = std::ceil(num / den);
    return needed >= maxIters ? maxIters : std::max(1, static_cast<int>(needed));
}

/** The sample cap for an iteration cap `maxIters` given in OpenCV's units. OpenCV's cap counts
samples of a direct solver, each of which solves an outlier-free sample; a solver that succeeds on
a fraction s of outlier-free samples gets maxIters / s samples, so that the confidence reached at
the cap is the same. (Its samples are cheaper by more than that factor: see docs/SOLVERS.md.) */
inline int sampleCap(int maxIters, double solverSuccess)
{
    const double s = std::min(1.0, std::max(solverSuccess, 0.01));
    const double cap = std::ceil(maxIters / s);
    return cap > 1e9 ? 1000000000 : static_cast<int>(cap);
}

} // namespace termination
} // namespace essential
} // namespace cv

#endif

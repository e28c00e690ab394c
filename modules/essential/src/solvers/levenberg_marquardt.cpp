// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "solvers/levenberg_marquardt.hpp"

namespace cv {
namespace essential {
namespace solvers {

optim::LmSettings
LevenbergMarquardtSolver::optimiserSettings(const LevenbergMarquardtSettings& settings)
{
    // The cap counts trial steps, accepted or not; a run of rejections ends only at maxLambda.
    optim::LmSettings lm;
    lm.maxIterations = settings.maxIterations;
    lm.maxTrials = settings.maxIterations;
    lm.damping.initial = settings.initialLambda;
    lm.damping.ceiling = settings.maxLambda;
    lm.damping.attempts = settings.maxIterations;
    lm.stopCost = settings.convergedCost;
    return lm;
}

} // namespace solvers
} // namespace essential
} // namespace cv

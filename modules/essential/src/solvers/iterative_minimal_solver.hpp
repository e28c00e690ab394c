// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#ifndef OPENCV_ESSENTIAL_SOLVERS_ITERATIVE_MINIMAL_SOLVER_HPP
#define OPENCV_ESSENTIAL_SOLVERS_ITERATIVE_MINIMAL_SOLVER_HPP

#include "opencv2/essential/solver.hpp"

namespace cv {
namespace essential {
namespace solvers {

/** What the optimisation-based minimal solvers (gn, lm) have in common: a five-point sample, at
most one solution per call, a measured success rate, and settings of type `Settings` (which must
have a `successRate` member). Each derived class only implements solve(). */
template <class Settings> class IterativeMinimalSolver : public EssentialSolver
{
public:
    explicit IterativeMinimalSolver(const Settings& settings) : settings_(settings) {}
    int sampleSize() const override { return 5; }
    int maxSolutions() const override { return 1; }
    double successRate() const override { return settings_.successRate; }

    /** Iterations used by the last call of solve() (for measurements). */
    int lastIterations() const { return lastIterations_; }

protected:
    Settings settings_;
    int lastIterations_ = 0;
};

} // namespace solvers
} // namespace essential
} // namespace cv

#endif

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#ifndef OPENCV_ESSENTIAL_SOLVERS_ITERATIVE_MINIMAL_SOLVER_HPP
#define OPENCV_ESSENTIAL_SOLVERS_ITERATIVE_MINIMAL_SOLVER_HPP

#include "opencv2/essential/solver.hpp"
#include "solvers/minimal_set_problem.hpp"
#include "solvers/sample_cheirality.hpp"
#include "solvers/solution_output.hpp"
#include "solvers/start_rotations.hpp"

#include <algorithm>

namespace cv {
namespace essential {
namespace solvers {

/** What the optimisation-based minimal solvers (gn, lm) have in common: a five-point sample, at
most one solution per call, a measured success rate, and the sequence of starts. Settings must have
the members `successRate`, `extraStarts` and `requireCheirality`. A derived class implements
converge(), the optimisation from one start.

A call starts from R = I (with the least-squares translation for it); if that does not give a
solution that puts the sample in front of both cameras, it starts again from the `extraStarts`
rotations of StartRotations that best explain the sample (rankStartRotations), in that order, and
returns the first such solution. A sample whose constraints are linearly dependent gets no start
(constraintsAreDependent). */
template <class Settings> class IterativeMinimalSolver : public EssentialSolver
{
public:
    explicit IterativeMinimalSolver(const Settings& settings) : settings_(settings) {}
    int sampleSize() const override { return 5; }
    int maxSolutions() const override { return 1; }
    double successRate() const override { return settings_.successRate; }

    int solve(const Point2d* x1, const Point2d* x2, RNG& /*rng*/, Matx33d* solutions) override
    {
        lastIterations_ = 0;
        lastStarts_ = 0;
        if (constraintsAreDependent(x1, x2)) return 0;
        lastStarts_ = 1;
        geometry::EssentialPose pose = bestTranslationStart(x1, x2, 5, Eigen::Matrix3d::Identity());
        if (accept(pose, x1, x2)) return writeSolution(pose, solutions);
        const int extra = std::min(std::max(settings_.extraStarts, 0), 4);
        if (extra == 0) return 0;
        int order[4];
        rankStartRotations(x1, x2, 5, extra, order);
        for (int k = 0; k < extra; ++k) {
            ++lastStarts_;
            pose = bestTranslationStart(x1, x2, 5, StartRotations::instance()[order[k]]);
            if (accept(pose, x1, x2)) return writeSolution(pose, solutions);
        }
        return 0;
    }

    /** Iterations used by the last call of solve(), over all its starts (for measurements). */
    int lastIterations() const { return lastIterations_; }
    /** Starts tried by the last call of solve(). */
    int lastStarts() const { return lastStarts_; }

protected:
    /** Optimises `pose` on the sample; true when it converged to an exact solution. Adds the
    iterations it used to lastIterations_. */
    virtual bool converge(geometry::EssentialPose& pose, const Point2d* x1, const Point2d* x2) = 0;

    Settings settings_;
    int lastIterations_ = 0;
    int lastStarts_ = 0;

private:
    bool accept(geometry::EssentialPose& pose, const Point2d* x1, const Point2d* x2)
    {
        return converge(pose, x1, x2) &&
               (!settings_.requireCheirality || sampleIsInFront(pose, x1, x2, 5));
    }
};

} // namespace solvers
} // namespace essential
} // namespace cv

#endif

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#ifndef OPENCV_ESSENTIAL_SOLVERS_ITERATIVE_MINIMAL_SOLVER_HPP
#define OPENCV_ESSENTIAL_SOLVERS_ITERATIVE_MINIMAL_SOLVER_HPP

#include "geometry/essential_decomposition.hpp"
#include "opencv2/essential/solver.hpp"
#include "optim/levenberg_marquardt.hpp"
#include "solvers/minimal_set_problem.hpp"
#include "solvers/sample_cheirality.hpp"
#include "solvers/solution_output.hpp"
#include "solvers/start_rotations.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace cv {
namespace essential {
namespace solvers {

/** What the optimisation-based minimal solvers (gn, lm) have in common: a five-point sample, at
most one solution per call, a measured success rate, and the sequence of starts. Settings must have
the members `successRate`, `rateByRotation`, `identityRateByRotation`, `extraStarts` and
`requireCheirality`. A derived class gives the settings of optim::minimise, the optimisation from
one start (gn undamped, lm damped).

A call starts from R = I (with the least-squares translation for it); if that does not give a
solution that puts the sample in front of both cameras, it starts again from the `extraStarts`
rotations of StartRotations that best explain the sample (StartRanking), in that order, and
returns the first such solution. A sample whose constraints are linearly dependent gets no start
(constraintsAreDependent). */
/** What an engine or a composite may ask of an iterative solver: start from R = I only. The extra
starts cost every contaminated sample a few more optimisations; next to a direct solver, which
finds wide rotations in one call per sample (composite_solver.cpp), or when only the number of
hypotheses per unit time counts (the preemptive engine), they are not worth it, and the rate by
rotation becomes that of R = I alone. `keepCheirality` false also returns the roots that cannot put
the sample in front of the cameras, as the solvers did before the filter: the preemptive engine
counts hypotheses, and its budgets were chosen for those. */
class IdentityStartOnly
{
public:
    virtual ~IdentityStartOnly() {}
    virtual void useIdentityStartOnly(bool keepCheirality = true) = 0;
};

/** IdentityStartOnly::useIdentityStartOnly for `solver` when it has that setting (an iterative
solver, or a composite holding one); any other solver, a user's included, is left as it is. For the
caller that creates the solver for an engine (pipeline/estimate.cpp), so that the engine itself
never changes the solver it is given. */
inline void useIdentityStartOnlyIfIterative(EssentialSolver& solver, bool keepCheirality)
{
    if (auto* iterative = dynamic_cast<IdentityStartOnly*>(&solver))
        iterative->useIdentityStartOnly(keepCheirality);
}

/** Ranked start rotations examined for the extra starts: the first extraStarts of them that put
the sample in front of the cameras at their start are optimised. */
constexpr int kRankedStarts = 8;

/** How one call of an iterative solver starts: from R = I, then, when that gave no solution
(in front of the cameras, with `requireCheirality`), from up to `extraStarts` of the ranked start
rotations that put the sample in front of the cameras at their start. */
struct StartPolicy
{
    int extraStarts = 0;
    bool requireCheirality = true;
};

/** What a call did, for measurements: optimiser iterations over all its starts (linearisations
undamped, trial steps damped: what each solver's cap counts) and the starts it tried. */
struct StartCounts
{
    int iterations = 0;
    int starts = 0;
};

/** The call of IterativeMinimalSolver::solve: the starts of `policy`, each optimised by
optim::minimise with `optimiser`, the first exact solution (in front of the cameras, with
requireCheirality) written to solutions[0]. Returns 0 or 1. Compiled into an AVX2 / FMA clone as
well (simd_dispatch.hpp), the optimiser, the start translation and the depth tests inlined into it:
fused multiply-adds take a third off the instructions of an iteration (docs/SOLVERS.md, "Cost per
call"). */
int solveFromStarts(const Point2d* x1, const Point2d* x2, const StartPolicy& policy,
                    const optim::LmSettings& optimiser, StartCounts& counts, Matx33d* solutions);

template <class Settings>
class IterativeMinimalSolver : public EssentialSolver, public IdentityStartOnly
{
public:
    IterativeMinimalSolver(const Settings& settings, const optim::LmSettings& optimiser)
        : settings_(settings), optimiser_(optimiser)
    {
    }
    int sampleSize() const override { return 5; }
    int maxSolutions() const override { return 1; }
    double successRate() const override { return settings_.successRate; }

    /** With Settings::rateByRotation: the rate of the bin of the model's rotation angle (bins of
    15 degrees from 0, the last bin for anything beyond) times w^5; otherwise the default. */
    double hitProbabilityAt(double inlierRatio, const Matx33d& model) const override
    {
        if (settings_.rateByRotation.empty()) return hitProbability(inlierRatio);
        const double w = std::min(1.0, std::max(0.0, inlierRatio));
        return rateAt(model) * std::pow(w, 5);
    }

    void useIdentityStartOnly(bool keepCheirality = true) override
    {
        settings_.extraStarts = 0;
        settings_.requireCheirality = settings_.requireCheirality && keepCheirality;
        settings_.rateByRotation = settings_.identityRateByRotation;
        settings_.successRate = *std::min_element(settings_.identityRateByRotation.begin(),
                                                  settings_.identityRateByRotation.end());
        cachedModel_ = Matx33d::zeros();
    }

    int solve(const Point2d* x1, const Point2d* x2, RNG& /*rng*/, Matx33d* solutions) override
    {
        StartPolicy policy;
        policy.extraStarts = std::min(std::max(settings_.extraStarts, 0), kRankedStarts);
        policy.requireCheirality = settings_.requireCheirality;
        StartCounts counts;
        const int found = solveFromStarts(x1, x2, policy, optimiser_, counts, solutions);
        lastIterations_ = counts.iterations;
        lastStarts_ = counts.starts;
        return found;
    }

    /** Iterations used by the last call of solve(), over all its starts (for measurements). */
    int lastIterations() const { return lastIterations_; }
    /** Starts tried by the last call of solve(). */
    int lastStarts() const { return lastStarts_; }

protected:
    Settings settings_;
    int lastIterations_ = 0;
    int lastStarts_ = 0;

private:
    /** The rate of the bin of the model's rotation; the model's angle is the smaller of its two
    rotations' (the twisted pair, 180 degrees apart: for a rotation of up to 90 degrees that is
    the true one). Cached: the engine asks several times per model. */
    double rateAt(const Matx33d& model) const
    {
        if (model == cachedModel_) return cachedRate_;
        Eigen::Matrix3d E, R1, R2;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                E(i, j) = model(i, j);
        Eigen::Vector3d t;
        double rate = settings_.successRate;
        if (geometry::decomposeEssential(E, R1, R2, t)) {
            const double cosine =
                std::min(1.0, std::max(-1.0, (std::max(R1.trace(), R2.trace()) - 1.0) / 2.0));
            const double degrees = std::acos(cosine) * 180.0 / CV_PI;
            const size_t bin =
                std::min(static_cast<size_t>(degrees / 15.0), settings_.rateByRotation.size() - 1);
            rate = settings_.rateByRotation[bin];
        }
        cachedModel_ = model;
        cachedRate_ = rate;
        return rate;
    }

    optim::LmSettings optimiser_;
    mutable Matx33d cachedModel_ = Matx33d::zeros();
    mutable double cachedRate_ = 0.0;
};

} // namespace solvers
} // namespace essential
} // namespace cv

#endif

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The one damped least-squares optimiser of the module: damping, acceptance and stopping, for
// every model with five parameters (the 5-DOF essential parameterisation). The minimal solvers
// (gn, lm), the robust solver's annealed fit and the IRLS refinement (local optimisation, the
// final step, the plane check) differ only in their model and their settings.

#ifndef OPENCV_ESSENTIAL_OPTIM_LEVENBERG_MARQUARDT_HPP
#define OPENCV_ESSENTIAL_OPTIM_LEVENBERG_MARQUARDT_HPP

#include "optim/small_linear_solve.hpp"
#include "simd_dispatch.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <algorithm>
#include <climits>
#include <cmath>

namespace cv {
namespace essential {
namespace optim {

using Matrix5 = Eigen::Matrix<double, 5, 5>;
using Vector5 = Eigen::Matrix<double, 5, 1>;

/** The normal equations A d = -g of a linearisation (A = sum w J J^T, g = sum w r J). */
struct NormalEquations
{
    Matrix5 A;
    Vector5 g;

    /** The damped step (A + lambda diag(A)) d = -g (Marquardt's scaling: the damping acts on each
    parameter in its own units). Cholesky first; a matrix that is not positive definite (a zero
    column of J) goes to the pivoting LDLT, which treats a zero pivot as a zero component of the
    step. False when the step is not finite. */
    ESSENTIAL_INLINE_INTO_CLONES bool solve(double lambda, Vector5& step)
    {
        Matrix5 damped = A;
        damped.diagonal() *= 1.0 + lambda;
        if (!solveCholesky<5>(damped, -g, step)) step = damped.ldlt().solve(-g);
        return step.allFinite();
    }

    /** The decrease of the cost the linearisation predicts for `step`, -g.d - d^T A d / 2: the
    cost sum w r^2 / 2 of A = sum w J J^T, g = sum w r J. */
    double predictedDecrease(const Vector5& step) const
    {
        return -g.dot(step) - 0.5 * step.dot(A * step);
    }
};

/** The square system of a minimal problem, five residuals r and their 5x5 Jacobian J. Undamped
(Gauss-Newton) it is solved as it stands, J d = -r, which keeps the condition number of J rather
than of J^T J; damped, through its normal equations, formed once per linearisation. */
class SquareSystem
{
public:
    /** The model writes r and J through `evaluate(r, J)`, whose result (the cost) is returned; the
    normal equations of the previous ones are dropped with them. */
    template <class Evaluate> ESSENTIAL_INLINE_INTO_CLONES double write(Evaluate&& evaluate)
    {
        normalFormed_ = false;
        return evaluate(r_, J_);
    }

    ESSENTIAL_INLINE_INTO_CLONES bool solve(double lambda, Vector5& step)
    {
        if (lambda == 0.0) return solvePartialPivot<5>(J_, -r_, step); // false unless finite
        if (!normalFormed_) {
            normal_.A = J_.transpose() * J_;
            normal_.g = J_.transpose() * r_;
            normalFormed_ = true;
        }
        return normal_.solve(lambda, step);
    }

    /** The decrease of the cost |r|^2 (the minimal problems' cost) the linearisation predicts for
    `step`: |r|^2 - |r + J d|^2. */
    ESSENTIAL_INLINE_INTO_CLONES double predictedDecrease(const Vector5& step) const
    {
        const Vector5 Jd = J_ * step;
        return -2.0 * r_.dot(Jd) - Jd.squaredNorm();
    }

private:
    Matrix5 J_;
    Vector5 r_;
    NormalEquations normal_;
    bool normalFormed_ = false;
};

/** The damping schedule: lambda starts at `initial`; an accepted step divides it by 10 (not below
`floor`), a rejected one multiplies it by 10. `initial` 0 is Gauss-Newton: every step is taken
undamped, without a trial evaluation. */
struct Damping
{
    double initial = 1e-3;
    double floor = 0.0;
    /** A rejection that takes lambda beyond this ends the optimisation (DampingLimit): the start
    is not in the basin of a minimum the steps can reach. */
    double ceiling = HUGE_VAL;
    /** Trial steps per iteration; when all are rejected the iteration stalls and the optimisation
    stops (the pose is at a minimum to working precision). */
    int attempts = 1;
};

struct LmSettings
{
    /** Iterations: linearisations for Gauss-Newton; for LM, rounds of trial steps that end with an
    accepted one. */
    int maxIterations = 20;
    /** LM only: trial steps over the whole run (a minimal solver's budget counts trials). */
    int maxTrials = INT_MAX;
    Damping damping;
    /** Converged once the cost is below this (a minimal problem's exact fit); 0: never. */
    double stopCost = 0.0;
    /** LM: stop once an accepted step lowers the cost by less than this fraction of it. */
    double relativeTolerance = 0.0;
    /** LM: stop, without evaluating it, when the first trial step of an iteration is predicted by
    the linearisation to lower the cost by less than this fraction of it; 0: never. */
    double predictedTolerance = 0.0;
    /** Gauss-Newton: a cost beyond this times the previous one ends the run (Diverged). */
    double divergenceFactor = HUGE_VAL;
};

enum class LmStatus {
    Converged,     //!< cost below LmSettings::stopCost
    Stalled,       //!< a small decrease, or every trial step of an iteration rejected
    MaxIterations, //!< the iteration or trial cap reached
    Diverged,      //!< Gauss-Newton: the cost grew by more than the divergence factor
    Singular,      //!< no finite step
    NotFinite,     //!< the cost at the start is not finite
    DampingLimit   //!< lambda beyond Damping::ceiling
};

struct LmResult
{
    LmStatus status = LmStatus::MaxIterations;
    double cost = HUGE_VAL;
    double initialCost = HUGE_VAL;
    int iterations = 0; //!< linearisations (Gauss-Newton) or iterations begun (LM)
    int trials = 0;     //!< LM: trial steps evaluated
};

/** What a damped iteration did: a step accepted; every attempt rejected; rejected until the run's
trial cap stopped it (LmSettings::maxTrials); a singular system; lambda past its ceiling; its first
step predicted to lower the cost by less than `stopBelow` (not evaluated). */
enum class StepOutcome { Accepted, Rejected, TrialCap, Singular, DampingLimit, PredictedSmall };

/** One LM iteration at the linearisation `system` of `x`, whose cost is `cost`: up to
damping.attempts trial steps, the first that lowers the cost accepted (x, cost updated). With
Model::kCostWithEquations the first trial is evaluated with its linearisation (`trialSystem`), which
is then the next iteration's when it is accepted, as it nearly always is; `systemCurrent` says
whether `system` now belongs to x. `lambda` carries the damping from one iteration to the next.

The Model: `double linearise(const Params&, System&)` (the cost, and the system written),
`double cost(const Params&)`, `static constexpr bool kCostWithEquations`; Params has
`update(const Vector5&)`. */
template <class Model, class Params, class System>
ESSENTIAL_INLINE_INTO_CLONES StepOutcome dampedIteration(Model& model, Params& x, System& system,
                                                         System& trialSystem, double& cost,
                                                         double& lambda, const Damping& damping,
                                                         LmResult& counts, int maxTrials,
                                                         bool& systemCurrent,
                                                         double stopBelow = 0.0)
{
    systemCurrent = true;
    for (int attempt = 0; attempt < damping.attempts; ++attempt) {
        if (counts.trials >= maxTrials) return StepOutcome::TrialCap;
        ++counts.trials;
        Vector5 step;
        if (!system.solve(lambda, step)) return StepOutcome::Singular;
        if (attempt == 0 && stopBelow > 0.0 && system.predictedDecrease(step) < stopBelow) {
            --counts.trials; // not a trial: the step is never evaluated
            return StepOutcome::PredictedSmall;
        }
        Params trial = x;
        trial.update(step);
        const bool withSystem = Model::kCostWithEquations && attempt == 0;
        const double trialCost =
            withSystem ? model.linearise(trial, trialSystem) : model.cost(trial);
        if (trialCost < cost) {
            x = trial;
            cost = trialCost;
            lambda = std::max(lambda * 0.1, damping.floor);
            if (withSystem)
                std::swap(system, trialSystem);
            else
                systemCurrent = false;
            return StepOutcome::Accepted;
        }
        lambda *= 10.0;
        if (lambda > damping.ceiling) return StepOutcome::DampingLimit;
    }
    return counts.trials >= maxTrials ? StepOutcome::TrialCap : StepOutcome::Rejected;
}

/** The same for a model whose trial steps evaluate the cost alone (no fused linearisation), which
needs no second system. */
template <class Model, class Params, class System>
inline StepOutcome dampedIteration(Model& model, Params& x, System& system, double& cost,
                                   double& lambda, const Damping& damping, LmResult& counts,
                                   int maxTrials, bool& systemCurrent)
{
    static_assert(!Model::kCostWithEquations, "a fused model needs the trial system");
    System notWritten; // only a fused model's first trial writes it
    return dampedIteration(model, x, system, notWritten, cost, lambda, damping, counts, maxTrials,
                           systemCurrent);
}

/** Minimises the model's cost from x. Damping::initial 0 runs Gauss-Newton (undamped steps, every
one taken, stopped by stopCost, divergence, a singular system or the iteration cap); otherwise
Levenberg-Marquardt (trial steps accepted when they lower the cost). */
template <class Model, class Params, class System>
ESSENTIAL_INLINE_INTO_CLONES LmResult minimise(Model& model, Params& x, System& system,
                                               const LmSettings& settings)
{
    LmResult result;
    if (settings.damping.initial == 0.0) {
        double previous = -1.0;
        for (int it = 0; it < settings.maxIterations; ++it) {
            const double cost = model.linearise(x, system);
            ++result.iterations;
            result.cost = cost;
            if (it == 0) result.initialCost = cost;
            if (!(cost < HUGE_VAL)) {
                result.status = LmStatus::NotFinite;
                return result;
            }
            if (cost < settings.stopCost) {
                result.status = LmStatus::Converged;
                return result;
            }
            if (previous >= 0.0 && cost > settings.divergenceFactor * previous) {
                result.status = LmStatus::Diverged;
                return result;
            }
            previous = cost;
            Vector5 step;
            if (!system.solve(0.0, step)) {
                result.status = LmStatus::Singular;
                return result;
            }
            x.update(step);
        }
        result.cost = model.linearise(x, system);
        result.status =
            result.cost < settings.stopCost ? LmStatus::Converged : LmStatus::MaxIterations;
        return result;
    }

    double cost = model.linearise(x, system);
    result.initialCost = result.cost = cost;
    if (!(cost < HUGE_VAL)) {
        result.status = LmStatus::NotFinite;
        return result;
    }
    System trialSystem; // written by the first fused trial before it is read
    double lambda = settings.damping.initial;
    for (int it = 0; it < settings.maxIterations; ++it) {
        if (cost < settings.stopCost) {
            result.status = LmStatus::Converged;
            return result;
        }
        if (result.trials >= settings.maxTrials) break;
        result.iterations = it + 1;
        const double before = cost;
        bool systemCurrent = true;
        const StepOutcome outcome =
            dampedIteration(model, x, system, trialSystem, cost, lambda, settings.damping, result,
                            settings.maxTrials, systemCurrent, settings.predictedTolerance * cost);
        result.cost = cost;
        if (outcome == StepOutcome::Singular || outcome == StepOutcome::DampingLimit) {
            result.status =
                outcome == StepOutcome::Singular ? LmStatus::Singular : LmStatus::DampingLimit;
            return result;
        }
        if (outcome == StepOutcome::TrialCap) break;
        if (outcome == StepOutcome::Rejected || outcome == StepOutcome::PredictedSmall) {
            result.status = LmStatus::Stalled;
            return result;
        }
        if ((before - cost) / before < settings.relativeTolerance) {
            result.status = LmStatus::Stalled;
            return result;
        }
        if (!systemCurrent) model.linearise(x, system);
    }
    result.status = cost < settings.stopCost ? LmStatus::Converged : LmStatus::MaxIterations;
    return result;
}

} // namespace optim
} // namespace essential
} // namespace cv

#endif

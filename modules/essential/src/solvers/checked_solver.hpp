// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// A guard around a user-registered solver (registerSolver()): the engines trust the built-in
// solvers' answers, but a user's solver may throw any exception, report a count outside
// [0, maxSolutions()], or return non-finite or zero matrices. This wrapper turns each of those
// into what the engines expect: a cv::Exception naming the solver, a clamped count, and only
// finite, non-zero solutions (the others are dropped, as a solver that gave up on them).

#ifndef OPENCV_ESSENTIAL_SOLVERS_CHECKED_SOLVER_HPP
#define OPENCV_ESSENTIAL_SOLVERS_CHECKED_SOLVER_HPP

#include "opencv2/essential/solver.hpp"

#include <cmath>
#include <exception>
#include <string>

namespace cv {
namespace essential {
namespace solvers {

/** Runs a user's code `f` (a factory, solve(), sampleSize(), ...) and returns its result; any
exception that is not a cv::Exception becomes one (StsError) naming the solver and `what`. */
template <typename F> auto callUserCode(const std::string& name, const char* what, F&& f)
{
    try {
        return f();
    } catch (const cv::Exception&) {
        throw;
    } catch (const std::exception& e) {
        CV_Error(Error::StsError, "solver '" + name + "': " + what + " threw: " + e.what());
    } catch (...) {
        CV_Error(Error::StsError,
                 "solver '" + name + "': " + what + " threw a non-standard exception");
    }
}

class CheckedSolver final : public EssentialSolver
{
public:
    /** `sampleSize` and `maxSolutions` as the registry read and checked them once. */
    CheckedSolver(Ptr<EssentialSolver> inner, std::string name, int sampleSize, int maxSolutions)
        : inner_(std::move(inner)), name_(std::move(name)), sampleSize_(sampleSize),
          maxSolutions_(maxSolutions)
    {
    }

    int sampleSize() const override { return sampleSize_; }
    int maxSolutions() const override { return maxSolutions_; }

    int solve(const Point2d* x1, const Point2d* x2, RNG& rng, Matx33d* solutions) override
    {
        int count =
            callUserCode(name_, "solve()", [&] { return inner_->solve(x1, x2, rng, solutions); });
        count = std::max(0, std::min(count, maxSolutions_));
        int kept = 0;
        for (int h = 0; h < count; ++h) {
            bool finite = true;
            double sum = 0.0;
            for (int i = 0; i < 9; ++i) {
                finite &= std::isfinite(solutions[h].val[i]);
                sum += std::abs(solutions[h].val[i]);
            }
            if (!finite || !(sum > 0.0) || !std::isfinite(sum)) continue;
            if (kept != h) solutions[kept] = solutions[h];
            ++kept;
        }
        return kept;
    }

    double successRate() const override
    {
        const double s =
            callUserCode(name_, "successRate()", [&] { return inner_->successRate(); });
        return s > 0.0 && s <= 1.0 ? s : 1.0; // NaN or out of range: as a direct solver
    }

    double hitProbability(double inlierRatio) const override
    {
        const double h = callUserCode(name_, "hitProbability()",
                                      [&] { return inner_->hitProbability(inlierRatio); });
        return h >= 0.0 && h <= 1.0 ? h : EssentialSolver::hitProbability(inlierRatio);
    }

    double hitProbabilityAt(double inlierRatio, const Matx33d& model) const override
    {
        const double h = callUserCode(name_, "hitProbabilityAt()",
                                      [&] { return inner_->hitProbabilityAt(inlierRatio, model); });
        return h >= 0.0 && h <= 1.0 ? h : hitProbability(inlierRatio);
    }

    void setThreshold(double normalisedThreshold) override
    {
        callUserCode(name_, "setThreshold()", [&] { inner_->setThreshold(normalisedThreshold); });
    }

private:
    Ptr<EssentialSolver> inner_;
    std::string name_;
    int sampleSize_;
    int maxSolutions_;
};

} // namespace solvers
} // namespace essential
} // namespace cv

#endif

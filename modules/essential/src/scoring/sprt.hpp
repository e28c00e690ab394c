// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Wald's sequential probability ratio test for hypothesis verification, as in Matas and Chum,
// "Randomized RANSAC with sequential probability ratio test" (R-RANSAC with SPRT, 2008): a
// hypothesis is checked point by point (in a random order) and rejected as soon as the likelihood
// ratio of "bad model" against "good model" exceeds a threshold A, so that a bad hypothesis costs a
// few dozen point checks instead of hundreds.

#ifndef OPENCV_ESSENTIAL_SCORING_SPRT_HPP
#define OPENCV_ESSENTIAL_SCORING_SPRT_HPP

#include <algorithm>
#include <cmath>
#include <vector>

namespace cv {
namespace essential {
namespace scoring {

/** One designed test: the model's assumed inlier ratio epsilon, the probability delta that a point
is consistent with a bad model, the decision threshold A and the log likelihood ratio increments. */
struct SprtTest
{
    double epsilon = 0.0, delta = 0.0, A = HUGE_VAL;
    double logA = HUGE_VAL; //!< reject when the summed increments exceed this
    double logIn = 0.0;     //!< log(delta / epsilon), added for a consistent point (< 0)
    double logOut = 0.0;    //!< log((1 - delta) / (1 - epsilon)), for an inconsistent one (> 0)
};

/** The adaptive SPRT state of one search: the current test, the delta estimate and the history of
tests for the stopping rule. Inactive until a first model has been accepted (its inlier ratio is the
first epsilon). */
class Sprt
{
public:
    /** `hypothesisCost`: time to generate one hypothesis in units of the time to check one point
    (the paper's t_M). `initialDelta`: delta before any bad model has been rejected. */
    Sprt(double hypothesisCost, double initialDelta)
        : hypothesisCost_(hypothesisCost), delta_(initialDelta)
    {
    }

    bool active() const { return active_; }
    const SprtTest& test() const { return test_; }

    /** A model with this inlier ratio became the best: the test now assumes a good model has at
    least its support (the paper's epsilon update). `modelsPerSample` is m_S. */
    void accepted(double inlierRatio, double modelsPerSample)
    {
        modelsPerSample_ = std::max(0.1, modelsPerSample);
        if (active_ && inlierRatio <= test_.epsilon) return;
        active_ = true;
        design(inlierRatio, delta_);
    }

    /** A hypothesis was rejected after `checked` points of which `consistent` were inliers: the
    paper's delta estimate is the average fraction of consistent points in rejected models (pooled
    over all of them here); the test is redesigned when it moves by more than 5%. Returns true when
    it was. */
    bool rejected(int consistent, int checked)
    {
        rejectedConsistent_ += consistent;
        rejectedChecked_ += checked;
        const double estimate =
            double(rejectedConsistent_) / double(std::max(1L, rejectedChecked_));
        if (estimate > 0.0 && std::abs(estimate - delta_) > 0.05 * delta_) {
            delta_ = estimate;
            design(test_.epsilon, delta_);
            return true;
        }
        return false;
    }

    /** Counts one sample drawn under the current test (or before the first one). */
    void sampleDrawn() { ++history_.back().samples; }

    /** The paper's stopping rule (its equation (9) with h_i = 1): total samples needed so that a
    good sample, drawn with probability p per sample, was drawn and accepted with the given
    confidence. Under test i a good model is rejected with probability at most 1 / A_i (Wald's
    bound; h_i = 1 is exact when the true inlier ratio is epsilon_i and conservative when it is
    higher, which holds as epsilon_i is the support of a model found so far), so the probability of
    missing it after k_i samples under each test is prod_i (1 - p (1 - 1 / A_i))^k_i. Samples drawn
    before the first test count with A = infinity. Capped at `cap`. */
    int samplesNeeded(double p, double confidence, int cap) const
    {
        if (!(p > 0.0)) return cap;
        const double logEta0 = std::log(std::max(1.0 - confidence, 1e-300));
        double logEta = 0.0, drawn = 0.0;
        for (size_t i = 0; i + 1 < history_.size(); ++i) {
            logEta +=
                history_[i].samples * std::log1p(-std::min(p * history_[i].pass, 1.0 - 1e-16));
            drawn += history_[i].samples;
        }
        if (logEta <= logEta0) return static_cast<int>(std::min<double>(drawn, cap));
        const double perSample = std::log1p(-std::min(p * history_.back().pass, 1.0 - 1e-16));
        if (!(perSample < 0.0)) return cap;
        const double total = drawn + std::ceil((logEta0 - logEta) / perSample);
        return total >= cap ? cap : std::max(1, static_cast<int>(total));
    }

    int testsDesigned() const { return tests_; }

private:
    void design(double epsilon, double delta)
    {
        // delta must stay below epsilon (otherwise consistent points would count against the
        // model); the cap at 0.3 is OpenCV's (a bad model is rarely consistent with more).
        epsilon = std::min(epsilon, 0.999);
        delta = std::min(std::min(delta, 0.5 * epsilon), 0.3);
        delta = std::max(delta, 1e-6);
        test_.epsilon = epsilon;
        test_.delta = delta;
        test_.logIn = std::log(delta / epsilon);
        test_.logOut = std::log((1.0 - delta) / (1.0 - epsilon));
        // A = K + log A (the paper's equation (7) iterated from A = K), K = t_M C / m_S + 1 with C
        // the Kullback-Leibler divergence between the bad and the good model's consistency.
        const double C = (1.0 - delta) * test_.logOut + delta * test_.logIn;
        const double K = hypothesisCost_ * C / modelsPerSample_ + 1.0;
        double A = K;
        for (int i = 0; i < 20; ++i) {
            const double next = K + std::log(A);
            if (std::abs(next - A) < 1e-9 * A) break;
            A = next;
        }
        test_.A = A;
        test_.logA = std::log(A);
        history_.push_back({1.0 - 1.0 / A, 0});
        ++tests_;
    }

    double hypothesisCost_;
    double delta_;
    double modelsPerSample_ = 1.0;
    bool active_ = false;
    SprtTest test_;
    /** Per test (the first entry: before any test), 1 - 1/A and the samples drawn under it. */
    struct History
    {
        double pass;
        long samples;
    };
    std::vector<History> history_ = {{1.0, 0}};
    long rejectedConsistent_ = 0, rejectedChecked_ = 0;
    int tests_ = 0;
};

} // namespace scoring
} // namespace essential
} // namespace cv

#endif

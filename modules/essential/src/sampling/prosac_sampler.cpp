// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "sampling/prosac_sampler.hpp"

#include "sampling/uniform_sampler.hpp"

#include <algorithm>
#include <cmath>

namespace cv {
namespace essential {
namespace sampling {

ProsacSampler::ProsacSampler(int n, int m, int growthMaxSamples)
    : n_(n), m_(m), growthMax_(std::max(1, growthMaxSamples)), pool_(m), termination_(n),
      growth_(static_cast<size_t>(n) + 1, 0.0)
{
    CV_Assert(m >= 1 && n >= m);
    // T_m = T_N prod_{i < m} (m - i) / (N - i), then T_{k+1} = T_k (k + 1) / (k + 1 - m).
    double T = growthMax_;
    for (int i = 0; i < m_; ++i)
        T *= double(m_ - i) / double(n_ - i);
    double Tprime = 1.0;
    growth_[static_cast<size_t>(m_)] = Tprime;
    for (int k = m_; k < n_; ++k) {
        const double next = T * double(k + 1) / double(k + 1 - m_);
        Tprime += std::ceil(next - T);
        growth_[static_cast<size_t>(k) + 1] = Tprime;
        T = next;
    }
}

void ProsacSampler::setTerminationLength(int nStar)
{
    termination_ = std::max(pool_, std::min(n_, nStar));
}

void ProsacSampler::draw(RNG& rng, int* indices)
{
    if (isUniform()) {
        drawUniformSample(rng, n_, m_, indices);
        return;
    }
    ++t_;
    if (pool_ < termination_ && t_ >= growth_[static_cast<size_t>(pool_)]) ++pool_;
    // Past T'_n the pool should already hold u_n: the sample takes it and m - 1 of the better
    // points. A pool held at the termination length is sampled uniformly instead (the paper's
    // rule would put its last point in every sample).
    if (pool_ < termination_ && growth_[static_cast<size_t>(pool_)] < t_) {
        drawUniformSample(rng, pool_ - 1, m_ - 1, indices);
        indices[m_ - 1] = pool_ - 1;
    } else {
        drawUniformSample(rng, pool_, m_, indices);
    }
}

namespace {

/** Probability that a point is an inlier of a wrong model, and the significance of the
non-randomness test (Chum and Matas; OpenCV 4.6 uses the same values). */
constexpr double kBeta = 0.05;
constexpr double kPsi = 0.05;
/** OpenCV's minimum termination length. */
constexpr int kMinTerminationLength = 100;

/** The least k with P(X >= k) < psi for X ~ Binomial(trials, beta). */
int binomialTailQuantile(int trials, double beta, double psi)
{
    if (trials <= 0) return 1;
    const double mean = trials * beta, sd = std::sqrt(trials * beta * (1.0 - beta));
    int k = std::min(trials, static_cast<int>(std::ceil(mean + 12.0 * sd + 12.0)));
    // pmf(k) in log space (no underflow of beta^k for large k), then downwards by the recurrence
    // pmf(k - 1) = pmf(k) k / (trials - k + 1) (1 - beta) / beta.
    double pmf =
        std::exp(std::lgamma(trials + 1.0) - std::lgamma(k + 1.0) - std::lgamma(trials - k + 1.0) +
                 k * std::log(beta) + (trials - k) * std::log1p(-beta));
    double tail = pmf; // P(X >= k); the mass above the start is negligible
    if (tail >= psi) return k + 1;
    while (k > 0) {
        const double below = pmf * k / double(trials - k + 1) * (1.0 - beta) / beta;
        if (tail + below >= psi) break;
        tail += below;
        pmf = below;
        --k;
    }
    return k;
}

} // namespace

ProsacTermination::ProsacTermination(int n, int m)
    : minLength_(std::min(n, std::max(m, kMinTerminationLength)))
{
    const int step = std::max(1, (n - m + 63) / 64);
    for (int len = m;; len = std::min(n, len + step)) {
        gridLength_.push_back(len);
        gridMin_.push_back(m + binomialTailQuantile(len - m, kBeta, kPsi));
        if (len == n) break;
    }
}

int ProsacTermination::minInliers(int n) const
{
    // I_min is non-decreasing in n: the value at the next grid length is an upper bound.
    const auto it = std::lower_bound(gridLength_.begin(), gridLength_.end(), n);
    if (it == gridLength_.end()) return gridMin_.back();
    return gridMin_[static_cast<size_t>(it - gridLength_.begin())];
}

} // namespace sampling
} // namespace essential
} // namespace cv

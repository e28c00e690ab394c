// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The robust losses of the module's reweighted least squares (the robust solver's annealed fit,
// the IRLS refinement), each as a function of u = s^2 / c^2 for a residual s at scale c: the
// IRLS weight rho'(s) / s and the cost, summed over points by the loss's own accumulator.

#ifndef OPENCV_ESSENTIAL_OPTIM_ROBUST_LOSS_HPP
#define OPENCV_ESSENTIAL_OPTIM_ROBUST_LOSS_HPP

#include <algorithm>
#include <cmath>

namespace cv {
namespace essential {
namespace optim {

/** Cauchy: rho(s) = c^2/2 log(1 + u), weight 1 / (1 + u). Every point keeps some pull (c^2 / s
for s >> c), which keeps the optimisation converging from a start that is off. */
struct CauchyLoss
{
    static double weight(double u) { return 1.0 / (1.0 + u); }
    /** rho(s) without its constant factor c^2/2 (comparisons at one scale need none). */
    static double cost(double u) { return std::log1p(u); }
    static double scaled(double sigma2, double costSum) { return 0.5 * sigma2 * costSum; }

    /** The logarithm is the costliest part: the sum of log(1 + u_i) is taken as the log of the
    product of the (1 + u_i) over runs of points, one log per run. Each factor is at least 1 and
    the product is flushed before it exceeds kFlush, so it never overflows (a single factor above
    the bound, a far outlier, is flushed on its own). */
    struct Sum
    {
        static constexpr double kFlush = 1e150;
        double sum = 0.0;
        double product = 1.0;

        void add(double u)
        {
            const double factor = 1.0 + u;
            if (product * factor > kFlush || !(factor < kFlush)) {
                sum += std::log(product);
                product = 1.0;
                if (!(factor < kFlush)) {
                    sum += std::log1p(u);
                    return;
                }
            }
            product *= factor;
        }
        double total() const { return sum + std::log(product); }
    };
};

/** Tukey's biweight: rho(s) = c^2/6 (1 - (1 - u)^3) for u < 1, c^2/6 beyond; weight (1 - u)^2
inside and 0 beyond. No pull at all from the points beyond c, none near it, which makes the minimum
exact on noise-free inliers whatever the outliers (it needs a start within about c of it). */
struct TukeyLoss
{
    /** max(0, 1 - u)^2 without a comparison, so that a per-point loop stays branch-free and
    vectorised (exact: d + |d| is 2d or 0, and the halving is exact). */
    static double weight(double u)
    {
        const double d = 1.0 - u;
        const double v = 0.5 * (d + std::abs(d));
        return v * v;
    }
    static double cost(double u)
    {
        const double v = std::max(0.0, 1.0 - u);
        return 1.0 - v * v * v;
    }
    static double scaled(double sigma2, double costSum) { return sigma2 / 6.0 * costSum; }

    struct Sum
    {
        double sum = 0.0;
        void add(double u) { sum += cost(u); }
        double total() const { return sum; }
    };
};

} // namespace optim
} // namespace essential
} // namespace cv

#endif

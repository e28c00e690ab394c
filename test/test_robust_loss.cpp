// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The robust losses (optim/robust_loss.hpp): each IRLS weight is rho'(s) / s of its loss, checked
// against a central difference of the scaled cost; the Cauchy sum with one logarithm per run equals
// the plain sum of log1p, far outliers included.

#include "optim/robust_loss.hpp"

#include "essential_test.hpp"

#include <cmath>

namespace {

using namespace cv::essential::optim;

template <class Loss> double rho(double s, double c)
{
    return Loss::scaled(c * c, Loss::cost(s * s / (c * c)));
}

template <class Loss> void expectWeightIsDerivative(double c)
{
    for (double s = 0.05 * c; s < 3.0 * c; s += 0.0731 * c) {
        const double h = 1e-6 * c;
        const double derivative = (rho<Loss>(s + h, c) - rho<Loss>(s - h, c)) / (2.0 * h);
        // The difference's error is O(h^2 rho''') plus round-off ~1e-16 rho / h.
        EXPECT_NEAR(Loss::weight(s * s / (c * c)), derivative / s, 1e-7) << "s / c = " << s / c;
    }
}

TEST(RobustLoss, CauchyWeightIsTheDerivativeOfItsCost)
{
    expectWeightIsDerivative<CauchyLoss>(1.0);
    expectWeightIsDerivative<CauchyLoss>(2e-3); // a threshold in normalised coordinates
}

TEST(RobustLoss, TukeyWeightIsTheDerivativeOfItsCost)
{
    expectWeightIsDerivative<TukeyLoss>(1.0);
    expectWeightIsDerivative<TukeyLoss>(2e-3);
    // Beyond the scale: constant cost c^2 / 6, no weight.
    EXPECT_EQ(TukeyLoss::weight(1.5), 0.0);
    EXPECT_EQ(TukeyLoss::cost(1.5), 1.0);
    EXPECT_DOUBLE_EQ(rho<TukeyLoss>(4.0, 2.0), 4.0 / 6.0);
}

TEST(RobustLoss, CauchySumTakesOneLogPerRunWithoutOverflow)
{
    CauchyLoss::Sum sum;
    double plain = 0.0;
    // Moderate residuals, then far outliers whose factors alone approach or pass the flush bound.
    for (int i = 0; i < 2000; ++i) {
        const double u = (i % 7) * 0.37 + 1e-3 * i;
        sum.add(u);
        plain += std::log1p(u);
    }
    for (double u : {1e149, 1e151, 1e300, 3.0, 1e160}) {
        sum.add(u);
        plain += std::log1p(u);
    }
    EXPECT_TRUE(std::isfinite(sum.total()));
    EXPECT_NEAR(sum.total(), plain, 1e-12 * plain);
}

} // namespace

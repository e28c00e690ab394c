// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The SO(3) exponential map, in the generator basis of Rosten et al. (section 2).

#ifndef OPENCV_ESSENTIAL_GEOMETRY_SO3_HPP
#define OPENCV_ESSENTIAL_GEOMETRY_SO3_HPP

#include "simd_dispatch.hpp"

#include <Eigen/Core>

#include <cmath>

namespace cv {
namespace essential {
namespace geometry {

/** [w]x: the skew-symmetric matrix with [w]x v = w x v. */
inline Eigen::Matrix3d skew(const Eigen::Vector3d& w)
{
    Eigen::Matrix3d S;
    S << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
    return S;
}

/** exp([w]x) by Rodrigues' formula, exp([w]x) = I + a [w]x + b [w]x^2 with a = sin(theta) / theta,
b = (1 - cos(theta)) / theta^2 and [w]x^2 = w w^T - theta^2 I.

Below theta = 1 rad (every Gauss-Newton step but a few of the first) a and b come from their Taylor
series instead of sin and cos: through the theta^16 terms the first omitted term is below
1e-17 relative (1 / 19! for a, 1 / 20! for b at theta = 1), so the result is the exponential map
to double precision, at a third of the instructions of the library's sincos (callgrind). The
bound was 0.5 rad with seven terms; the first steps of gn from R = I are often between 0.5 and
1 rad, and two more terms cost less than the sincos they replace (docs/SOLVERS.md, "Cost per
call"). */
ESSENTIAL_INLINE_INTO_CLONES Eigen::Matrix3d expSO3(const Eigen::Vector3d& w)
{
    const double t2 = w.squaredNorm();
    double a, b;
    if (t2 < 1.0) {
        // Horner in theta^2: a = sum (-t2)^k / (2k + 1)!, b = sum (-t2)^k / (2k + 2)!, k = 0..8.
        // The coefficients as constants, so that every step is a multiplication and an addition:
        // written as divisions by (2k)(2k + 1) they stay divisions without -freciprocal-math.
        static constexpr double kA[9] = {1.0,
                                         -1.0 / 6,
                                         1.0 / 120,
                                         -1.0 / 5040,
                                         1.0 / 362880,
                                         -1.0 / 39916800,
                                         1.0 / 6227020800.0,
                                         -1.0 / 1307674368000.0,
                                         1.0 / 355687428096000.0};
        static constexpr double kB[9] = {0.5,
                                         -1.0 / 24,
                                         1.0 / 720,
                                         -1.0 / 40320,
                                         1.0 / 3628800,
                                         -1.0 / 479001600,
                                         1.0 / 87178291200.0,
                                         -1.0 / 20922789888000.0,
                                         1.0 / 6402373705728000.0};
        a = kA[8];
        b = kB[8];
        for (int k = 7; k >= 0; --k) {
            a = a * t2 + kA[k];
            b = b * t2 + kB[k];
        }
    } else {
        const double theta = std::sqrt(t2);
        a = std::sin(theta) / theta;
        b = (1.0 - std::cos(theta)) / t2;
    }
    const double x = w.x(), y = w.y(), z = w.z();
    const double c = 1.0 - b * t2; // the diagonal's I - b theta^2 I
    Eigen::Matrix3d R;
    R << c + b * x * x, b * x * y - a * z, b * x * z + a * y, //
        b * x * y + a * z, c + b * y * y, b * y * z - a * x,  //
        b * x * z - a * y, b * y * z + a * x, c + b * z * z;
    return R;
}

/** The paper's generators are G1 = -[e3]x, G2 = [e2]x, G3 = -[e1]x, so that
exp(d1 G1 + d2 G2 + d3 G3) = exp([w]x) with w = (-d3, d2, -d1). */
ESSENTIAL_INLINE_INTO_CLONES Eigen::Vector3d generatorCoefficientsToAxis(double d1, double d2,
                                                                         double d3)
{
    return Eigen::Vector3d(-d3, d2, -d1);
}

/** exp(d1 G1 + d2 G2 + d3 G3) with the paper's generators. */
ESSENTIAL_INLINE_INTO_CLONES Eigen::Matrix3d expGenerators(double d1, double d2, double d3)
{
    return expSO3(generatorCoefficientsToAxis(d1, d2, d3));
}

/** Projects a nearly orthonormal matrix back onto SO(3) by one step of the polar iteration
R <- (R + R^-T) / 2, enough to remove the round-off that repeated updates accumulate. */
inline void reorthonormalise(Eigen::Matrix3d& R)
{
    R = 0.5 * (R + R.inverse().transpose());
}

} // namespace geometry
} // namespace essential
} // namespace cv

#endif

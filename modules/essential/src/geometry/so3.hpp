// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The SO(3) exponential map, in the generator basis of Rosten et al. (section 2).

#ifndef OPENCV_ESSENTIAL_GEOMETRY_SO3_HPP
#define OPENCV_ESSENTIAL_GEOMETRY_SO3_HPP

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

/** exp([w]x) by Rodrigues' formula; below an angle of 1e-4 rad the series to second order, whose
truncation error (theta^3/6 relative) is then below double precision. */
inline Eigen::Matrix3d expSO3(const Eigen::Vector3d& w)
{
    const double theta2 = w.squaredNorm();
    const Eigen::Matrix3d W = skew(w);
    double a, b;
    if (theta2 < 1e-8) {
        a = 1.0 - theta2 / 6.0;
        b = 0.5 - theta2 / 24.0;
    } else {
        const double theta = std::sqrt(theta2);
        a = std::sin(theta) / theta;
        b = (1.0 - std::cos(theta)) / theta2;
    }
    return Eigen::Matrix3d::Identity() + a * W + b * (W * W);
}

/** The paper's generators are G1 = -[e3]x, G2 = [e2]x, G3 = -[e1]x, so that
exp(d1 G1 + d2 G2 + d3 G3) = exp([w]x) with w = (-d3, d2, -d1). */
inline Eigen::Vector3d generatorCoefficientsToAxis(double d1, double d2, double d3)
{
    return Eigen::Vector3d(-d3, d2, -d1);
}

/** exp(d1 G1 + d2 G2 + d3 G3) with the paper's generators. */
inline Eigen::Matrix3d expGenerators(double d1, double d2, double d3)
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

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// What the iterative minimal-set solvers (gn, lm) share: the random starting pose and the 5x5
// system of residuals and Jacobian of a five-point sample in the 5-DOF parameterisation.

#ifndef OPENCV_ESSENTIAL_SOLVERS_MINIMAL_SET_PROBLEM_HPP
#define OPENCV_ESSENTIAL_SOLVERS_MINIMAL_SET_PROBLEM_HPP

#include "geometry/essential_parameterisation.hpp"

#include <opencv2/core.hpp>

namespace cv {
namespace essential {
namespace solvers {

/** A uniformly distributed unit vector (normalised Gaussian triple). */
inline Eigen::Vector3d randomUnitVector(RNG& rng)
{
    for (;;) {
        Eigen::Vector3d v(rng.gaussian(1.0), rng.gaussian(1.0), rng.gaussian(1.0));
        const double n = v.norm();
        if (n > 1e-6) return v / n;
    }
}

/** The starting point of one optimisation: R = I (the paper notes that the method is very
insensitive to the initial rotation, and small inter-frame rotations are the common case) and a
translation direction drawn uniformly from the sphere. */
inline geometry::EssentialPose randomStart(RNG& rng)
{
    geometry::EssentialPose pose;
    pose.R.setIdentity();
    pose.Rt = geometry::rotationWithFirstColumn(randomUnitVector(rng));
    return pose;
}

/** Residuals r (5) and Jacobian J (5x5) of the sample at pose. Returns the squared norm of r. */
inline double evaluateMinimalSet(const geometry::EssentialPose& pose, const Point2d* x1,
                                 const Point2d* x2, geometry::Vector5d& r, geometry::Matrix5d& J)
{
    const geometry::ResidualFrame frame(pose);
    double row[5];
    for (int i = 0; i < 5; ++i) {
        r[i] = geometry::residualAndJacobian(frame, x1[i].x, x1[i].y, x2[i].x, x2[i].y, row);
        for (int k = 0; k < 5; ++k) J(i, k) = row[k];
    }
    return r.squaredNorm();
}

/** Squared norm of the residuals alone (used by LM to judge a trial step). */
inline double minimalSetCost(const geometry::EssentialPose& pose, const Point2d* x1,
                             const Point2d* x2)
{
    const Eigen::Matrix3d E = pose.E();
    double cost = 0.0;
    for (int i = 0; i < 5; ++i) {
        const double r = geometry::algebraicResidual(E, x1[i].x, x1[i].y, x2[i].x, x2[i].y);
        cost += r * r;
    }
    return cost;
}

} // namespace solvers
} // namespace essential
} // namespace cv

#endif

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Splitting an essential matrix into rotation and translation (by SVD), and the way back to the
// 5-DOF parameterisation.

#ifndef OPENCV_ESSENTIAL_GEOMETRY_ESSENTIAL_DECOMPOSITION_HPP
#define OPENCV_ESSENTIAL_GEOMETRY_ESSENTIAL_DECOMPOSITION_HPP

#include "geometry/essential_parameterisation.hpp"

#include <Eigen/Core>

namespace cv {
namespace essential {
namespace geometry {

/** The two rotations and the translation direction of E = U diag(s, s, 0) V^T:
R1 = U W V^T, R2 = U W^T V^T, t = U e3 (each with det U = det V = +1), so that the four poses
(R1, t), (R1, -t), (R2, t), (R2, -t) are the candidates. Returns false for a matrix with a zero or
non-finite largest singular value. */
bool decomposeEssential(const Eigen::Matrix3d& E, Eigen::Matrix3d& R1, Eigen::Matrix3d& R2,
                        Eigen::Vector3d& t);

/** A 5-DOF pose (R, Rt) with [t]x R proportional to E (up to sign), for refining an essential
matrix that came from any solver. Returns false if E cannot be decomposed. */
bool poseFromEssential(const Eigen::Matrix3d& E, EssentialPose& pose);

/** The essential matrix nearest to M in Frobenius norm, U diag(1, 1, 0) V^T from M's SVD (fixed
size, no allocation). */
Eigen::Matrix3d nearestEssential(const Eigen::Matrix3d& M);

/** E scaled to Frobenius norm sqrt(2) (that of [t]x R with |t| = 1), with the sign chosen so that
its largest-magnitude entry is positive: a canonical form for comparing essential matrices. */
Eigen::Matrix3d canonicalEssential(const Eigen::Matrix3d& E);

} // namespace geometry
} // namespace essential
} // namespace cv

#endif

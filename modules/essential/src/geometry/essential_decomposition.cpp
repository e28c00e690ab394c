// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "geometry/essential_decomposition.hpp"

#include <Eigen/SVD>

#include <cmath>

namespace cv {
namespace essential {
namespace geometry {

bool decomposeEssential(const Eigen::Matrix3d& E, Eigen::Matrix3d& R1, Eigen::Matrix3d& R2,
                        Eigen::Vector3d& t)
{
    if (!E.allFinite()) return false;
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(E, Eigen::ComputeFullU | Eigen::ComputeFullV);
    if (!(svd.singularValues()[0] > 0.0)) return false;
    Eigen::Matrix3d U = svd.matrixU();
    Eigen::Matrix3d V = svd.matrixV();
    if (U.determinant() < 0) U = -U;
    if (V.determinant() < 0) V = -V;
    Eigen::Matrix3d W;
    W << 0, 1, 0, -1, 0, 0, 0, 0, 1;
    R1 = U * W * V.transpose();
    R2 = U * W.transpose() * V.transpose();
    t = U.col(2);
    return true;
}

bool poseFromEssential(const Eigen::Matrix3d& E, EssentialPose& pose)
{
    Eigen::Matrix3d R1, R2;
    Eigen::Vector3d t;
    if (!decomposeEssential(E, R1, R2, t)) return false;
    pose.R = R1;
    pose.Rt = rotationWithFirstColumn(t);
    return true;
}

Eigen::Matrix3d nearestEssential(const Eigen::Matrix3d& M)
{
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
    return svd.matrixU() * Eigen::Vector3d(1.0, 1.0, 0.0).asDiagonal() * svd.matrixV().transpose();
}

Eigen::Matrix3d canonicalEssential(const Eigen::Matrix3d& E)
{
    const double n = E.norm();
    if (!(n > 0.0)) return E;
    Eigen::Matrix3d C = E * (std::sqrt(2.0) / n);
    Eigen::Index i, j;
    C.cwiseAbs().maxCoeff(&i, &j);
    if (C(i, j) < 0) C = -C;
    return C;
}

} // namespace geometry
} // namespace essential
} // namespace cv

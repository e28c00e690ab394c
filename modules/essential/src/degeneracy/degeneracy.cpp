// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "degeneracy/degeneracy.hpp"

#include <Eigen/Dense>

#include <cmath>

namespace cv {
namespace essential {
namespace degeneracy {

namespace {

Eigen::Vector3d bearing(const Point2d& x)
{
    return Eigen::Vector3d(x.x, x.y, 1.0).normalized();
}

} // namespace

double rotationOnlyFraction(const Problem& points, const uchar* mask, double maxDistance)
{
    const int n = points.size();
    Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
    int used = 0;
    for (int i = 0; i < n; ++i) {
        if (!mask[i]) continue;
        M += bearing(points.point2(i)) * bearing(points.point1(i)).transpose();
        ++used;
    }
    if (used < 3) return 0.0;
    // Kabsch: R = U diag(1, 1, det(U V^T)) V^T maximises sum b2^T R b1.
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
    D(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1.0 : 1.0;
    const Eigen::Matrix3d R = svd.matrixU() * D * svd.matrixV().transpose();
    if (!R.allFinite()) return 0.0;
    int explained = 0;
    for (int i = 0; i < n; ++i) {
        if (!mask[i]) continue;
        const Eigen::Vector3d q = R * Eigen::Vector3d(points.x1[i], points.y1[i], 1.0);
        if (!(q.z() > 0.0)) continue; // rotated behind the camera: not explained
        const double dx = q.x() / q.z() - points.x2[i], dy = q.y() / q.z() - points.y2[i];
        explained += dx * dx + dy * dy <= maxDistance * maxDistance;
    }
    return double(explained) / used;
}

double homographyFraction(const Problem& points, const uchar* mask, double maxDistance)
{
    const int n = points.size();
    // Hartley's normalisation: centre each view's points and scale them to mean distance sqrt(2),
    // so that the 9 x 9 normal equations are well conditioned.
    Eigen::Vector2d c1(0, 0), c2(0, 0);
    int used = 0;
    for (int i = 0; i < n; ++i) {
        if (!mask[i]) continue;
        c1 += Eigen::Vector2d(points.x1[i], points.y1[i]);
        c2 += Eigen::Vector2d(points.x2[i], points.y2[i]);
        ++used;
    }
    if (used < 5) return 0.0;
    c1 /= used;
    c2 /= used;
    double d1 = 0, d2 = 0;
    for (int i = 0; i < n; ++i) {
        if (!mask[i]) continue;
        d1 += (Eigen::Vector2d(points.x1[i], points.y1[i]) - c1).norm();
        d2 += (Eigen::Vector2d(points.x2[i], points.y2[i]) - c2).norm();
    }
    if (!(d1 > 0) || !(d2 > 0)) return 0.0;
    const double s1 = std::sqrt(2.0) * used / d1, s2 = std::sqrt(2.0) * used / d2;
    Eigen::Matrix<double, 9, 9> AtA = Eigen::Matrix<double, 9, 9>::Zero();
    for (int i = 0; i < n; ++i) {
        if (!mask[i]) continue;
        const double u = s1 * (points.x1[i] - c1.x()), v = s1 * (points.y1[i] - c1.y());
        const double p = s2 * (points.x2[i] - c2.x()), q = s2 * (points.y2[i] - c2.y());
        Eigen::Matrix<double, 9, 1> a, b;
        a << u, v, 1, 0, 0, 0, -p * u, -p * v, -p;
        b << 0, 0, 0, u, v, 1, -q * u, -q * v, -q;
        AtA.noalias() += a * a.transpose() + b * b.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 9, 9>> eig(AtA);
    const Eigen::Matrix<double, 9, 1> h = eig.eigenvectors().col(0);
    Eigen::Matrix3d Hn;
    Hn << h(0), h(1), h(2), h(3), h(4), h(5), h(6), h(7), h(8);
    Eigen::Matrix3d T1, T2inv;
    T1 << s1, 0, -s1 * c1.x(), 0, s1, -s1 * c1.y(), 0, 0, 1;
    T2inv << 1 / s2, 0, c2.x(), 0, 1 / s2, c2.y(), 0, 0, 1;
    const Eigen::Matrix3d H = T2inv * Hn * T1;
    if (!H.allFinite()) return 0.0;
    int explained = 0;
    for (int i = 0; i < n; ++i) {
        if (!mask[i]) continue;
        const Eigen::Vector3d m = H * Eigen::Vector3d(points.x1[i], points.y1[i], 1.0);
        if (!(std::abs(m.z()) > 1e-12)) continue;
        const double dx = m.x() / m.z() - points.x2[i], dy = m.y() / m.z() - points.y2[i];
        explained += dx * dx + dy * dy <= maxDistance * maxDistance;
    }
    return double(explained) / used;
}

} // namespace degeneracy
} // namespace essential
} // namespace cv

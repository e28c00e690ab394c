// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The unit eigenvector of the smallest eigenvalue of a symmetric positive semi-definite 3 x 3
// matrix, without trigonometry: the iterative solvers need it at every start (the translation that
// best explains a sample), and Eigen's closed form (computeDirect) spends most of its instructions
// in acos, cos and sin for all three eigenvalues.

#ifndef OPENCV_ESSENTIAL_OPTIM_SMALLEST_EIGENVECTOR_HPP
#define OPENCV_ESSENTIAL_OPTIM_SMALLEST_EIGENVECTOR_HPP

#include "simd_dispatch.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry> // cross products

#include <cmath>

namespace cv {
namespace essential {
namespace optim {

/** For S = S^T >= 0: a unit v with S v = lambda_min v.

lambda_min by Newton's method on p(l) = det(S - l I) = -l^3 + a l^2 - b l + c (a = trace,
b = the sum of the principal 2 x 2 minors, c = det S) from l = 0: p has only real roots, all at or
above 0, and Newton's method from the left of the smallest root of such a polynomial rises to it
monotonically (quadratically once near). v is then the longest cross product of two rows of
S - lambda_min I, which span the plane orthogonal to v. Where the two smallest eigenvalues
coincide (S of rank 1 or 0, e.g. all constraint vectors parallel) any unit vector of that plane is
an answer; one orthogonal to S's largest row is returned (e1 for S = 0). */
ESSENTIAL_INLINE_INTO_CLONES Eigen::Vector3d smallestEigenvector(const Eigen::Matrix3d& S)
{
    const double s00 = S(0, 0), s01 = S(1, 0), s02 = S(2, 0), s11 = S(1, 1), s12 = S(2, 1),
                 s22 = S(2, 2);
    const double a = s00 + s11 + s22;
    const double b = s00 * s11 - s01 * s01 + s00 * s22 - s02 * s02 + s11 * s22 - s12 * s12;
    const double c = s00 * (s11 * s22 - s12 * s12) - s01 * (s01 * s22 - s12 * s02) +
                     s02 * (s01 * s12 - s11 * s02);
    double l = 0.0;
    // At most 30 steps: from l = 0 the iterates never pass the root; the measured need is 3 to 8
    // for the starts' matrices (the smallest eigenvalue far below the others), more only where the
    // two smallest nearly coincide and the vector is ill-defined anyway.
    for (int it = 0; it < 30; ++it) {
        const double p = ((-l + a) * l - b) * l + c;
        const double dp = (-3.0 * l + 2.0 * a) * l - b;
        if (!(dp < 0.0)) break; // p' >= 0 only at a double root (or S = 0): l is the root
        const double step = p / dp;
        l -= step;
        if (!(std::abs(step) > 1e-15 * a)) break;
    }
    const Eigen::Vector3d r0(s00 - l, s01, s02), r1(s01, s11 - l, s12), r2(s02, s12, s22 - l);
    const Eigen::Vector3d c01 = r0.cross(r1), c02 = r0.cross(r2), c12 = r1.cross(r2);
    const double n01 = c01.squaredNorm(), n02 = c02.squaredNorm(), n12 = c12.squaredNorm();
    Eigen::Vector3d v = c01;
    double n = n01;
    if (n02 > n) {
        v = c02;
        n = n02;
    }
    if (n12 > n) {
        v = c12;
        n = n12;
    }
    // A relative floor on the cross product: below it the rows are (nearly) parallel, rank <= 1.
    const double scale = a * a;
    if (n > 1e-24 * scale * scale) return v / std::sqrt(n);
    // Rank <= 1: any unit vector orthogonal to the largest row.
    Eigen::Vector3d row = r0;
    if (r1.squaredNorm() > row.squaredNorm()) row = r1;
    if (r2.squaredNorm() > row.squaredNorm()) row = r2;
    if (!(row.squaredNorm() > 0.0)) return Eigen::Vector3d::UnitX();
    const int k = std::abs(row.x()) <= std::abs(row.y()) && std::abs(row.x()) <= std::abs(row.z())
                      ? 0
                      : (std::abs(row.y()) <= std::abs(row.z()) ? 1 : 2);
    return row.cross(Eigen::Vector3d::Unit(k)).normalized();
}

} // namespace optim
} // namespace essential
} // namespace cv

#endif

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The N x N linear solves of the optimisers (N = 5: the 5-DOF essential parameterisation), written
// for a size known at compile time: every loop has constant bounds, so the compiler unrolls them
// and keeps the matrix in registers. Eigen's PartialPivLU and LDLT run their general blocked code
// for fixed sizes too (a run-time-sized Ref inside); on the gn solver's 5 x 5 systems that was a
// third of its instructions (callgrind, docs/SOLVERS.md "Cost per call").

#ifndef OPENCV_ESSENTIAL_OPTIM_SMALL_LINEAR_SOLVE_HPP
#define OPENCV_ESSENTIAL_OPTIM_SMALL_LINEAR_SOLVE_HPP

#include <Eigen/Core>

#include <cmath>
#include <utility>

namespace cv {
namespace essential {
namespace optim {

/** Solves A x = b by Gaussian elimination with partial pivoting (row exchanges by the largest
magnitude in the column, as LAPACK's getrf). Returns false, leaving x unspecified, when a pivot is
zero or not finite: A is singular to working precision or holds a NaN / infinity. A and b are taken
by value: the elimination works in place on the copies. */
template <int N>
inline bool solvePartialPivot(Eigen::Matrix<double, N, N> A, Eigen::Matrix<double, N, 1> b,
                              Eigen::Matrix<double, N, 1>& x)
{
    for (int k = 0; k < N; ++k) {
        int p = k;
        double largest = std::abs(A(k, k));
        for (int i = k + 1; i < N; ++i) {
            const double v = std::abs(A(i, k));
            if (v > largest) {
                largest = v;
                p = i;
            }
        }
        // Also false for a NaN column: every comparison with NaN fails, so largest stays NaN or 0.
        if (!(largest > 0.0) || !std::isfinite(largest)) return false;
        if (p != k) {
            A.row(k).swap(A.row(p));
            std::swap(b[k], b[p]);
        }
        const double inversePivot = 1.0 / A(k, k);
        for (int i = k + 1; i < N; ++i) {
            const double factor = A(i, k) * inversePivot;
            for (int j = k + 1; j < N; ++j)
                A(i, j) -= factor * A(k, j);
            b[i] -= factor * b[k];
        }
    }
    for (int i = N - 1; i >= 0; --i) {
        double sum = b[i];
        for (int j = i + 1; j < N; ++j)
            sum -= A(i, j) * x[j];
        x[i] = sum / A(i, i);
    }
    return true;
}

/** The determinant of A by the same elimination (the product of the pivots, its sign flipped by
each row exchange); 0 when a column has no non-zero pivot, NaN when A holds a NaN. */
template <int N> inline double determinantPartialPivot(Eigen::Matrix<double, N, N> A)
{
    double det = 1.0;
    for (int k = 0; k < N; ++k) {
        int p = k;
        double largest = std::abs(A(k, k));
        for (int i = k + 1; i < N; ++i) {
            const double v = std::abs(A(i, k));
            if (v > largest) {
                largest = v;
                p = i;
            }
        }
        if (std::isnan(largest)) return largest;
        if (largest == 0.0) return 0.0;
        if (p != k) {
            A.row(k).swap(A.row(p));
            det = -det;
        }
        det *= A(k, k);
        const double inversePivot = 1.0 / A(k, k);
        for (int i = k + 1; i < N; ++i) {
            const double factor = A(i, k) * inversePivot;
            for (int j = k + 1; j < N; ++j)
                A(i, j) -= factor * A(k, j);
        }
    }
    return det;
}

/** Solves A x = b for a symmetric positive definite A by its Cholesky factorisation A = L L^T
(only A's lower triangle is read). Returns false, leaving x unspecified, when A is not positive
definite to working precision (a pivot <= 0) or holds a NaN / infinity; the damped normal equations
of Levenberg-Marquardt are positive definite whenever the Jacobian has no zero column. */
template <int N>
inline bool solveCholesky(const Eigen::Matrix<double, N, N>& A,
                          const Eigen::Matrix<double, N, 1>& b, Eigen::Matrix<double, N, 1>& x)
{
    Eigen::Matrix<double, N, N> L;
    for (int j = 0; j < N; ++j) {
        double d = A(j, j);
        for (int k = 0; k < j; ++k)
            d -= L(j, k) * L(j, k);
        if (!(d > 0.0) || !std::isfinite(d)) return false;
        const double ljj = std::sqrt(d), inverse = 1.0 / ljj;
        L(j, j) = ljj;
        for (int i = j + 1; i < N; ++i) {
            double s = A(i, j);
            for (int k = 0; k < j; ++k)
                s -= L(i, k) * L(j, k);
            L(i, j) = s * inverse;
        }
    }
    Eigen::Matrix<double, N, 1> y;
    for (int i = 0; i < N; ++i) {
        double s = b[i];
        for (int k = 0; k < i; ++k)
            s -= L(i, k) * y[k];
        y[i] = s / L(i, i);
    }
    for (int i = N - 1; i >= 0; --i) {
        double s = y[i];
        for (int k = i + 1; k < N; ++k)
            s -= L(k, i) * x[k];
        x[i] = s / L(i, i);
    }
    return true;
}

} // namespace optim
} // namespace essential
} // namespace cv

#endif

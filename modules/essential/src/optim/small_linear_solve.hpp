// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The N x N linear solves of the optimisers (N = 5: the 5-DOF essential parameterisation), written
// for a size known at compile time: every loop has constant bounds, so the compiler unrolls them
// and keeps the matrix in registers. Eigen's PartialPivLU and LDLT run their general blocked code
// for fixed sizes too (a run-time-sized Ref inside); on the gn solver's 5 x 5 systems that was a
// third of its instructions (callgrind, docs/SOLVERS.md "Cost per call").

#ifndef OPENCV_ESSENTIAL_OPTIM_SMALL_LINEAR_SOLVE_HPP
#define OPENCV_ESSENTIAL_OPTIM_SMALL_LINEAR_SOLVE_HPP

#include "simd_dispatch.hpp"

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <utility>

/** Unrolls the loop that follows completely (GCC and Clang). GCC at -O3 leaves these nested loops
of constant trip count rolled: unrolling the elimination took the gn solver from 20.8 k to 19.4 k
instructions per call (callgrind, docs/SOLVERS.md "Cost per call"); the same pragma on the
residual loop of the five points made it slower. */
#if defined(__GNUC__)
#define ESSENTIAL_UNROLL _Pragma("GCC unroll 8")
#else
#define ESSENTIAL_UNROLL
#endif

namespace cv {
namespace essential {
namespace optim {

/** The pivot of column k: the row at or below k with the largest magnitude there (the first of
equal ones), or -1 when it is not a usable pivot. That is also the case for a NaN column (every
comparison with NaN fails, so the largest stays NaN or 0) and an infinite pivot, whose zero
multipliers would hide it from the solution. */
template <int N> inline int pivotRow(const Eigen::Matrix<double, N, N>& A, int k)
{
    int p = k;
    double largest = std::abs(A(k, k));
    ESSENTIAL_UNROLL
    for (int i = k + 1; i < N; ++i) {
        const double v = std::abs(A(i, k));
        if (v > largest) {
            largest = v;
            p = i;
        }
    }
    return largest > 0.0 && std::isfinite(largest) ? p : -1;
}

/** LU factorisation with partial pivoting in place (row exchanges by the largest magnitude in the
column, as LAPACK's getrf): on return A holds U on and above the diagonal and the multipliers
below it, and row k was exchanged with row pivot[k] at step k; `sign` is the permutation's sign.
Returns false at a column with no non-zero pivot (singular to working precision) or a pivot that
is not finite; A is then only partly reduced. */
template <int N>
inline bool factorPartialPivot(Eigen::Matrix<double, N, N>& A, int pivot[N], double& sign)
{
    sign = 1.0;
    for (int k = 0; k < N; ++k) {
        const int p = pivotRow<N>(A, k);
        if (p < 0) return false;
        pivot[k] = p;
        if (p != k) {
            A.row(k).swap(A.row(p));
            sign = -sign;
        }
        const double inversePivot = 1.0 / A(k, k);
        for (int i = k + 1; i < N; ++i) {
            const double factor = A(i, k) * inversePivot;
            A(i, k) = factor;
            for (int j = k + 1; j < N; ++j)
                A(i, j) -= factor * A(k, j);
        }
    }
    return true;
}

/** Solves A x = b by that factorisation: Gaussian elimination on the rows [A | b] with the pivots
of factorPartialPivot, followed by the substitution, so the same x to the bit as getrf and getrs,
but without storing the multipliers. The pivot is brought up by conditional exchanges: each row
below k is compared with row k, and the two are exchanged when the lower one is larger in magnitude
in column k, so row k ends with the first of the largest, as pivotRow picks it. The rows below are
then in another order than getrf leaves them, which changes nothing unless two of them tie for a
later pivot. The comparisons become selects with constant indices, so that the rows stay in
registers; a row exchange with an index known only at run time made the matrix live in memory (a
quarter fewer instructions for the 5 x 5 and 8 x 8 solves, callgrind, docs/SOLVERS.md "Cost per
call"). Returns false, leaving x unspecified, when A is singular to working precision or the
solution is not finite (A or b held a NaN or an infinity, or A is so near singular that x
overflows). A and b are taken by value: the elimination works on the copies. (Storing A by rows cost
the gn solver 4 k more instructions per call.) */
template <int N>
ESSENTIAL_INLINE_INTO_CLONES bool solvePartialPivot(Eigen::Matrix<double, N, N> A,
                                                    Eigen::Matrix<double, N, 1> b,
                                                    Eigen::Matrix<double, N, 1>& x)
{
    ESSENTIAL_UNROLL
    for (int k = 0; k < N; ++k) {
        ESSENTIAL_UNROLL
        for (int i = k + 1; i < N; ++i) {
            // false for a NaN: a NaN never becomes the pivot, as in pivotRow
            const bool exchange = std::abs(A(i, k)) > std::abs(A(k, k));
            ESSENTIAL_UNROLL
            for (int j = k; j < N; ++j) {
                const double upper = A(k, j), lower = A(i, j);
                A(k, j) = exchange ? lower : upper;
                A(i, j) = exchange ? upper : lower;
            }
            const double upper = b[k], lower = b[i];
            b[k] = exchange ? lower : upper;
            b[i] = exchange ? upper : lower;
        }
        const double pivot = A(k, k);
        // pivotRow's refusal: no non-zero pivot in the column, or an infinite or NaN one
        if (!(std::abs(pivot) > 0.0) || !std::isfinite(pivot)) return false;
        const double inversePivot = 1.0 / pivot;
        ESSENTIAL_UNROLL
        for (int i = k + 1; i < N; ++i) {
            const double factor = A(i, k) * inversePivot;
            ESSENTIAL_UNROLL
            for (int j = k + 1; j < N; ++j)
                A(i, j) -= factor * A(k, j);
            b[i] -= factor * b[k];
        }
    }
    ESSENTIAL_UNROLL
    for (int i = N - 1; i >= 0; --i) {
        double sum = b[i];
        ESSENTIAL_UNROLL
        for (int j = i + 1; j < N; ++j)
            sum -= A(i, j) * x[j];
        x[i] = sum / A(i, i);
    }
    return x.allFinite();
}

/** The determinant of A by the same factorisation (the product of the pivots and the sign of the
row exchanges): 0 when a column has no non-zero pivot, NaN when A is not finite. */
template <int N> inline double determinantPartialPivot(Eigen::Matrix<double, N, N> A)
{
    if (!A.allFinite()) return std::numeric_limits<double>::quiet_NaN();
    int pivot[N];
    double sign;
    if (!factorPartialPivot<N>(A, pivot, sign)) return 0.0;
    double det = sign;
    for (int k = 0; k < N; ++k)
        det *= A(k, k);
    return det;
}

/** Solves A x = b for a symmetric positive definite A by its Cholesky factorisation A = L L^T
(only A's lower triangle is read). Returns false, leaving x unspecified, when A is not positive
definite to working precision (a pivot <= 0) or holds a NaN / infinity; the damped normal equations
of Levenberg-Marquardt are positive definite whenever the Jacobian has no zero column. */
template <int N>
ESSENTIAL_INLINE_INTO_CLONES bool solveCholesky(const Eigen::Matrix<double, N, N>& A,
                                                const Eigen::Matrix<double, N, 1>& b,
                                                Eigen::Matrix<double, N, 1>& x)
{
    Eigen::Matrix<double, N, N> L;
    ESSENTIAL_UNROLL
    for (int j = 0; j < N; ++j) {
        double d = A(j, j);
        ESSENTIAL_UNROLL
        for (int k = 0; k < j; ++k)
            d -= L(j, k) * L(j, k);
        if (!(d > 0.0) || !std::isfinite(d)) return false;
        const double ljj = std::sqrt(d), inverse = 1.0 / ljj;
        L(j, j) = ljj;
        ESSENTIAL_UNROLL
        for (int i = j + 1; i < N; ++i) {
            double s = A(i, j);
            ESSENTIAL_UNROLL
            for (int k = 0; k < j; ++k)
                s -= L(i, k) * L(j, k);
            L(i, j) = s * inverse;
        }
    }
    Eigen::Matrix<double, N, 1> y;
    ESSENTIAL_UNROLL
    for (int i = 0; i < N; ++i) {
        double s = b[i];
        ESSENTIAL_UNROLL
        for (int k = 0; k < i; ++k)
            s -= L(i, k) * y[k];
        y[i] = s / L(i, i);
    }
    ESSENTIAL_UNROLL
    for (int i = N - 1; i >= 0; --i) {
        double s = y[i];
        ESSENTIAL_UNROLL
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

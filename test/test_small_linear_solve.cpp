// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The fixed-size solves of the optimisers (optim/small_linear_solve.hpp) and the 3 x 3 smallest
// eigenvector (optim/smallest_eigenvector.hpp) against Eigen's general decompositions: the same
// solutions, determinants and eigenvectors to round-off on well-conditioned systems, and a refusal
// (false, or a zero determinant) where the system has no unique solution.

#include "optim/small_linear_solve.hpp"
#include "optim/smallest_eigenvector.hpp"

#include "essential_test.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <limits>
#include <random>
#include <utility>

namespace {

using namespace cv::essential::optim;
typedef Eigen::Matrix<double, 5, 5> Matrix5d;
typedef Eigen::Matrix<double, 5, 1> Vector5d;

Matrix5d randomMatrix(std::mt19937_64& g)
{
    std::normal_distribution<double> n(0.0, 1.0);
    Matrix5d A;
    for (int i = 0; i < 25; ++i)
        A.data()[i] = n(g);
    return A;
}

Vector5d randomVector(std::mt19937_64& g)
{
    std::normal_distribution<double> n(0.0, 1.0);
    Vector5d b;
    for (int i = 0; i < 5; ++i)
        b[i] = n(g);
    return b;
}

} // namespace

TEST(SmallLinearSolve, PartialPivotSolvesAsEigenDoes)
{
    // Relative to the solution and the condition number: |x - x_eigen| <= 1e-13 cond(A) |x|
    // (backward-stable elimination; measured at most 2e-15 cond |x| over these 2000 systems).
    std::mt19937_64 g(1);
    for (int i = 0; i < 2000; ++i) {
        const Matrix5d A = randomMatrix(g);
        const Vector5d b = randomVector(g);
        Vector5d x;
        ASSERT_TRUE(solvePartialPivot<5>(A, b, x));
        const Vector5d expected = A.fullPivLu().solve(b);
        const double cond = A.norm() * A.inverse().norm();
        EXPECT_LE((x - expected).norm(), 1e-13 * cond * expected.norm()) << "system " << i;
        EXPECT_LE((A * x - b).norm(), 1e-12 * (A.norm() * x.norm() + b.norm())) << "system " << i;
    }
}

// The fused elimination is the factorisation followed by getrs's substitutions, to the bit.
TEST(SmallLinearSolve, EliminationEqualsFactorisationAndSubstitution)
{
    std::mt19937_64 g(3);
    for (int i = 0; i < 2000; ++i) {
        const Matrix5d A = randomMatrix(g);
        const Vector5d b = randomVector(g);
        Matrix5d LU = A;
        int pivot[5];
        double sign;
        ASSERT_TRUE(factorPartialPivot<5>(LU, pivot, sign));
        Vector5d y = b, expected;
        for (int k = 0; k < 5; ++k)
            std::swap(y[k], y[pivot[k]]);
        for (int k = 0; k < 5; ++k)
            for (int r = k + 1; r < 5; ++r)
                y[r] -= LU(r, k) * y[k];
        for (int r = 4; r >= 0; --r) {
            double sum = y[r];
            for (int j = r + 1; j < 5; ++j)
                sum -= LU(r, j) * expected[j];
            expected[r] = sum / LU(r, r);
        }
        Vector5d x;
        ASSERT_TRUE(solvePartialPivot<5>(A, b, x));
        for (int k = 0; k < 5; ++k)
            ASSERT_EQ(x[k], expected[k]) << "system " << i << " entry " << k;
    }
}

TEST(SmallLinearSolve, PartialPivotRefusesSingularAndNonFiniteSystems)
{
    std::mt19937_64 g(2);
    Matrix5d A = randomMatrix(g);
    A.col(3).setZero(); // a zero column: no pivot in it
    Vector5d x;
    EXPECT_FALSE(solvePartialPivot<5>(A, randomVector(g), x));
    A = randomMatrix(g);
    A.row(4) = 2.0 * A.row(1) - A.row(0); // exact dependence; 0 pivot after elimination or tiny
    const bool solved = solvePartialPivot<5>(A, randomVector(g), x);
    // Round-off may leave a tiny last pivot: then the solution is huge, never a plausible step.
    if (solved) {
        EXPECT_GT(x.norm(), 1e10);
    }
    A = randomMatrix(g);
    A(2, 2) = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(solvePartialPivot<5>(A, randomVector(g), x));
    A = randomMatrix(g);
    A(0, 0) = std::numeric_limits<double>::infinity();
    EXPECT_FALSE(solvePartialPivot<5>(A, randomVector(g), x));
}

TEST(SmallLinearSolve, DeterminantAsEigen)
{
    std::mt19937_64 g(3);
    for (int i = 0; i < 2000; ++i) {
        const Matrix5d A = randomMatrix(g);
        const double expected = A.fullPivLu().determinant();
        EXPECT_NEAR(determinantPartialPivot<5>(A), expected, 1e-12 * (1.0 + std::abs(expected)));
    }
    Matrix5d A = randomMatrix(g);
    A.col(0).setZero();
    EXPECT_EQ(determinantPartialPivot<5>(A), 0.0);
    A = randomMatrix(g);
    A(1, 0) = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(std::isnan(determinantPartialPivot<5>(A)));
}

TEST(SmallLinearSolve, CholeskySolvesPositiveDefiniteSystemsAsEigen)
{
    // Normal equations J^T J (+ damping), as the optimisers build them.
    std::mt19937_64 g(4);
    for (int i = 0; i < 2000; ++i) {
        const Matrix5d J = randomMatrix(g);
        Matrix5d A = J.transpose() * J;
        A.diagonal() *= 1.0 + (i % 3 == 0 ? 0.0 : 1e-3);
        const Vector5d b = randomVector(g);
        Vector5d x;
        ASSERT_TRUE(solveCholesky<5>(A, b, x)) << "system " << i;
        const Vector5d expected = A.ldlt().solve(b);
        const double cond = A.norm() * A.inverse().norm();
        EXPECT_LE((x - expected).norm(), 1e-13 * cond * expected.norm()) << "system " << i;
    }
}

TEST(SmallLinearSolve, CholeskyRefusesWhatIsNotPositiveDefinite)
{
    std::mt19937_64 g(5);
    Matrix5d J = randomMatrix(g);
    J.col(2).setZero(); // J^T J then has a zero row and column
    Vector5d x;
    EXPECT_FALSE(solveCholesky<5>(Matrix5d(J.transpose() * J), randomVector(g), x));
    Matrix5d indefinite = Matrix5d::Identity();
    indefinite(3, 3) = -1.0;
    EXPECT_FALSE(solveCholesky<5>(indefinite, randomVector(g), x));
    Matrix5d nan = Matrix5d::Identity();
    nan(4, 4) = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(solveCholesky<5>(nan, randomVector(g), x));
}

TEST(SmallestEigenvector, AsEigensIterativeSolverOnPositiveSemiDefiniteMatrices)
{
    // Sums of five outer products c c^T, as the translation start builds them, and rank-2 ones
    // (a zero eigenvalue): the eigenvector of the smallest eigenvalue agrees with Eigen's
    // (iterative QL) solver up to sign, |v . v_eigen| >= 1 - 1e-10, wherever the two smallest
    // eigenvalues are apart by more than 1e-6 of the largest; S v = lambda_min v to 1e-12 of it.
    std::mt19937_64 g(6);
    std::normal_distribution<double> n(0.0, 1.0);
    int checked = 0;
    for (int i = 0; i < 4000; ++i) {
        Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
        const int terms = i % 4 == 0 ? 2 : 5;
        const double shrink = i % 3 == 0 ? 1e-3 : 1.0; // small smallest eigenvalues too
        for (int k = 0; k < terms; ++k) {
            Eigen::Vector3d c(n(g), n(g), shrink * n(g));
            S += c * c.transpose();
        }
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(S);
        const Eigen::Vector3d lambda = eig.eigenvalues();
        const Eigen::Vector3d v = cv::essential::optim::smallestEigenvector(S);
        EXPECT_NEAR(v.norm(), 1.0, 1e-14);
        EXPECT_LE((S * v - lambda[0] * v).norm(), 1e-12 * lambda[2]) << "matrix " << i;
        if (lambda[1] - lambda[0] > 1e-6 * lambda[2]) {
            EXPECT_GE(std::abs(v.dot(eig.eigenvectors().col(0))), 1.0 - 1e-10) << "matrix " << i;
            ++checked;
        }
    }
    EXPECT_GT(checked, 3900);
}

TEST(SmallestEigenvector, RankOneAndZeroMatrices)
{
    const Eigen::Vector3d c(1.0, 2.0, -0.5);
    const Eigen::Vector3d v =
        cv::essential::optim::smallestEigenvector(Eigen::Matrix3d(c * c.transpose()));
    EXPECT_NEAR(v.norm(), 1.0, 1e-14);
    EXPECT_LT(std::abs(v.dot(c)), 1e-14); // any unit vector orthogonal to c
    const Eigen::Vector3d zero = cv::essential::optim::smallestEigenvector(Eigen::Matrix3d::Zero());
    EXPECT_NEAR(zero.norm(), 1.0, 1e-14);
}

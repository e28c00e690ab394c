// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The fixed-size solves of the optimisers (optim/small_linear_solve.hpp) against Eigen's general
// decompositions: the same solutions and determinants to round-off on well-conditioned systems,
// and a refusal (false, or a zero determinant) where the system has no unique solution.

#include "optim/small_linear_solve.hpp"

#include "essential_test.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <limits>
#include <random>

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

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The one implementation of the Sampson distance (geometry/sampson.hpp) against its definition,
// and the places that use it: scoring and the 5-DOF Jacobian agree with it exactly.

#include "geometry/essential_parameterisation.hpp"
#include "geometry/sampson.hpp"
#include "geometry/so3.hpp"
#include "geometry/symmetric_epipolar.hpp"
#include "input/problem.hpp"
#include "scoring/msac_score.hpp"

#include "essential_test.hpp"

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using namespace cv::essential::geometry;

Eigen::Matrix3d randomEssential(std::mt19937_64& g)
{
    std::normal_distribution<double> n(0.0, 1.0);
    EssentialPose p;
    p.R = expSO3(Eigen::Vector3d(n(g), n(g), n(g)));
    p.Rt = expSO3(Eigen::Vector3d(n(g), n(g), n(g)) * 2.0);
    return p.E();
}

/** The epipolar residual r = q2^T E q1 of a correspondence, the squared lengths D1 of the first two
entries of E^T q2 and D2 of E q1 (the Sampson and symmetric distances' denominators), and the
magnitudes that bound their rounding: M, the sum of |r|'s terms, and A1, A2, the same sums of
squares with every term of the line entries taken by magnitude. */
struct EpipolarMagnitudes
{
    double r = 0.0, M = 0.0, D1 = 0.0, D2 = 0.0, A1 = 0.0, A2 = 0.0;
};

template <class Matrix>
EpipolarMagnitudes epipolarMagnitudes(const Matrix& E, const cv::Point2d& p1, const cv::Point2d& p2)
{
    const double q1[3] = {p1.x, p1.y, 1.0}, q2[3] = {p2.x, p2.y, 1.0};
    EpipolarMagnitudes m;
    for (int k = 0; k < 3; ++k) {
        double line2 = 0.0, line2Abs = 0.0, line1 = 0.0, line1Abs = 0.0; // E q1, E^T q2
        for (int j = 0; j < 3; ++j) {
            m.M += std::abs(q2[k] * E(k, j) * q1[j]);
            m.r += q2[k] * E(k, j) * q1[j];
            line2 += E(k, j) * q1[j];
            line2Abs += std::abs(E(k, j) * q1[j]);
            line1 += E(j, k) * q2[j];
            line1Abs += std::abs(E(j, k) * q2[j]);
        }
        if (k < 2) {
            m.D2 += line2 * line2;
            m.A2 += line2Abs * line2Abs;
            m.D1 += line1 * line1;
            m.A1 += line1Abs * line1Abs;
        }
    }
    return m;
}

double algebraic(const Eigen::Matrix3d& E, const double v[4])
{
    return Eigen::Vector3d(v[2], v[3], 1.0).dot(E * Eigen::Vector3d(v[0], v[1], 1.0));
}

TEST(Sampson, IsTheResidualOverTheNormOfItsGradient)
{
    // The definition: the squared Sampson distance of a correspondence v = (x1, y1, x2, y2) is
    // r(v)^2 / |dr/dv|^2, r = q2^T E q1. The gradient is taken here by central differences of r,
    // independently of the closed form (r is bilinear, so the difference is exact up to rounding:
    // relative errors measured below 1e-9 over these 500 cases).
    std::mt19937_64 g(21);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    for (int trial = 0; trial < 500; ++trial) {
        const Eigen::Matrix3d E = randomEssential(g);
        double v[4] = {u(g), u(g), u(g), u(g)};
        const double h = 1e-5;
        double gradient2 = 0.0;
        for (int k = 0; k < 4; ++k) {
            double plus[4] = {v[0], v[1], v[2], v[3]}, minus[4] = {v[0], v[1], v[2], v[3]};
            plus[k] += h;
            minus[k] -= h;
            const double d = (algebraic(E, plus) - algebraic(E, minus)) / (2 * h);
            gradient2 += d * d;
        }
        const double r = algebraic(E, v);
        const double expected = r * r / gradient2;
        const double got = sampsonSquared(E, v[0], v[1], v[2], v[3]);
        EXPECT_NEAR(got, expected, 1e-8 * expected + 1e-300) << "trial " << trial;
        const SampsonTerms t = sampsonTerms(EssentialEntries(E), v[0], v[1], v[2], v[3]);
        EXPECT_NEAR(t.r, r, 1e-12 * (1 + std::abs(r)));
        EXPECT_NEAR(t.D, gradient2, 1e-8 * gradient2);
    }
}

TEST(Sampson, ScaledGradientIsTheDerivativeWithRespectToE)
{
    // sampsonScaledGradient gives G = sqrt(D) ds/dE for s = r / sqrt(D); compare with central
    // differences of s over each entry of E (step 1e-6; the error is O(h^2) ~ 1e-12 relative to
    // the second derivatives, which are O(1) for these points away from the epipoles).
    std::mt19937_64 g(22);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const double h = 1e-6;
    for (int trial = 0; trial < 200; ++trial) {
        const Eigen::Matrix3d E = randomEssential(g);
        const double x1 = u(g), y1 = u(g), x2 = u(g), y2 = u(g);
        const SampsonTerms t = sampsonTerms(EssentialEntries(E), x1, y1, x2, y2);
        ASSERT_GT(t.D, 0.0);
        const double sqrtD = std::sqrt(t.D);
        double G[8];
        sampsonScaledGradient(t, t.r / t.D, x1, y1, x2, y2, G);
        const double full[9] = {G[0], G[1], G[2], G[3], G[4], G[5], G[6], G[7], 1.0};
        auto s = [&](const Eigen::Matrix3d& F) {
            const SampsonTerms ft = sampsonTerms(EssentialEntries(F), x1, y1, x2, y2);
            return ft.r / std::sqrt(ft.D);
        };
        for (int k = 0; k < 9; ++k) {
            Eigen::Matrix3d plus = E, minus = E;
            plus(k / 3, k % 3) += h;
            minus(k / 3, k % 3) -= h;
            const double numeric = (s(plus) - s(minus)) / (2 * h);
            EXPECT_NEAR(full[k] / sqrtD, numeric, 1e-7 * (1.0 + std::abs(numeric)))
                << "entry " << k << " trial " << trial;
        }
        // Contracting with the unit matrices picks out the same entries.
        for (int k = 0; k < 9; ++k) {
            double unit[9] = {};
            unit[k] = 1.0;
            EXPECT_EQ(contractScaledGradient(G, unit), full[k]);
        }
    }
}

TEST(Sampson, ScoringAndTheJacobianUseTheSameDistance)
{
    // The scoring loop (vectorised, in the library's AVX2 / FMA clone on such a CPU) and the
    // refinement's residual call the same inline code, so they may differ only by the compiler's
    // contraction of the same expression into fused multiply-adds, which round a product and a sum
    // once instead of twice: in r = q2^T E q1 by at most a few units in the last place of the sum
    // of its terms' magnitudes M, in D by as many of the magnitudes' sum of squares A. Another
    // distance (the symmetric epipolar one, or r^2 alone) is off by far more than the bound.
    std::mt19937_64 g(23);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::normal_distribution<double> n(0.0, 1.0);
    std::vector<cv::Point2d> p1(300), p2(300);
    for (size_t i = 0; i < p1.size(); ++i) {
        p1[i] = cv::Point2d(u(g), u(g));
        p2[i] = cv::Point2d(u(g), u(g));
    }
    const cv::essential::Problem problem = cv::essential::makeProblem(p1, p2);
    EssentialPose pose;
    pose.R = expSO3(Eigen::Vector3d(n(g), n(g), n(g)));
    pose.Rt = expSO3(Eigen::Vector3d(n(g), n(g), n(g)));
    const EssentialDerivatives d(pose);
    cv::Matx33d Ecv;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            Ecv(i, j) = d.E(i, j);
    std::vector<double> errors(p1.size());
    cv::essential::scoring::sampsonErrors(Ecv, problem, errors.data());
    for (size_t i = 0; i < p1.size(); ++i) {
        const double reference = sampsonSquared(d.E, p1[i].x, p1[i].y, p2[i].x, p2[i].y);
        const EpipolarMagnitudes m = epipolarMagnitudes(d.E, p1[i], p2[i]);
        const double eps = std::numeric_limits<double>::epsilon();
        const double bound =
            16.0 * eps * (2.0 * std::abs(m.r) * m.M + reference * (m.A1 + m.A2)) / (m.D1 + m.D2);
        EXPECT_NEAR(errors[i], reference, bound + 1e-14 * reference) << i;
        double s, J[5];
        ASSERT_TRUE(sampsonResidualAndJacobian(d, p1[i].x, p1[i].y, p2[i].x, p2[i].y, s, J));
        EXPECT_NEAR(s * s, reference, 1e-14 * reference) << i;
    }
}

TEST(SymmetricEpipolar, IsTheSumOfTheTwoPointToLineDistances)
{
    // d1 = distance of q2 to the line E q1 in image 2, d2 = distance of q1 to E^T q2 in image 1,
    // computed here from the lines directly; OpenCV's USAC thresholds d1^2 + d2^2. It is at least
    // four times the squared Sampson distance (1/D1 + 1/D2 >= 4 / (D1 + D2)).
    std::mt19937_64 g(24);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 500; ++trial) {
        const Eigen::Matrix3d E = randomEssential(g);
        const Eigen::Vector3d q1(u(g), u(g), 1.0), q2(u(g), u(g), 1.0);
        const Eigen::Vector3d l2 = E * q1, l1 = E.transpose() * q2;
        const double d1 = std::abs(l2.dot(q2)) / l2.head<2>().norm();
        const double d2 = std::abs(l1.dot(q1)) / l1.head<2>().norm();
        const double got =
            symmetricEpipolarSquared(EssentialEntries(E), q1.x(), q1.y(), q2.x(), q2.y());
        const double expected = d1 * d1 + d2 * d2;
        EXPECT_NEAR(got, expected, 1e-12 * expected) << "trial " << trial;
        EXPECT_GE(got * (1 + 1e-12), 4.0 * sampsonSquared(E, q1.x(), q1.y(), q2.x(), q2.y()));
    }
}

TEST(SymmetricEpipolar, ScoringUsesTheProblemsDistance)
{
    std::mt19937_64 g(25);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<cv::Point2d> p1(100), p2(100);
    for (size_t i = 0; i < p1.size(); ++i) {
        p1[i] = cv::Point2d(u(g), u(g));
        p2[i] = cv::Point2d(u(g), u(g));
    }
    const Eigen::Matrix3d E = randomEssential(g);
    cv::Matx33d Ecv;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            Ecv(i, j) = E(i, j);
    const auto symmetric = cv::essential::makeProblem(p1, p2);
    const cv::essential::InlierTest test{0.05, cv::essential::DISTANCE_SYMMETRIC_EPIPOLAR};
    std::vector<double> d(p1.size());
    cv::essential::scoring::squaredDistances(Ecv, symmetric, test, d.data());
    std::vector<uchar> mask(p1.size());
    const int inliers = cv::essential::scoring::inlierMask(Ecv, symmetric, test, mask.data());
    int expected = 0;
    for (size_t i = 0; i < p1.size(); ++i) {
        const double ref =
            symmetricEpipolarSquared(EssentialEntries(E), p1[i].x, p1[i].y, p2[i].x, p2[i].y);
        // The scoring loop may run in the library's FMA clone (see
        // ScoringAndTheJacobianUseTheSameDistance): a few ulps of r's and the lines' magnitudes.
        const EpipolarMagnitudes m = epipolarMagnitudes(E, p1[i], p2[i]);
        const double eps = std::numeric_limits<double>::epsilon();
        const double bound =
            16.0 * eps * ref * (2.0 * m.M / std::abs(m.r) + m.A1 / m.D1 + m.A2 / m.D2);
        EXPECT_NEAR(d[i], ref, bound + 1e-14 * ref);
        EXPECT_EQ(mask[i], ref <= 0.05 * 0.05 ? 1 : 0);
        expected += ref <= 0.05 * 0.05;
    }
    EXPECT_EQ(inliers, expected);
    EXPECT_GT(inliers, 0);
}

} // namespace

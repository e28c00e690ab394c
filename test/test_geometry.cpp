// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The SO(3) exponential map and the 5-DOF essential parameterisation: algebraic properties, and
// the analytic Jacobians (paper equations 3 and 4, the Sampson residual, and the epipolar
// distances of equation 5) against central finite differences.

#include "geometry/essential_decomposition.hpp"
#include "geometry/essential_parameterisation.hpp"
#include "geometry/sampson.hpp"
#include "geometry/so3.hpp"

#include "essential_test.hpp"

#include <cstdio>
#include <random>

namespace {

using namespace cv::essential::geometry;

Eigen::Vector3d randomVector(std::mt19937_64& g, double scale)
{
    std::normal_distribution<double> n(0.0, scale);
    return Eigen::Vector3d(n(g), n(g), n(g));
}

EssentialPose randomPose(std::mt19937_64& g)
{
    EssentialPose p;
    p.R = expSO3(randomVector(g, 1.0));
    p.Rt = expSO3(randomVector(g, 2.0));
    return p;
}

/** Central difference of f(pose) along parameter k of the 5-DOF update, step h. */
template <class F> double centralDifference(const EssentialPose& p, int k, double h, F f)
{
    Vector5d d = Vector5d::Zero();
    d[k] = h;
    EssentialPose plus = p, minus = p;
    plus.update(d);
    minus.update(-d);
    return (f(plus) - f(minus)) / (2 * h);
}

TEST(SO3, ExpIsARotation)
{
    std::mt19937_64 g(1);
    for (int i = 0; i < 200; ++i) {
        const double scale = i < 100 ? 1.0 : 1e-5; // large angles and the small-angle branch
        const Eigen::Matrix3d R = expSO3(randomVector(g, scale));
        EXPECT_LT((R.transpose() * R - Eigen::Matrix3d::Identity()).norm(), 1e-14);
        EXPECT_NEAR(R.determinant(), 1.0, 1e-14);
    }
}

TEST(SO3, ExpRotatesByTheAngleAboutTheAxis)
{
    std::mt19937_64 g(2);
    for (int i = 0; i < 100; ++i) {
        const Eigen::Vector3d w = randomVector(g, 1.0);
        const Eigen::Matrix3d R = expSO3(w);
        EXPECT_LT((R * w - w).norm(), 1e-13 * (1 + w.norm())); // the axis is fixed
        const double angle = std::acos(std::min(1.0, std::max(-1.0, (R.trace() - 1.0) / 2.0)));
        const double expected = std::fmod(w.norm(), 2 * M_PI);
        EXPECT_NEAR(angle, expected > M_PI ? 2 * M_PI - expected : expected, 1e-7);
    }
}

TEST(SO3, ExpOfOppositeIsInverseAndSmallAngleIsContinuous)
{
    std::mt19937_64 g(3);
    for (int i = 0; i < 100; ++i) {
        const Eigen::Vector3d w = randomVector(g, 1.0);
        EXPECT_LT((expSO3(w) * expSO3(-w) - Eigen::Matrix3d::Identity()).norm(), 1e-14);
    }
    // Both sides of the series/Rodrigues switch (theta = 0.5) agree.
    const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, 3).normalized();
    const Eigen::Matrix3d below = expSO3(axis * (0.5 - 1e-12)),
                          above = expSO3(axis * (0.5 + 1e-12));
    EXPECT_LT((below - above).norm(), 1e-11);
    const Eigen::Matrix3d tiny = expSO3(axis * 1e-9);
    EXPECT_LT((tiny - (Eigen::Matrix3d::Identity() + skew(axis * 1e-9))).norm(), 1e-17);
}

namespace {

/** exp([w]x) by Rodrigues' formula in long double: the reference for the double-precision map. */
Eigen::Matrix3d referenceExp(const Eigen::Vector3d& w)
{
    const long double x = w.x(), y = w.y(), z = w.z();
    const long double t2 = x * x + y * y + z * z, t = std::sqrt(t2);
    const long double a = std::sin(t) / t, b = (1.0L - std::cos(t)) / t2;
    const long double W[3][3] = {{0, -z, y}, {z, 0, -x}, {-y, x, 0}};
    Eigen::Matrix3d R;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            long double w2 = 0;
            for (int k = 0; k < 3; ++k)
                w2 += W[i][k] * W[k][j];
            R(i, j) = static_cast<double>((i == j ? 1.0L : 0.0L) + a * W[i][j] + b * w2);
        }
    return R;
}

} // namespace

TEST(SO3, SeriesBranchIsTheExponentialToDoublePrecision)
{
    // Below 1 rad expSO3 takes sin(t)/t and (1 - cos t)/t^2 from their Taylor series: against
    // Rodrigues' formula in long double every entry agrees to a few units of double rounding
    // (the bound 4e-16 is four ulps of 1). The Rodrigues branch in double, from 1 to 3 rad, is held
    // to 8e-16: its worst entry here is 5.6e-16, the rounding of sin and cos near 1 and 3 rad.
    std::mt19937_64 g(4);
    std::uniform_real_distribution<double> angle(1e-6, 1.0);
    double worstSeries = 0, worstRodrigues = 0;
    for (int i = 0; i < 2000; ++i) {
        const Eigen::Vector3d axis = randomVector(g, 1.0).normalized();
        const Eigen::Vector3d w = axis * angle(g);
        worstSeries = std::max(worstSeries, (expSO3(w) - referenceExp(w)).cwiseAbs().maxCoeff());
        const Eigen::Vector3d v = axis * (1.0 + 2.0 * angle(g));
        worstRodrigues =
            std::max(worstRodrigues, (expSO3(v) - referenceExp(v)).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(worstSeries, 4e-16);
    EXPECT_LT(worstRodrigues, 8e-16);
}

TEST(SO3, GeneratorsMatchThePaper)
{
    // G1 = [0 1 0; -1 0 0; 0 0 0], G2 = [0 0 1; 0 0 0; -1 0 0], G3 = [0 0 0; 0 0 1; 0 -1 0].
    Eigen::Matrix3d G[3];
    G[0] << 0, 1, 0, -1, 0, 0, 0, 0, 0;
    G[1] << 0, 0, 1, 0, 0, 0, -1, 0, 0;
    G[2] << 0, 0, 0, 0, 0, 1, 0, -1, 0;
    const double h = 1e-7;
    for (int k = 0; k < 3; ++k) {
        double d[3] = {0, 0, 0};
        d[k] = h;
        const Eigen::Matrix3d derivative =
            (expGenerators(d[0], d[1], d[2]) - Eigen::Matrix3d::Identity()) / h;
        EXPECT_LT((derivative - G[k]).norm(), 1e-6) << "generator " << k + 1;
    }
}

TEST(EssentialParameterisation, EssentialHasTheRightStructure)
{
    std::mt19937_64 g(4);
    for (int i = 0; i < 50; ++i) {
        const EssentialPose p = randomPose(g);
        const Eigen::Matrix3d E = p.E();
        EXPECT_NEAR(E.norm(), std::sqrt(2.0), 1e-12);
        EXPECT_NEAR(E.determinant(), 0.0, 1e-12);
        // 2 E E^T E - trace(E E^T) E = 0 (the trace constraint).
        const Eigen::Matrix3d C = 2 * E * E.transpose() * E - (E * E.transpose()).trace() * E;
        EXPECT_LT(C.norm(), 1e-12);
        EXPECT_LT((E.transpose() * p.t()).norm(), 1e-12); // t is the left epipole
    }
}

TEST(EssentialParameterisation, JacobianMatchesFiniteDifferences)
{
    std::mt19937_64 g(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const double h = 1e-6;
    double worst = 0.0;
    for (int trial = 0; trial < 200; ++trial) {
        const EssentialPose p = randomPose(g);
        const double x1 = u(g), y1 = u(g), x2 = u(g), y2 = u(g);
        double J[5];
        const double r = residualAndJacobian(ResidualFrame(p), x1, y1, x2, y2, J);
        EXPECT_NEAR(r, algebraicResidual(p.E(), x1, y1, x2, y2), 1e-14);
        for (int k = 0; k < 5; ++k) {
            const double numeric = centralDifference(p, k, h, [&](const EssentialPose& q) {
                return algebraicResidual(q.E(), x1, y1, x2, y2);
            });
            // Central differences: truncation O(h^2) ~ 1e-12, round-off ~ 1e-16 / h = 1e-10.
            EXPECT_NEAR(J[k], numeric, 1e-8) << "parameter " << k + 1 << " trial " << trial;
            worst = std::max(worst, std::abs(J[k] - numeric));
        }
    }
    RecordProperty("worst_jacobian_error", std::to_string(worst));
}

TEST(EssentialParameterisation, SampsonJacobianMatchesFiniteDifferences)
{
    std::mt19937_64 g(9);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const double h = 1e-6;
    for (int trial = 0; trial < 200; ++trial) {
        const EssentialPose p = randomPose(g);
        const double x1 = u(g), y1 = u(g), x2 = u(g), y2 = u(g);
        double s, J[5];
        ASSERT_TRUE(sampsonResidualAndJacobian(EssentialDerivatives(p), x1, y1, x2, y2, s, J));
        const double r = algebraicResidual(p.E(), x1, y1, x2, y2);
        EXPECT_NEAR(s * s, sampsonSquared(p.E(), x1, y1, x2, y2), 1e-12);
        EXPECT_GE(s * r, 0.0); // the Sampson residual keeps the sign of r
        auto signedSampson = [&](const EssentialPose& q) {
            const double rq = algebraicResidual(q.E(), x1, y1, x2, y2);
            return std::copysign(std::sqrt(sampsonSquared(q.E(), x1, y1, x2, y2)), rq);
        };
        for (int k = 0; k < 5; ++k) {
            const double numeric = centralDifference(p, k, h, signedSampson);
            // Relative to the derivative's size: points near an epipole have large derivatives.
            EXPECT_NEAR(J[k], numeric, 1e-7 * (1.0 + std::abs(numeric)))
                << "parameter " << k + 1 << " trial " << trial;
        }
    }
}

// The robust solver (Algorithm 3) minimises the epipolar distances of the paper's equation (5),
// g = r / |(E q1)_xy| and g' = r / |(E^T q2)_xy|, with the analytic derivatives of
// epipolarDistancesAndJacobian(). Both are checked against central differences of g and g'
// computed here from E alone. Step h = 1e-6: the truncation error is about h^2 |g'''| / 6 and the
// round-off about 1e-16 |g| / h = 1e-10 |g|, so agreement to 1e-7 relative to the derivative's
// size (points near an epipole have large derivatives) leaves a margin of 20: the worst relative
// error measured over the 400 trials is 5.3e-9.
TEST(EssentialParameterisation, EpipolarDistanceJacobiansMatchFiniteDifferences)
{
    std::mt19937_64 g(13);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const double h = 1e-6;
    double worst = 0.0;
    for (int trial = 0; trial < 400; ++trial) {
        const EssentialPose p = randomPose(g);
        const double x1 = u(g), y1 = u(g), x2 = u(g), y2 = u(g);
        double d[2], J[2][5];
        ASSERT_TRUE(epipolarDistancesAndJacobian(EssentialDerivatives(p), x1, y1, x2, y2, d, J));
        // g (view 2: distance of q2 to the epipolar line E q1) and g' (view 1), from E alone.
        auto distance = [&](const EssentialPose& q, int view) {
            const Eigen::Matrix3d E = q.E();
            const Eigen::Vector3d q1(x1, y1, 1.0), q2(x2, y2, 1.0);
            const Eigen::Vector3d line =
                view == 0 ? Eigen::Vector3d(E * q1) : Eigen::Vector3d(E.transpose() * q2);
            return q2.dot(E * q1) / line.head<2>().norm();
        };
        for (int view = 0; view < 2; ++view) {
            EXPECT_NEAR(d[view], distance(p, view), 1e-12 * (1.0 + std::abs(d[view])));
            for (int k = 0; k < 5; ++k) {
                const double numeric = centralDifference(
                    p, k, h, [&](const EssentialPose& q) { return distance(q, view); });
                const double relative = std::abs(J[view][k] - numeric) / (1.0 + std::abs(numeric));
                EXPECT_LT(relative, 1e-7)
                    << (view == 0 ? "g" : "g'") << ", parameter " << k + 1 << ", trial " << trial;
                worst = std::max(worst, relative);
            }
        }
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", worst);
    RecordProperty("worst_relative_error", text);
}

TEST(EssentialParameterisation, UpdateKeepsTheManifold)
{
    std::mt19937_64 g(6);
    EssentialPose p = randomPose(g);
    std::normal_distribution<double> n(0.0, 0.3);
    for (int i = 0; i < 1000; ++i) {
        Vector5d d;
        for (int k = 0; k < 5; ++k)
            d[k] = n(g);
        p.update(d);
    }
    EXPECT_LT((p.R.transpose() * p.R - Eigen::Matrix3d::Identity()).norm(), 1e-12);
    EXPECT_LT((p.Rt.transpose() * p.Rt - Eigen::Matrix3d::Identity()).norm(), 1e-12);
    EXPECT_NEAR(p.t().norm(), 1.0, 1e-12);
}

TEST(EssentialDecomposition, PoseFromEssentialReproducesE)
{
    std::mt19937_64 g(7);
    for (int i = 0; i < 100; ++i) {
        const EssentialPose truth = randomPose(g);
        const Eigen::Matrix3d E = truth.E() * 3.7; // any scale
        EssentialPose p;
        ASSERT_TRUE(poseFromEssential(E, p));
        EXPECT_LT((canonicalEssential(p.E()) - canonicalEssential(E)).norm(), 1e-10);
        EXPECT_NEAR(p.Rt.determinant(), 1.0, 1e-12);
    }
    EssentialPose p;
    EXPECT_FALSE(poseFromEssential(Eigen::Matrix3d::Zero(), p));
    Eigen::Matrix3d bad = Eigen::Matrix3d::Identity();
    bad(0, 0) = std::nan("");
    EXPECT_FALSE(poseFromEssential(bad, p));
}

TEST(Sampson, IsTheFirstOrderGeometricError)
{
    // A point moved by d off its epipolar line in view 2 only: its distance to that line is d, so
    // r = d |(E q1)_xy| and the Sampson distance r / sqrt(|(E q1)_xy|^2 + |(E^T q2)_xy|^2) lies in
    // (0, d], with equality when the view-1 term vanishes.
    std::mt19937_64 g(8);
    std::uniform_real_distribution<double> u(-0.5, 0.5);
    for (int i = 0; i < 100; ++i) {
        const Eigen::Matrix3d E = randomPose(g).E();
        const Eigen::Vector3d q1(u(g), u(g), 1.0);
        const Eigen::Vector3d l = E * q1; // epipolar line in view 2
        const double d = 1e-3;
        // a point of the line, moved by d along its normal
        Eigen::Vector3d q2(u(g), 0.0, 1.0);
        q2.y() = -(l.x() * q2.x() + l.z()) / l.y();
        q2.head<2>() += d * l.head<2>().normalized();
        const double s = std::sqrt(sampsonSquared(E, q1.x(), q1.y(), q2.x(), q2.y()));
        EXPECT_LE(s, d * (1 + 1e-6));
        EXPECT_GT(s, 0.0);
    }
}

} // namespace

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "solvers/robust_irls.hpp"

#include "geometry/essential_decomposition.hpp"
#include "geometry/essential_parameterisation.hpp"
#include "solvers/minimal_set_problem.hpp"
#include "solvers/solution_output.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace cv {
namespace essential {
namespace solvers {

namespace {

using geometry::EssentialPose;
using geometry::Matrix5d;
using geometry::Vector5d;

/** Sum over the sample of the Cauchy loss of both epipolar distances at scale^2 = sigma2 (without
the constant factor sigma2 / 2, which does not change comparisons at one scale). */
double robustCost(const EssentialPose& pose, const Point2d* x1, const Point2d* x2, int n,
                  double sigma2)
{
    const Eigen::Matrix3d E = pose.E();
    double cost = 0.0;
    for (int i = 0; i < n; ++i) {
        const Eigen::Vector3d q1(x1[i].x, x1[i].y, 1.0), q2(x2[i].x, x2[i].y, 1.0);
        const Eigen::Vector3d Eq1 = E * q1, Etq2 = E.transpose() * q2;
        const double r2 = q2.dot(Eq1) * q2.dot(Eq1);
        const double D1 = Eq1.head<2>().squaredNorm(), D2 = Etq2.head<2>().squaredNorm();
        if (!(D1 > 0.0) || !(D2 > 0.0)) continue;
        cost += std::log1p(r2 / (D1 * sigma2)) + std::log1p(r2 / (D2 * sigma2));
    }
    return cost;
}

/** Weighted normal equations of the epipolar distances with weights fixed at pose. */
void normalEquations(const EssentialPose& pose, const Point2d* x1, const Point2d* x2, int n,
                     double sigma2, Matrix5d& A, Vector5d& b)
{
    const geometry::EssentialDerivatives d(pose);
    A.setZero();
    b.setZero();
    double g[2], J[2][5];
    for (int i = 0; i < n; ++i) {
        if (!geometry::epipolarDistancesAndJacobian(d, x1[i].x, x1[i].y, x2[i].x, x2[i].y, g, J))
            continue;
        for (int m = 0; m < 2; ++m) {
            const double w = 1.0 / (1.0 + g[m] * g[m] / sigma2);
            const Eigen::Map<const Vector5d> j(J[m]);
            A.noalias() += w * j * j.transpose();
            b.noalias() += (w * g[m]) * j;
        }
    }
}

int countInliers(const EssentialPose& pose, const Point2d* x1, const Point2d* x2, int n,
                 double maxDistance)
{
    const geometry::EssentialDerivatives d(pose);
    double g[2], J[2][5];
    int count = 0;
    for (int i = 0; i < n; ++i)
        if (geometry::epipolarDistancesAndJacobian(d, x1[i].x, x1[i].y, x2[i].x, x2[i].y, g, J))
            count += std::abs(g[0]) < maxDistance && std::abs(g[1]) < maxDistance;
    return count;
}

/** The linear least-squares essential matrix of the sample (the eight-point method on n >= 8
points: the eigenvector of sum a_i a_i^T with the smallest eigenvalue, a_i = q2_i (x) q1_i), as a
5-DOF pose. Outliers in the sample bias it, but it lands within the basin of the robust fit far more
often than a fixed start: see docs/SOLVERS.md. Returns false when the sample is degenerate. */
bool linearStart(const Point2d* x1, const Point2d* x2, int n, EssentialPose& pose)
{
    Eigen::Matrix<double, 9, 9> M = Eigen::Matrix<double, 9, 9>::Zero();
    for (int i = 0; i < n; ++i) {
        Eigen::Matrix<double, 9, 1> a;
        const double u1 = x1[i].x, v1 = x1[i].y, u2 = x2[i].x, v2 = x2[i].y;
        a << u2 * u1, u2 * v1, u2, v2 * u1, v2 * v1, v2, u1, v1, 1.0;
        M.noalias() += a * a.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 9, 9>> eig(M);
    if (eig.info() != Eigen::Success) return false;
    const Eigen::Matrix<double, 9, 1> e = eig.eigenvectors().col(0);
    Eigen::Matrix3d E;
    E << e[0], e[1], e[2], e[3], e[4], e[5], e[6], e[7], e[8];
    return geometry::poseFromEssential(E, pose);
}

/** Measured probability that a 10-point sample with k inliers (the rest independent random
points) gives E within 0.05 of the truth, 1000 samples per k, synthetic protocol with noise 0.001
(docs/SOLVERS.md; test_robust asserts them with a margin). Below six inliers nothing distinguishes
the true E from the other exact fits of five points, and even one gross outlier pulls the fit into
a wrong minimum more often than not. */
const double kRates10[11] = {0, 0, 0, 0, 0, 0.0, 0.003, 0.012, 0.051, 0.174, 0.962};

} // namespace

RobustIrlsSolver::RobustIrlsSolver(const RobustIrlsSettings& settings) : settings_(settings)
{
    if (settings_.sampleSize < 6)
        CV_Error(Error::StsBadArg, "robust solver: sampleSize must be at least 6");
    if (settings_.rateByInliers.empty() && settings_.sampleSize == 10)
        settings_.rateByInliers.assign(kRates10, kRates10 + 11);
}

double RobustIrlsSolver::successRate() const
{
    return settings_.rateByInliers.empty() ? 0.5 : settings_.rateByInliers.back();
}

double RobustIrlsSolver::hitProbability(double inlierRatio) const
{
    const int n = settings_.sampleSize;
    if (static_cast<int>(settings_.rateByInliers.size()) != n + 1)
        return EssentialSolver::hitProbability(inlierRatio);
    const double w = std::min(1.0, std::max(0.0, inlierRatio));
    double p = 0.0, binom = 1.0; // binom = C(n, k)
    for (int k = 0; k <= n; ++k) {
        if (k > 0) binom = binom * (n - k + 1) / k;
        p += binom * std::pow(w, k) * std::pow(1.0 - w, n - k) * settings_.rateByInliers[k];
    }
    return p;
}

/** One annealed IRLS run from `pose`; returns the final robust cost at the final scale. */
double RobustIrlsSolver::fit(EssentialPose& pose, const Point2d* x1, const Point2d* x2) const
{
    const int n = settings_.sampleSize;
    double sigma = settings_.initialScale;
    double lambda = 1e-3;
    Matrix5d A;
    Vector5d b;
    for (int it = 0; it < settings_.maxIterations; ++it) {
        const double sigma2 = sigma * sigma;
        normalEquations(pose, x1, x2, n, sigma2, A, b);
        const double cost = robustCost(pose, x1, x2, n, sigma2);
        // One LM step at this scale: up to three damping increases before moving on.
        for (int attempt = 0; attempt < 3; ++attempt) {
            Matrix5d damped = A;
            damped.diagonal() *= 1.0 + lambda;
            const Vector5d step = damped.ldlt().solve(-b);
            if (!step.allFinite()) return HUGE_VAL;
            EssentialPose trial = pose;
            trial.update(step);
            if (robustCost(trial, x1, x2, n, sigma2) < cost) {
                pose = trial;
                lambda = std::max(1e-9, lambda * 0.1);
                break;
            }
            lambda *= 10.0;
        }
        sigma = std::max(settings_.finalScale, sigma * settings_.scaleDecay);
    }
    return robustCost(pose, x1, x2, n, settings_.finalScale * settings_.finalScale);
}

int RobustIrlsSolver::solve(const Point2d* x1, const Point2d* x2, RNG& /*rng*/, Matx33d* solutions)
{
    const int n = settings_.sampleSize;
    // Two starts, the better final robust cost wins: the linear estimate of the whole sample (close
    // when the sample is nearly clean) and R = I with the least-squares translation (independent of
    // the linear fit's outlier bias).
    EssentialPose best;
    double bestCost = HUGE_VAL;
    EssentialPose starts[2];
    int numStarts = 0;
    if (linearStart(x1, x2, n, starts[numStarts])) ++numStarts;
    if (settings_.twoStarts || numStarts == 0)
        starts[numStarts++] = bestTranslationStart(x1, x2, n, Eigen::Matrix3d::Identity());
    for (int s = 0; s < numStarts; ++s) {
        const double cost = fit(starts[s], x1, x2);
        if (cost < bestCost) {
            bestCost = cost;
            best = starts[s];
        }
    }
    if (!(bestCost < HUGE_VAL)) return 0;
    if (countInliers(best, x1, x2, n, settings_.inlierDistance) < settings_.minInliers) return 0;
    return writeSolution(best, solutions);
}

} // namespace solvers
} // namespace essential
} // namespace cv

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "solvers/robust_irls.hpp"

#include "geometry/essential_decomposition.hpp"
#include "geometry/essential_parameterisation.hpp"
#include "geometry/sampson.hpp"
#include "optim/levenberg_marquardt.hpp"
#include "optim/robust_loss.hpp"
#include "solvers/minimal_set_problem.hpp"
#include "solvers/solution_output.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <climits>
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
        cost += optim::CauchyLoss::cost(r2 / (D1 * sigma2)) +
                optim::CauchyLoss::cost(r2 / (D2 * sigma2));
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
            const double w = optim::CauchyLoss::weight(g[m] * g[m] / sigma2);
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

/** The constraint row of a correspondence, q2 (x) q1, scaled to unit length (so that pivot
tolerances mean the same for every point). */
void constraintRow(const Point2d& p1, const Point2d& p2, double row[9])
{
    const double u1 = p1.x, v1 = p1.y, u2 = p2.x, v2 = p2.y;
    const double a[9] = {u2 * u1, u2 * v1, u2, v2 * u1, v2 * v1, v2, u1, v1, 1.0};
    double n2 = 0.0;
    for (double x : a)
        n2 += x * x;
    const double inv = 1.0 / std::sqrt(n2);
    for (int k = 0; k < 9; ++k)
        row[k] = a[k] * inv;
}

/** The null vector of an 8 x 9 matrix of unit rows (eight correspondences' constraints) by
Gauss-Jordan elimination with full pivoting, about 1200 flops. False when the rows have rank below
8 (a pivot below 1e-10: a degenerate subset). */
bool nullVector8(double A[8][9], Eigen::Matrix3d& F)
{
    int column[9] = {0, 1, 2, 3, 4, 5, 6, 7, 8};
    for (int r = 0; r < 8; ++r) {
        int pi = r, pj = r;
        double best = 0.0;
        for (int i = r; i < 8; ++i)
            for (int j = r; j < 9; ++j)
                if (std::abs(A[i][j]) > best) {
                    best = std::abs(A[i][j]);
                    pi = i;
                    pj = j;
                }
        if (!(best > 1e-10)) return false;
        if (pi != r)
            for (int j = 0; j < 9; ++j)
                std::swap(A[r][j], A[pi][j]);
        if (pj != r) {
            for (int i = 0; i < 8; ++i)
                std::swap(A[i][r], A[i][pj]);
            std::swap(column[r], column[pj]);
        }
        const double inv = 1.0 / A[r][r];
        for (int j = r; j < 9; ++j)
            A[r][j] *= inv;
        for (int i = 0; i < 8; ++i) {
            if (i == r) continue;
            const double f = A[i][r];
            if (f == 0.0) continue;
            for (int j = r; j < 9; ++j)
                A[i][j] -= f * A[r][j];
        }
    }
    // A = [I | c] in the permuted columns: x_column[8] = 1, x_column[r] = -c_r.
    double e[9];
    e[column[8]] = 1.0;
    for (int r = 0; r < 8; ++r)
        e[column[r]] = -A[r][8];
    F << e[0], e[1], e[2], e[3], e[4], e[5], e[6], e[7], e[8];
    return F.allFinite();
}

/** The least-squares eight-point fit of all n points: the eigenvector of sum a_i a_i^T with the
smallest eigenvalue. */
bool leastSquaresFit(const double rows[][9], int n, Eigen::Matrix3d& F)
{
    Eigen::Matrix<double, 9, 9> M = Eigen::Matrix<double, 9, 9>::Zero();
    for (int i = 0; i < n; ++i) {
        const Eigen::Map<const Eigen::Matrix<double, 9, 1>> a(rows[i]);
        M.noalias() += a * a.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 9, 9>> eig(M);
    if (eig.info() != Eigen::Success) return false;
    const Eigen::Matrix<double, 9, 1> e = eig.eigenvectors().col(0);
    F << e[0], e[1], e[2], e[3], e[4], e[5], e[6], e[7], e[8];
    return true;
}

/** Sum over the sample of the squared Sampson distances of F, each at most gate2 (in units of
gate2): how well a start explains the sample, outliers counting once each. */
double truncatedCost(const Eigen::Matrix3d& F, const Point2d* x1, const Point2d* x2, int n,
                     double gate2)
{
    const geometry::EssentialEntries e(F);
    double cost = 0.0;
    for (int i = 0; i < n; ++i) {
        const double d2 = geometry::sampsonSquared(e, x1[i].x, x1[i].y, x2[i].x, x2[i].y);
        cost += d2 < gate2 ? d2 / gate2 : 1.0; // NaN (a point on both epipoles) counts as 1
    }
    return cost;
}

/** Measured probability that a 10-point sample with k inliers (the rest independent random
points) gives E within 0.05 of the truth: 1000 samples per k of the paper's protocol, noise 0.5 px
and threshold 1 px at f = 500 (essential_robust_sample_rates; docs/SOLVERS.md; test_robust asserts
them with a margin). With ten inliers the noise alone keeps 4% of the fits beyond 0.05; with eight,
one of the 45 subsets is clean, but its exact fit carries its noise and is not always the start
chosen; below eight no subset is clean. */
const double kRates10[11] = {0, 0, 0, 0, 0, 0.0, 0.003, 0.047, 0.626, 0.885, 0.957};

/** Most correspondences per sample: the starts enumerate the sample's subsets of eight. */
constexpr int kMaxSample = 10;

} // namespace

RobustIrlsSolver::RobustIrlsSolver(const RobustIrlsSettings& settings) : settings_(settings)
{
    if (settings_.sampleSize < 8 || settings_.sampleSize > kMaxSample)
        CV_Error(Error::StsBadArg, "robust solver: sampleSize must be from 8 to 10");
    if (settings_.rateByInliers.empty() && settings_.sampleSize == 10)
        settings_.rateByInliers.assign(kRates10, kRates10 + 11);
}

void RobustIrlsSolver::setThreshold(double normalisedThreshold)
{
    if (normalisedThreshold > 0.0 && std::isfinite(normalisedThreshold))
        settings_.threshold = normalisedThreshold;
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

namespace {

/** The sample at one scale of the annealing, as a model of optim::minimise. */
struct AnnealedSampleModel
{
    static constexpr bool kCostWithEquations = false;
    const Point2d* x1;
    const Point2d* x2;
    int n;
    double sigma2;

    double linearise(const EssentialPose& pose, optim::NormalEquations& system) const
    {
        normalEquations(pose, x1, x2, n, sigma2, system.A, system.g);
        return robustCost(pose, x1, x2, n, sigma2);
    }
    double cost(const EssentialPose& pose) const { return robustCost(pose, x1, x2, n, sigma2); }
};

} // namespace

/** One annealed IRLS run from `pose`: one LM iteration (up to three trial steps) per scale, the
scale shrinking towards its final value; returns the robust cost at the final scale. */
double RobustIrlsSolver::fit(EssentialPose& pose, const Point2d* x1, const Point2d* x2) const
{
    const int n = settings_.sampleSize;
    const double finalScale = settings_.finalScale * settings_.threshold;
    double sigma = std::max(settings_.initialScale, settings_.finalScale) * settings_.threshold;
    optim::Damping damping;
    damping.initial = 1e-3;
    damping.floor = 1e-9;
    damping.attempts = 3;
    double lambda = damping.initial;
    optim::NormalEquations system;
    optim::LmResult counts;
    for (int it = 0; it < settings_.maxIterations; ++it) {
        AnnealedSampleModel model{x1, x2, n, sigma * sigma};
        double cost = model.linearise(pose, system);
        bool systemCurrent = true;
        // A rejected iteration moves on to the next scale: the cost itself changes with it.
        if (optim::dampedIteration(model, pose, system, cost, lambda, damping, counts, INT_MAX,
                                   systemCurrent) == optim::StepOutcome::Singular)
            return HUGE_VAL;
        sigma = std::max(finalScale, sigma * settings_.scaleDecay);
    }
    return robustCost(pose, x1, x2, n, finalScale * finalScale);
}

int RobustIrlsSolver::solve(const Point2d* x1, const Point2d* x2, RNG& /*rng*/, Matx33d* solutions)
{
    const int n = settings_.sampleSize;
    double rows[kMaxSample][9];
    for (int i = 0; i < n; ++i)
        constraintRow(x1[i], x2[i], rows[i]);

    // The starts, ranked by their truncated cost; only the best few are kept.
    constexpr int kMaxKept = 4;
    const int kept = std::min(std::max(settings_.refinedStarts, 1), kMaxKept);
    Eigen::Matrix3d best[kMaxKept];
    double bestCost[kMaxKept];
    for (int k = 0; k < kept; ++k)
        bestCost[k] = HUGE_VAL;
    const double gate = settings_.startGate * settings_.threshold;
    auto consider = [&](const Eigen::Matrix3d& F) {
        // Scored as the nearest essential matrix: an exact fit of eight points fits them whatever
        // they are, but only a clean subset's fit stays close to them once made essential.
        EssentialPose pose;
        if (!geometry::poseFromEssential(F, pose)) return;
        Eigen::Matrix3d candidate = pose.E();
        double cost = truncatedCost(candidate, x1, x2, n, gate * gate);
        if (!(cost < bestCost[kept - 1])) return;
        for (int k = 0; k < kept; ++k)
            if (cost < bestCost[k]) {
                std::swap(cost, bestCost[k]);
                std::swap(candidate, best[k]);
            }
    };
    // Every subset of eight: leave out none (n = 8), one point i (n = 9) or a pair i < j (n = 10).
    double A[8][9];
    Eigen::Matrix3d F;
    const int outI = n >= 9 ? n : 1, outJ = n == 10 ? n : 1;
    for (int i = 0; i < outI; ++i)
        for (int j = n == 10 ? i + 1 : 0; j < outJ; ++j) {
            int r = 0;
            for (int k = 0; k < n; ++k)
                if ((n < 9 || k != i) && (n < 10 || k != j))
                    std::copy(rows[k], rows[k] + 9, A[r++]);
            if (nullVector8(A, F)) consider(F);
        }
    if (leastSquaresFit(rows, n, F)) consider(F);
    consider(bestTranslationStart(x1, x2, n, Eigen::Matrix3d::Identity()).E());

    EssentialPose winner;
    double winnerCost = HUGE_VAL;
    for (int k = 0; k < kept && bestCost[k] < HUGE_VAL; ++k) {
        EssentialPose pose;
        if (!geometry::poseFromEssential(best[k], pose)) continue;
        const double cost = fit(pose, x1, x2);
        if (cost < winnerCost) {
            winnerCost = cost;
            winner = pose;
        }
    }
    if (!(winnerCost < HUGE_VAL)) return 0;
    if (countInliers(winner, x1, x2, n, settings_.inlierDistance * settings_.threshold) <
        settings_.minInliers)
        return 0;
    return writeSolution(winner, solutions);
}

} // namespace solvers
} // namespace essential
} // namespace cv

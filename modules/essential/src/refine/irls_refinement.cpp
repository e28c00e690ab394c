// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "refine/irls_refinement.hpp"

#include "geometry/essential_decomposition.hpp"
#include "geometry/essential_parameterisation.hpp"

#include <Eigen/Cholesky>

#include <cmath>

namespace cv {
namespace essential {
namespace refine {

namespace {

using geometry::EssentialPose;
using geometry::Matrix5d;
using geometry::Vector5d;

/** Sum of the Cauchy loss over all points for E. */
double robustCost(const Problem& p, const Eigen::Matrix3d& E, double sigma2)
{
    double cost = 0.0;
    const int n = p.size();
    for (int i = 0; i < n; ++i) {
        const Eigen::Vector3d q1(p.x1[i], p.y1[i], 1.0), q2(p.x2[i], p.y2[i], 1.0);
        const Eigen::Vector3d Eq1 = E * q1, Etq2 = E.transpose() * q2;
        const double r = q2.dot(Eq1);
        const double D = Eq1.head<2>().squaredNorm() + Etq2.head<2>().squaredNorm();
        if (!(D > 0.0)) continue;
        cost += std::log1p(r * r / (D * sigma2));
    }
    return 0.5 * sigma2 * cost;
}

/** The IRLS normal equations A d = -g at pose: Gauss-Newton on the Sampson residuals s_i with the
Cauchy weights w_i = 1 / (1 + s_i^2 / sigma^2) held fixed, A = sum w J J^T, g = sum w s J. */
void normalEquations(const Problem& p, const EssentialPose& pose, double sigma2, Matrix5d& A,
                     Vector5d& g)
{
    const geometry::EssentialDerivatives derivatives(pose);
    A.setZero();
    g.setZero();
    const int n = p.size();
    double J[5], s;
    for (int i = 0; i < n; ++i) {
        if (!geometry::sampsonResidualAndJacobian(derivatives, p.x1[i], p.y1[i], p.x2[i], p.y2[i],
                                                  s, J))
            continue;
        const double w = 1.0 / (1.0 + s * s / sigma2);
        const Eigen::Map<const Vector5d> j(J);
        A.noalias() += w * j * j.transpose();
        g.noalias() += (w * s) * j;
    }
}

} // namespace

IrlsResult refineIrls(const Problem& problem, const Matx33d& E0, double scale,
                      const IrlsSettings& settings)
{
    IrlsResult result;
    result.E = E0;
    Eigen::Matrix3d E;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            E(i, j) = E0(i, j);
    EssentialPose pose;
    if (!geometry::poseFromEssential(E, pose)) return result;

    const double sigma2 = scale * scale;
    double cost = robustCost(problem, pose.E(), sigma2);
    const double initialCost = cost;
    double lambda = 1e-4;
    Matrix5d A;
    Vector5d g;
    for (int it = 0; it < settings.maxIterations; ++it) {
        result.iterations = it + 1;
        normalEquations(problem, pose, sigma2, A, g);
        bool accepted = false;
        // Up to a few damping increases per iteration; a failure at the largest damping means the
        // pose is at a minimum of the robust cost to working precision.
        for (int attempt = 0; attempt < 6 && !accepted; ++attempt) {
            Matrix5d damped = A;
            damped.diagonal() *= 1.0 + lambda;
            const Vector5d step = damped.ldlt().solve(-g);
            if (!step.allFinite()) break;
            EssentialPose trial = pose;
            trial.update(step);
            const double trialCost = robustCost(problem, trial.E(), sigma2);
            if (trialCost < cost) {
                const double decrease = (cost - trialCost) / cost;
                pose = trial;
                cost = trialCost;
                lambda = std::max(lambda * 0.1, 1e-12);
                accepted = true;
                if (decrease < settings.relativeTolerance) it = settings.maxIterations;
            } else {
                lambda *= 10.0;
            }
        }
        if (!accepted) break;
    }
    if (cost < initialCost) {
        geometry::reorthonormalise(pose.R);
        geometry::reorthonormalise(pose.Rt);
        const Eigen::Matrix3d Er = pose.E();
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                result.E(i, j) = Er(i, j);
        result.improved = true;
    }
    return result;
}

} // namespace refine
} // namespace essential
} // namespace cv

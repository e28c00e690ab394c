// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "search/minimal_set.hpp"

#include "geometry/essential_decomposition.hpp"

#include <opencv2/calib3d.hpp>

#include <algorithm>
#include <vector>

namespace cv {
namespace essential {
namespace search {

namespace {

/** To list the solutions of a five-point problem (what cv::findEssentialMat returns for exactly
five points) a solver that finds one root per call (gn, lm) is run on this many
rotated copies of the problem: view 1's points are rotated by a random Q (q1' ~ Q q1), which moves
the solver's start relative to the data, and each solution E' of the copy maps back to E = E' Q.
Measured with gn on 200 noise-free problems of the paper's protocol (cv::findEssentialMat finds
4.70 real roots on average there, the true one always): 30 / 60 / 120 copies find 4.21 / 4.53 /
4.67 roots and the true E in 192 / 197 / 199 problems (the time per call in docs/TUNING.md, "Five
points exactly"). */
constexpr int kFivePointStarts = 120;

/** Largest rotation of the copies: the solvers start at R = I, so this spreads their starts over
rotations up to this angle. */
constexpr double kFivePointMaxAngle = 60.0 * CV_PI / 180.0;

/** Two solutions closer than this (essential matrices of norm sqrt(2), up to sign) are the same
root: converged solutions agree to ~1e-7 (residuals below 1e-7), distinct roots differ by far more.
*/
constexpr double kSameSolution = 1e-4;

} // namespace

Mat solveExactlyFive(const Problem& problem, EssentialSolver& solver, RNG& rng,
                     EssentialReport& report)
{
    // A direct solver that finds (nearly) every root in one call, like nister, needs one call;
    // iterative ones and composites that contain one need the rotated copies.
    const int starts = solver.successRate() >= 0.99 ? 1 : kFivePointStarts;
    std::vector<Matx33d> buffer(static_cast<size_t>(solver.maxSolutions()));
    std::vector<Eigen::Matrix3d> found;
    std::vector<Point2d> rotated(5), second(5);
    for (int i = 0; i < 5; ++i)
        second[static_cast<size_t>(i)] = problem.point2(i);
    for (int s = 0; s < starts; ++s) {
        Matx33d Q = Matx33d::eye();
        if (s > 0) {
            Vec3d axis(rng.gaussian(1.0), rng.gaussian(1.0), rng.gaussian(1.0));
            axis *= rng.uniform(0.0, kFivePointMaxAngle) / std::max(norm(axis), 1e-12);
            Rodrigues(axis, Q);
        }
        bool usable = true;
        for (int i = 0; i < 5; ++i) {
            const Vec3d q = Q * Vec3d(problem.x1[i], problem.y1[i], 1.0);
            usable &= q[2] > 0.3; // keep the rotated coordinates bounded
            rotated[i] = Point2d(q[0] / q[2], q[1] / q[2]);
        }
        if (!usable) continue;
        const int count = solver.solve(rotated.data(), second.data(), rng, buffer.data());
        ++report.hypothesesGenerated;
        report.hypothesesConverged += std::max(0, count);
        for (int h = 0; h < std::min(count, static_cast<int>(buffer.size())); ++h) {
            const Matx33d Eq = buffer[h] * Q;
            Eigen::Matrix3d E;
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    E(i, j) = Eq(i, j);
            if (!E.allFinite() || !(E.norm() > 0)) continue;
            const Eigen::Matrix3d C = geometry::canonicalEssential(E);
            // Compared up to sign: the canonical sign follows the largest entry, which is not a
            // stable choice when two entries tie in magnitude with opposite signs (forward motion
            // with no rotation gives E = [e_z]x, entries -1 and +1), so two copies of one root
            // may come back as C and -C.
            bool seen = false;
            for (const Eigen::Matrix3d& F : found)
                seen |= std::min((C - F).norm(), (C + F).norm()) < kSameSolution;
            if (!seen && found.size() < 10) found.push_back(C);
        }
    }
    if (found.empty()) return Mat();
    Mat stacked(3 * static_cast<int>(found.size()), 3, CV_64F);
    for (size_t s = 0; s < found.size(); ++s)
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                stacked.at<double>(3 * static_cast<int>(s) + i, j) =
                    found[s](i, j) / found[s].norm();
    return stacked;
}

} // namespace search
} // namespace essential
} // namespace cv

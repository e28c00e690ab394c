// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "scoring/in_front_score.hpp"

#include "geometry/depth_signs.hpp"
#include "geometry/sampson.hpp"
#include "geometry/symmetric_epipolar.hpp"
#include "pose/pose_recovery.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>

namespace cv {
namespace essential {
namespace scoring {

namespace {

/** The parallax (geometry::scaledDepths) below which a point's depth signs do not decide, in
inlier thresholds: such a point (a distant one, or one near the epipole) counts as in front under
every pose rather than as evidence against one. The inlier threshold bounds the angle noise moves a
ray by (in normalised units, about radians); twice that is where the sign of the triangulated depth
stops being set by the noise. */
constexpr double kUndecidedParallax = 2.0;

/** Counts and costs of the inliers in front under each of the four poses, in the order
(R1, t), (R1, -t), (R2, t), (R2, -t). */
struct FourPoses
{
    std::array<int, 4> count{};
    std::array<double, 4> cost{};
};

/** For every inlier (distance at most threshold): its squared distance added to the poses that
place it in front of both cameras (geometry::scaledDepths; -t flips both depth signs). */
FourPoses inFrontOfFourPoses(const Matx33d& E, const Problem& problem, InlierTest test, bool& ok)
{
    FourPoses out;
    Eigen::Matrix3d R[2];
    Eigen::Vector3d t;
    ok = pose::poseCandidates(E, R[0], R[1], t);
    if (!ok) return out;
    const geometry::EssentialEntries e(E);
    const bool symmetric = test.distance == DISTANCE_SYMMETRIC_EPIPOLAR;
    const double t2 = test.threshold * test.threshold;
    const double minParallax = kUndecidedParallax * test.threshold;
    const int n = problem.size();
    for (int i = 0; i < n; ++i) {
        const double x1 = problem.x1[i], y1 = problem.y1[i], x2 = problem.x2[i], y2 = problem.y2[i];
        const double d2 = symmetric ? geometry::symmetricEpipolarSquared(e, x1, y1, x2, y2)
                                    : geometry::sampsonSquared(e, x1, y1, x2, y2);
        if (!(d2 <= t2)) continue;
        const Eigen::Vector3d q1(x1, y1, 1.0), q2(x2, y2, 1.0);
        for (int r = 0; r < 2; ++r) {
            double depth1, depth2;
            bool plus = true, minus = true;
            if (geometry::scaledDepths(R[r] * q1, q2, t, minParallax, depth1, depth2)) {
                plus = depth1 > 0.0 && depth2 > 0.0;
                minus = depth1 < 0.0 && depth2 < 0.0;
            }
            if (plus) {
                ++out.count[2 * r];
                out.cost[2 * r] += d2;
            }
            if (minus) {
                ++out.count[2 * r + 1];
                out.cost[2 * r + 1] += d2;
            }
        }
    }
    return out;
}

} // namespace

Score scoreMsacInFront(const Matx33d& E, const Problem& problem, InlierTest test, double bestCost)
{
    const Score plain = scoreMsac(E, problem, test, bestCost);
    if (plain.cost >= bestCost) return plain; // the in-front cost is never lower
    const int n = problem.size();
    const double t2 = test.threshold * test.threshold;
    bool ok = false;
    const FourPoses poses = inFrontOfFourPoses(E, problem, test, ok);
    Score s;
    s.scored = n;
    s.cost = n * t2;
    if (!ok) return s;
    for (int k = 0; k < 4; ++k) {
        const double cost = poses.cost[k] + (n - poses.count[k]) * t2;
        if (cost < s.cost) {
            s.cost = cost;
            s.inliers = poses.count[k];
        }
    }
    return s;
}

int inliersInFront(const Matx33d& E, const Problem& problem, InlierTest test)
{
    bool ok = false;
    const FourPoses poses = inFrontOfFourPoses(E, problem, test, ok);
    return ok ? *std::max_element(poses.count.begin(), poses.count.end()) : 0;
}

} // namespace scoring
} // namespace essential
} // namespace cv

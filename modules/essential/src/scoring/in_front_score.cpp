// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "scoring/in_front_score.hpp"

#include "geometry/depth_signs.hpp"
#include "geometry/sampson.hpp"
#include "geometry/symmetric_epipolar.hpp"
#include "pose/pose_recovery.hpp"
#include "simd_dispatch.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>

namespace cv {
namespace essential {
namespace scoring {

namespace {

/** The parallax (geometry::DepthProducts::decided) below which a point's depth signs do not decide,
in inlier thresholds: such a point (a distant one, or one near the epipole) counts as in front under
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

#if defined(__GNUC__)
#define ESSENTIAL_INLINE_SCORE inline __attribute__((always_inline))
#else
#define ESSENTIAL_INLINE_SCORE inline
#endif

/** Points per block of inFrontOfFourPoses' two passes, small enough for the block's arrays to stay
in L1. */
constexpr int kBlock = 128;

/** The depth signs of one point under the four poses (R, +-t), (R', +-t), R row-major and
R' = (2 t t^T - I) R its twisted pair, as bits 1, 2, 4, 8: a pose's bit is set when both depths are
positive under it, or when the parallax is below minParallax and the signs do not decide
(geometry::DepthProducts; scalars and no branch, so that the loop over a block vectorises). */
inline int depthSigns(const double* r, const double* t, double x1, double y1, double x2, double y2,
                      double minParallax2)
{
    const geometry::DepthProducts p = geometry::depthProducts(r, t, x1, y1, x2, y2);
    const geometry::DepthProducts w = p.twisted();
    const double depth1 = p.depth1(), depth2 = p.depth2();
    const double twisted1 = w.depth1(), twisted2 = w.depth2();
    const int undecided = !p.decided(minParallax2);
    const int front = undecided | ((depth1 > 0.0) & (depth2 > 0.0));
    const int behind = undecided | ((depth1 < 0.0) & (depth2 < 0.0));
    const int twistedUndecided = !w.decided(minParallax2);
    const int twistedFront = twistedUndecided | ((twisted1 > 0.0) & (twisted2 > 0.0));
    const int twistedBehind = twistedUndecided | ((twisted1 < 0.0) & (twisted2 < 0.0));
    return front | behind << 1 | twistedFront << 2 | twistedBehind << 3;
}

/** First pass over a block: each point's squared distance and its verdicts as bits, in the order
(R1, t), (R1, -t), (R2, t), (R2, -t); 0 for the points beyond the threshold. */
template <bool kSymmetric>
ESSENTIAL_INLINE_SCORE void verdicts(const geometry::EssentialEntries& e, const double* r1,
                                     const double* t, const double* x1, const double* y1,
                                     const double* x2, const double* y2, int count, double t2,
                                     double minParallax2, double* d2, int* bits)
{
    for (int i = 0; i < count; ++i) {
        const geometry::SampsonTerms terms = geometry::sampsonTerms(e, x1[i], y1[i], x2[i], y2[i]);
        const double d = kSymmetric ? geometry::symmetricEpipolarSquared(terms)
                                    : geometry::sampsonSquared(terms);
        const int inlier = d <= t2;
        d2[i] = d;
        bits[i] = inlier * depthSigns(r1, t, x1[i], y1[i], x2[i], y2[i], minParallax2);
    }
}

ESSENTIAL_SIMD_CLONES void blockVerdicts(const geometry::EssentialEntries& e, const double* r1,
                                         const double* t, const double* x1, const double* y1,
                                         const double* x2, const double* y2, int count,
                                         bool symmetric, double t2, double minParallax2, double* d2,
                                         int* bits)
{
    if (symmetric)
        verdicts<true>(e, r1, t, x1, y1, x2, y2, count, t2, minParallax2, d2, bits);
    else
        verdicts<false>(e, r1, t, x1, y1, x2, y2, count, t2, minParallax2, d2, bits);
}

/** For every inlier (distance at most threshold): its squared distance added to the poses that
place it in front of both cameras (geometry::DepthProducts; -t flips both depth signs). The costs
are summed in the points' order, as one loop over them would. */
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
    // R[1] is R[0]'s twisted pair about t (geometry::decomposeEssential: U W V^T and U W^T V^T, t
    // the third column of U), so its verdicts follow from R[0]'s rays (depthSigns).
    double r[9];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            r[3 * i + j] = R[0](i, j);
    const double tv[3] = {t[0], t[1], t[2]};
    const int n = problem.size();
    alignas(32) double d2[kBlock];
    alignas(32) int bits[kBlock];
    for (int begin = 0; begin < n; begin += kBlock) {
        const int count = std::min(kBlock, n - begin);
        blockVerdicts(e, r, tv, problem.x1.data() + begin, problem.y1.data() + begin,
                      problem.x2.data() + begin, problem.y2.data() + begin, count, symmetric, t2,
                      minParallax * minParallax, d2, bits);
        for (int i = 0; i < count; ++i) {
            const int b = bits[i];
            if (!b) continue;
            for (int k = 0; k < 4; ++k)
                if (b & (1 << k)) {
                    ++out.count[static_cast<size_t>(k)];
                    out.cost[static_cast<size_t>(k)] += d2[i];
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

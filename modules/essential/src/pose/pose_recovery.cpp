// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Cheirality test for the four poses of an essential matrix. Each correspondence is triangulated by
// the two-view least-squares depths (z1, z2) that best satisfy z2 q2 = z1 R q1 + t; a point counts
// for a pose when both depths are positive. There is deliberately no far-point cut: a point at any
// distance in front of both cameras counts, so that deep scenes seen from a short baseline still
// decide the sign of t (cv::recoverPose in OpenCV 4.6 ignores points beyond 50 baselines).

#include "pose/pose_recovery.hpp"

#include "geometry/depth_signs.hpp"
#include "geometry/essential_decomposition.hpp"
#include "simd_dispatch.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <vector>

namespace cv {
namespace essential {
namespace pose {

namespace {

#if defined(__GNUC__)
#define ESSENTIAL_INLINE_POSE inline __attribute__((always_inline))
#else
#define ESSENTIAL_INLINE_POSE inline
#endif

/** Bits of the four candidates, in the order cv::recoverPose tries them. */
constexpr int kR1Plus = 1, kR2Plus = 2, kR1Minus = 4, kR2Minus = 8;

/** The depth signs of the correspondence (q1, q2) = ((x1, y1, 1), (x2, y2, 1)) under the four
candidates of R1 (row-major r) and its twisted pair R2 = (2 t t^T - I) R1 with the unit translation
t (X2 = R X1 + t), as bits: kR1Plus when both depths are positive under (R1, t), kR1Minus when both
are negative, which is when both are positive under (R1, -t), and kR2Plus, kR2Minus likewise.
Parallel rays have no depth and never count (geometry::DepthProducts::solvable). Branch-free, so
that the loop over the points vectorises. */
inline int depthSignBits(const double* r, const double* t, double x1, double y1, double x2,
                         double y2)
{
    const geometry::DepthProducts p = geometry::depthProducts(r, t, x1, y1, x2, y2);
    const geometry::DepthProducts w = p.twisted();
    const double z1 = p.depth1(), z2 = p.depth2();
    const double w1 = w.depth1(), w2 = w.depth2();
    const int solvable = p.solvable(), twistedSolvable = w.solvable();
    const int front = (z1 > 0.0) & (z2 > 0.0), behind = (z1 < 0.0) & (z2 < 0.0);
    const int twistedFront = (w1 > 0.0) & (w2 > 0.0), twistedBehind = (w1 < 0.0) & (w2 < 0.0);
    return solvable * (front * kR1Plus + behind * kR1Minus) +
           twistedSolvable * (twistedFront * kR2Plus + twistedBehind * kR2Minus);
}

/** The four candidates' verdicts on every point as bits (0 for the points maskIn leaves out),
written to bits[] (which may alias maskIn) and counted per candidate. */
template <bool kMasked>
ESSENTIAL_INLINE_POSE void voteAll(const Problem& points, const double* r1, const double* t,
                                   const uchar* maskIn, uchar* bits, int counts[4])
{
    const int n = points.size();
    const double* x1 = points.x1.data();
    const double* y1 = points.y1.data();
    const double* x2 = points.x2.data();
    const double* y2 = points.y2.data();
    int c0 = 0, c1 = 0, c2 = 0, c3 = 0;
    for (int i = 0; i < n; ++i) {
        const int used = kMasked ? maskIn[i] != 0 : 1;
        const int b = used * depthSignBits(r1, t, x1[i], y1[i], x2[i], y2[i]);
        c0 += b & 1;
        c1 += (b >> 1) & 1;
        c2 += (b >> 2) & 1;
        c3 += (b >> 3) & 1;
        bits[i] = static_cast<uchar>(b);
    }
    counts[0] = c0;
    counts[1] = c1;
    counts[2] = c2;
    counts[3] = c3;
}

ESSENTIAL_SIMD_CLONES void voteMasked(const Problem& points, const double* r1, const double* t,
                                      const uchar* maskIn, uchar* bits, int counts[4])
{
    voteAll<true>(points, r1, t, maskIn, bits, counts);
}

ESSENTIAL_SIMD_CLONES void voteUnmasked(const Problem& points, const double* r1, const double* t,
                                        uchar* bits, int counts[4])
{
    voteAll<false>(points, r1, t, nullptr, bits, counts);
}

} // namespace

bool poseCandidates(const Matx33d& E, Eigen::Matrix3d& R1, Eigen::Matrix3d& R2, Eigen::Vector3d& t)
{
    Eigen::Matrix3d Ee;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            Ee(i, j) = E(i, j);
    if (!geometry::decomposeEssential(Ee, R1, R2, t) || !t.allFinite() || !(t.norm() > 0.0))
        return false;
    t.normalize();
    return true;
}

bool recoverPoseNormalised(const Matx33d& E, const Problem& points, const uchar* maskIn,
                           uchar* maskOut, PoseResult& out)
{
    const int n = points.size();
    Eigen::Matrix3d R1, R2;
    Eigen::Vector3d t;
    if (!poseCandidates(E, R1, R2, t)) {
        if (maskOut)
            for (int i = 0; i < n; ++i)
                maskOut[i] = 0;
        return false;
    }

    // The candidates in the order cv::recoverPose tries them, (R1, t), (R2, t), (R1, -t),
    // (R2, -t); ties go to the first, as there. Each point's four verdicts are kept as bits (in
    // maskOut, which may alias maskIn: each entry is read before it is written, or in a buffer)
    // for the mask of the chosen pose.
    // R2 is R1's twisted pair about t (geometry::decomposeEssential: U W V^T and U W^T V^T, t the
    // third column of U), so the votes need R1's rays only (depthSignBits).
    double r1[9];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            r1[3 * i + j] = R1(i, j);
    const double tv[3] = {t[0], t[1], t[2]};
    std::vector<uchar> scratch;
    uchar* bits = maskOut;
    if (!bits) {
        scratch.resize(static_cast<size_t>(n));
        bits = scratch.data();
    }
    int counts[4] = {0, 0, 0, 0};
    if (maskIn)
        voteMasked(points, r1, tv, maskIn, bits, counts);
    else
        voteUnmasked(points, r1, tv, bits, counts);
    const int best = static_cast<int>(std::max_element(counts, counts + 4) - counts);
    if (maskOut)
        for (int i = 0; i < n; ++i)
            maskOut[i] = static_cast<uchar>((maskOut[i] >> best) & 1);
    const Eigen::Matrix3d& R = best % 2 == 0 ? R1 : R2;
    const double sign = best < 2 ? 1.0 : -1.0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
            out.R(i, j) = R(i, j);
        out.t[i] = sign * t[i];
    }
    out.inFront = counts[best];
    return true;
}

} // namespace pose
} // namespace essential
} // namespace cv

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "ransac/plane_parallax.hpp"

#include "ransac/termination.hpp"
#include "ransac/uniform_sampler.hpp"

#include <opencv2/calib3d.hpp>

#include <vector>

namespace cv {
namespace essential {
namespace ransac {

namespace {

/** The homography must explain at least this share of the model's inliers for the scene to count
as dominated by a plane. Below it the inliers are mostly off any one plane, so the model is already
constrained by parallax and the check would only cost time. */
constexpr double kPlaneShare = 0.5;

/** A point is on the plane when its image-2 position is within this many thresholds of H x1: the
transfer distance in one image is about twice the Sampson distance for the same noise
(EssentialReport::degenerate uses the same factor). */
constexpr double kPlaneBand = 2.0;

/** At most this many 2-point samples: each costs one MSAC score on all points (about 2 ns per
point), and at 20% off-plane inliers the confidence of 0.999 needs 170 samples. */
constexpr int kMaxParallaxSamples = 500;

/** The homography's own RANSAC (OpenCV's findHomography on the model's inliers, which are mostly
plane points when the check matters). */
constexpr int kHomographyIterations = 2000;
constexpr double kHomographyConfidence = 0.995;

/** The essential matrix nearest to M in Frobenius norm: singular values (1, 1, 0). */
Matx33d nearestEssential(const Matx33d& M)
{
    SVD svd(Mat(M), SVD::FULL_UV);
    const Mat Es = svd.u * Mat::diag((Mat_<double>(3, 1) << 1, 1, 0)) * svd.vt;
    return Matx33d(Es);
}

Vec3d homogeneous(const Point2d& p)
{
    return Vec3d(p.x, p.y, 1.0);
}

} // namespace

PlaneParallaxResult checkPlaneAndParallax(const Problem& problem, const Matx33d& E,
                                          const Score& score, double confidence, RNG& rng)
{
    PlaneParallaxResult result;
    const int n = problem.size();
    std::vector<uchar> mask(static_cast<size_t>(n));
    const int inliers = inlierMask(E, problem, problem.threshold, mask.data());
    if (inliers < 8) return result; // a homography needs 4, and a plane share of it 8 to mean much

    std::vector<Point2d> a, b;
    a.reserve(static_cast<size_t>(inliers));
    b.reserve(static_cast<size_t>(inliers));
    for (int i = 0; i < n; ++i)
        if (mask[i]) {
            a.push_back(problem.p1[i]);
            b.push_back(problem.p2[i]);
        }
    const double band = kPlaneBand * problem.threshold;
    Mat Hm =
        findHomography(a, b, RANSAC, band, noArray(), kHomographyIterations, kHomographyConfidence);
    if (Hm.empty()) return result;
    const Matx33d H(Hm);

    // Plane membership over all points; the rest are the parallax candidates.
    std::vector<int> offPlane;
    offPlane.reserve(static_cast<size_t>(n));
    int onPlaneInliers = 0;
    for (int i = 0; i < n; ++i) {
        const Vec3d m = H * homogeneous(problem.p1[i]);
        bool onPlane = false;
        if (std::abs(m[2]) > 1e-12) {
            const double dx = m[0] / m[2] - problem.p2[i].x, dy = m[1] / m[2] - problem.p2[i].y;
            onPlane = dx * dx + dy * dy <= band * band;
        }
        if (onPlane) {
            ++result.planeInliers;
            onPlaneInliers += mask[i];
        } else {
            offPlane.push_back(i);
        }
    }
    if (onPlaneInliers < kPlaneShare * inliers) return result;
    result.planeFound = true;
    const int m = static_cast<int>(offPlane.size());
    if (m < 2) return result;

    double bestCost = score.cost;
    int needed = kMaxParallaxSamples;
    int idx[2];
    for (int k = 0; k < needed; ++k) {
        ++result.samples;
        drawUniformSample(rng, m, 2, idx);
        const Point2d& a1 = problem.p1[offPlane[idx[0]]];
        const Point2d& a2 = problem.p2[offPlane[idx[0]]];
        const Point2d& b1 = problem.p1[offPlane[idx[1]]];
        const Point2d& b2 = problem.p2[offPlane[idx[1]]];
        const Vec3d la = (H * homogeneous(a1)).cross(homogeneous(a2));
        const Vec3d lb = (H * homogeneous(b1)).cross(homogeneous(b2));
        Vec3d e = la.cross(lb);
        const double len = norm(e);
        if (!(len > 1e-12)) continue; // parallel lines: the two points do not fix the epipole
        e /= len;
        const Matx33d Ex(0, -e[2], e[1], e[2], 0, -e[0], -e[1], e[0], 0);
        const Matx33d candidate = nearestEssential(Ex * H);
        const Score s = scoreMsac(candidate, problem, bestCost);
        if (s.cost < bestCost && s.inliers >= 5) {
            bestCost = s.cost;
            result.E = candidate;
            result.score = s;
            result.improved = true;
            // The off-plane inlier ratio among the candidates for the confidence rule, counting the
            // model's inliers beyond the plane's (an estimate: a few plane points may fall out).
            const int offInliers = s.inliers - onPlaneInliers;
            const double w = std::max(0, offInliers) / double(m);
            needed = std::min(kMaxParallaxSamples,
                              requiredIterations(confidence, w * w, kMaxParallaxSamples));
        }
    }
    return result;
}

} // namespace ransac
} // namespace essential
} // namespace cv

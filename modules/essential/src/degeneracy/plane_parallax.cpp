// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "degeneracy/plane_parallax.hpp"

#include "geometry/essential_decomposition.hpp"
#include "optim/small_linear_solve.hpp"
#include "refine/irls_refinement.hpp"
#include "sampling/uniform_sampler.hpp"

#include <Eigen/Core>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace cv {
namespace essential {
namespace degeneracy {

namespace {

/** The homography must explain at least this share of the model's inliers for the scene to count
as dominated by a plane. Below it the inliers are mostly off any one plane, so the model is already
constrained by parallax and the check would only cost time. */
constexpr double kPlaneShare = 0.5;

/** A point is on the plane when its image-2 position is within this many thresholds of H x1: the
transfer distance in one image is about twice the Sampson distance for the same noise
(EssentialReport::degenerate uses the same factor). */
constexpr double kPlaneBand = 2.0;
constexpr double kMemberBand = 4.0;

/** 2-point samples drawn when a plane dominates: each costs one MSAC score on all points (a small
share of what such a hard call takes: docs/TUNING.md, "Plane and parallax"), and at 12% off-plane
inliers among the candidates (the dominant-plane scenes of the tests) 500 samples
hold a clean pair with probability 0.999. */
constexpr int kMaxParallaxSamples = 500;

/** The best 2-point models by loose cost that are polished and compared (each an IRLS polish). */
constexpr int kPolishedCandidates = 8;

/** The 2-point models are ranked on the points within this many thresholds of them, and
polished by this many IRLS iterations (the search's local optimisation uses 2 thresholds and 5
iterations; a model built on an estimated homography starts further off). */
constexpr double kLooseBand = 3.0;
constexpr int kPolishIterations = 10;

/** The first this many 2-point models give the chance level of off-plane support (their median). */
constexpr int kChanceSamples = 50;

/** A replacement must gain at least this many standard deviations of the chance count (Poisson:
sqrt of the chance level) off the plane. Measured on dominant-plane scenes (30 each at 10, 15 and
25% inliers, 80% of them on the plane; the winner of a search without the check, checked): without
the rule the check turns 21 wrong winners right and 3 right ones wrong (all at 10%, gains of a few
points at chance levels near 10); with 2.5 sigmas, 19 and none. */
constexpr double kSignificance = 2.5;

/** The homography's own RANSAC (OpenCV's findHomography on the model's inliers). The check only
matters when at least kPlaneShare of them are on the plane: then a 4-point sample is clean with
probability >= 0.0625 and 72 samples reach 0.99; a cap of 100 bounds the cost on scenes without a
plane, where it would otherwise run its 2000 default iterations. */
constexpr int kHomographyIterations = 100;
constexpr double kHomographyConfidence = 0.99;

/** Only winners supported by less than this fraction of the points are checked. Above it the
search has drawn many clean samples, most of them with off-plane points, and MSAC has already
preferred the model they support; and even the plane probes would be a large share of an easy
call (docs/TUNING.md, "Plane and parallax"). */
constexpr double kMaxCheckedInlierRatio = 0.5;

Vec3d homogeneous(const Point2d& p)
{
    return Vec3d(p.x, p.y, 1.0);
}

/** Whether H maps a to within `band` of b (transfer distance in image 2; false when H sends a to
infinity). */
bool transfersWithin(const Matx33d& H, const Point2d& a, const Point2d& b, double band)
{
    const Vec3d m = H * homogeneous(a);
    if (!(std::abs(m[2]) > 1e-12)) return false;
    const double dx = m[0] / m[2] - b.x, dy = m[1] / m[2] - b.y;
    return dx * dx + dy * dy <= band * band;
}

/** The homography through four correspondences (h33 = 1; 8 x 8 linear system, solved in fixed
size: cv::solve converts its arguments to cv::Mat and allocates, about nine tenths of a probe's
cost, and the probes run on every call below kMaxCheckedInlierRatio). False when the system is
singular to working precision or its solution not finite (three of the points collinear, exactly
or so nearly that the homography overflows); a homography of nearly collinear points that survives
is extreme and explains no probe points. */
bool homographyOf4(const Point2d* a, const Point2d* b, Matx33d& H)
{
    Eigen::Matrix<double, 8, 8> A;
    Eigen::Matrix<double, 8, 1> rhs, h;
    for (int i = 0; i < 4; ++i) {
        const double x = a[i].x, y = a[i].y, u = b[i].x, v = b[i].y;
        A.row(2 * i) << x, y, 1, 0, 0, 0, -u * x, -u * y;
        A.row(2 * i + 1) << 0, 0, 0, x, y, 1, -v * x, -v * y;
        rhs[2 * i] = u;
        rhs[2 * i + 1] = v;
    }
    if (!optim::solvePartialPivot<8>(A, rhs, h)) return false;
    H = Matx33d(h[0], h[1], h[2], h[3], h[4], h[5], h[6], h[7], 1.0);
    return true;
}

/** A quick test for a plane among the inliers before the full homography fit: kPlaneProbes
4-point homographies of random inliers, each checked on kProbePoints random inliers within
kProbeBand plane bands (a homography through four noisy points is off away from them); true when
one explains at least kProbeShare of them. With half of the inliers on a plane a probe's sample is
clean with probability 1/16, so 40 probes miss it with probability 0.08 (0.00003 at 80%); on
scenes without a plane it costs a tenth of the full fit (docs/TUNING.md, "Plane and parallax"). */
constexpr int kPlaneProbes = 40;
constexpr int kProbePoints = 32;
constexpr double kProbeShare = 0.3;
constexpr double kProbeBand = 3.0;

bool planeLikely(const std::vector<Point2d>& a, const std::vector<Point2d>& b, double band,
                 RNG& rng)
{
    const int n = static_cast<int>(a.size());
    const double probeBand = kProbeBand * band;
    int idx[4];
    Point2d pa[4], pb[4];
    for (int probe = 0; probe < kPlaneProbes; ++probe) {
        sampling::drawUniformSample(rng, n, 4, idx);
        for (int i = 0; i < 4; ++i) {
            pa[i] = a[static_cast<size_t>(idx[i])];
            pb[i] = b[static_cast<size_t>(idx[i])];
        }
        Matx33d H;
        if (!homographyOf4(pa, pb, H)) continue;
        int on = 0;
        for (int k = 0; k < kProbePoints; ++k) {
            const size_t i = static_cast<size_t>(rng.uniform(0, n));
            on += transfersWithin(H, a[i], b[i], probeBand);
        }
        if (on >= kProbeShare * kProbePoints) return true;
    }
    return false;
}

} // namespace

PlaneParallaxResult checkPlaneAndParallax(const Problem& problem, InlierTest test, const Matx33d& E,
                                          const scoring::Score& score, RNG& rng)
{
    PlaneParallaxResult result;
    const int n = problem.size();
    std::vector<uchar> mask(static_cast<size_t>(n));
    const int inliers = scoring::inlierMask(E, problem, test, mask.data());
    if (inliers < 8) return result; // a homography needs 4, and a plane share of it 8 to mean much
    if (inliers >= kMaxCheckedInlierRatio * n) return result;

    std::vector<Point2d> a, b;
    a.reserve(static_cast<size_t>(inliers));
    b.reserve(static_cast<size_t>(inliers));
    for (int i = 0; i < n; ++i)
        if (mask[i]) {
            a.push_back(problem.point1(i));
            b.push_back(problem.point2(i));
        }
    const double band = kPlaneBand * test.threshold;
    if (!planeLikely(a, b, band, rng)) return result;
    Mat Hm =
        findHomography(a, b, RANSAC, band, noArray(), kHomographyIterations, kHomographyConfidence);
    if (Hm.empty()) return result;
    const Matx33d H(Hm);

    // Plane membership over all points; the rest are the parallax candidates. The band is wider
    // than the fit's: with noise near the threshold (1 px noise, 1 px threshold) the transfer error
    // of a plane point exceeds 2 thresholds a third of the time, and those points, put among the
    // candidates, outnumber the true off-plane inliers; 4 thresholds keep 98% of them on the plane
    // (points with less parallax than that say little about the epipole anyway).
    const double memberBand = kMemberBand * test.threshold;
    std::vector<int> offPlane;
    offPlane.reserve(static_cast<size_t>(n));
    int onPlaneInliers = 0;
    for (int i = 0; i < n; ++i) {
        if (transfersWithin(H, problem.point1(i), problem.point2(i), memberBand)) {
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

    // The points off the plane as a problem of their own, to count a model's inliers among them.
    const Problem off = subsetProblem(problem, offPlane.data(), m);
    std::vector<uchar> offMask(static_cast<size_t>(m));
    auto offInliers = [&](const Matx33d& model) {
        return scoring::inlierMask(model, off, test, offMask.data());
    };
    result.offPlaneBefore = offInliers(E);
    std::vector<int> chance;

    // Each off-plane correspondence's line (H x1) x x2 through the epipole, scaled to unit normal
    // so that l . e is a point-line distance in image 2.
    std::vector<Vec3d> lines(static_cast<size_t>(m));
    for (int k = 0; k < m; ++k) {
        const int i = offPlane[static_cast<size_t>(k)];
        Vec3d l = (H * homogeneous(problem.point1(i))).cross(homogeneous(problem.point2(i)));
        const double len = std::sqrt(l[0] * l[0] + l[1] * l[1]);
        lines[static_cast<size_t>(k)] = len > 1e-15 ? l / len : Vec3d(0, 0, 0);
    }
    auto essentialOf = [&](Vec3d e) {
        e /= norm(e);
        const Matx33d M = Matx33d(0, -e[2], e[1], e[2], 0, -e[0], -e[1], e[0], 0) * H;
        Eigen::Matrix3d m;
        cv2eigen(M, m);
        Matx33d model;
        eigen2cv(Eigen::Matrix3d(geometry::nearestEssential(m)), model);
        return model;
    };
    // A model [e']x H carries the homography's error: H fitted to a plane seen in part of the image
    // is off in its projective part by enough that [t]x H with the true t keeps only half of the
    // true inliers within the threshold (measured on the dominant-plane scenes of the tests). So
    // the pairs are ranked with a looser band, and each new best is polished in all five degrees
    // of freedom (IRLS on the points within that band, as the search's local optimisation) before
    // it is compared with the model checked.
    // Every candidate fits the plane through H, so only the points off it rank them.
    const InlierTest loose = test.withThreshold(kLooseBand * test.threshold);
    double bestCost = score.cost;
    std::vector<uchar> near(static_cast<size_t>(n));
    auto polishAndCompare = [&](const Matx33d& candidate) {
        if (scoring::inlierMask(candidate, problem, loose, near.data()) < 5) return;
        const Problem subset = maskedProblem(problem, near.data());
        refine::IrlsSettings irls;
        irls.maxIterations = kPolishIterations;
        const refine::IrlsResult polished =
            refine::refineIrls(subset, candidate, test.threshold, irls);
        const Matx33d E2 = polished.improved ? polished.E : candidate;
        const scoring::Score s = scoring::scoreMsac(E2, problem, test, bestCost);
        if (s.cost < bestCost && s.inliers >= 5) {
            bestCost = s.cost;
            result.E = E2;
            result.score = s;
            result.improved = true;
        }
    };

    // The kPolishedCandidates best 2-point models by their loose cost, polished at the end: the
    // loose ranking of unpolished models is noisy (a model from a clean pair with a short parallax
    // can rank below one that gathered outliers), so the best one alone is not enough.
    std::vector<std::pair<double, Matx33d>> pool;
    pool.reserve(kPolishedCandidates + 1);
    int idx[2];
    for (int k = 0; k < kMaxParallaxSamples; ++k) {
        ++result.samples;
        sampling::drawUniformSample(rng, m, 2, idx);
        const Vec3d e =
            lines[static_cast<size_t>(idx[0])].cross(lines[static_cast<size_t>(idx[1])]);
        if (!(norm(e) > 1e-12)) continue; // parallel lines: the two points do not fix the epipole
        const Matx33d candidate = essentialOf(e);
        if (static_cast<int>(chance.size()) < kChanceSamples)
            chance.push_back(offInliers(candidate));
        const double worst =
            pool.size() < static_cast<size_t>(kPolishedCandidates) ? HUGE_VAL : pool.back().first;
        const scoring::Score s = scoring::scoreMsac(candidate, off, loose, worst);
        if (!(s.cost < worst)) continue;
        pool.emplace_back(s.cost, candidate);
        std::sort(pool.begin(), pool.end(),
                  [](const std::pair<double, Matx33d>& x, const std::pair<double, Matx33d>& y) {
                      return x.first < y.first;
                  });
        if (pool.size() > static_cast<size_t>(kPolishedCandidates)) pool.pop_back();
    }
    for (const auto& entry : pool)
        polishAndCompare(entry.second);
    if (!chance.empty()) {
        std::nth_element(chance.begin(), chance.begin() + chance.size() / 2, chance.end());
        result.offPlaneChance = chance[chance.size() / 2];
    }
    if (result.improved) {
        result.offPlaneAfter = offInliers(result.E);
        // A polished model slides along the family of models that fit the plane and can gather
        // outliers by chance: keep it only when its gain off the plane clearly exceeds chance.
        const double gain = result.offPlaneAfter - result.offPlaneBefore;
        if (gain < kSignificance * std::sqrt(result.offPlaneChance + 1.0)) result.improved = false;
    }
    return result;
}

} // namespace degeneracy
} // namespace essential
} // namespace cv

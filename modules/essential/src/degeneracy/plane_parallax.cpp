// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "degeneracy/plane_parallax.hpp"

#include "geometry/essential_decomposition.hpp"
#include "optim/small_linear_solve.hpp"
#include "refine/irls_refinement.hpp"
#include "sampling/uniform_sampler.hpp"

#include <Eigen/Core>
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

/** A plane among the inliers, found by sampling: kPlaneProbes 4-point homographies of random
inliers, each checked on kProbePoints random inliers within kProbeBand plane bands (a homography
through four noisy points is off away from them). True when one explains at least kProbeShare of
them; probeH is then the probe that explains the most, the start of fitPlane. With half of the
inliers on a plane a probe's sample is clean with probability 1/16, so 40 probes miss it with
probability 0.08 (0.00003 at 80%). Every probe runs when one passes, because stopping at the first
can start the fit on a smaller plane than the dominant one (measured, with the fit below: FAST-9
real pairs AUC@5 0.493 stopping at the first against 0.497 with the best, OpenCV's findHomography
0.495; essential_hard_pairs' synthetic repeated structure 141 against 142 of 200 right). */
constexpr int kPlaneProbes = 40;
constexpr int kProbePoints = 32;
constexpr double kProbeShare = 0.3;
constexpr double kProbeBand = 3.0;

bool planeLikely(const std::vector<Point2d>& a, const std::vector<Point2d>& b, double band,
                 RNG& rng, Matx33d& probeH)
{
    const int n = static_cast<int>(a.size());
    const double probeBand = kProbeBand * band;
    int idx[4];
    Point2d pa[4], pb[4];
    int bestOn = -1;
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
        if (on >= kProbeShare * kProbePoints && on > bestOn) {
            probeH = H;
            bestOn = on;
        }
    }
    return bestOn >= 0;
}

/** The homography of the plane the best probe found, H on entry: up to kFitRounds rounds of a
linear least-squares fit (h33 = 1, on the points centred and scaled to unit mean distance in each
image) to the inliers H transfers within the band, the first round within the probe's kProbeBand
bands (a homography through four noisy points is off away from them), then within one band,
stopping once the set stops growing. It replaces OpenCV's findHomography (RANSAC, then
Levenberg-Marquardt), whose 100 iterations on the inliers of one call at 50% inliers (N = 500) took
about 8.3 M instructions, some 400 five-point solves (callgrind): the best probe already is the
plane's sample, and what the check needs of H is which points it transfers within 4 thresholds.
Against findHomography on the same data: the synthetic dominant-plane scenes of
essential_hard_pairs 122 -> 130 of 200 right, the other hard sets the same; the real pairs' AUC@5
with SIFT the same (0.766, the drop-in; seeds 1-4 of `ours` the same or +0.002) and with FAST-9
0.495 -> 0.497. Four rounds: the set still grows in the fourth in 15% of 363 fits (the synthetic
plane scenes and the SIFT pairs), but eight measured no better (FAST-9 AUC@5 0.494, the rest the
same). False when fewer than 8 points are within the band or the fit is singular. */
constexpr int kFitRounds = 4;

bool fitPlane(const std::vector<Point2d>& a, const std::vector<Point2d>& b, double band, Matx33d& H)
{
    const int n = static_cast<int>(a.size());
    // Centring and scaling (Hartley's normalisation) keeps the normal equations well conditioned.
    Point2d ca(0, 0), cb(0, 0);
    for (int i = 0; i < n; ++i) {
        ca += a[i];
        cb += b[i];
    }
    ca *= 1.0 / n;
    cb *= 1.0 / n;
    double sa = 0.0, sb = 0.0;
    for (int i = 0; i < n; ++i) {
        sa += std::hypot(a[i].x - ca.x, a[i].y - ca.y);
        sb += std::hypot(b[i].x - cb.x, b[i].y - cb.y);
    }
    if (!(sa > 0.0) || !(sb > 0.0)) return false;
    sa = n / sa;
    sb = n / sb;
    const Matx33d Ta(sa, 0, -sa * ca.x, 0, sa, -sa * ca.y, 0, 0, 1);
    const Matx33d TbInverse(1.0 / sb, 0, cb.x, 0, 1.0 / sb, cb.y, 0, 0, 1);
    int previous = 0;
    for (int round = 0; round < kFitRounds; ++round) {
        const double roundBand = round == 0 ? kProbeBand * band : band;
        Eigen::Matrix<double, 8, 8> A = Eigen::Matrix<double, 8, 8>::Zero();
        Eigen::Matrix<double, 8, 1> rhs = Eigen::Matrix<double, 8, 1>::Zero();
        int count = 0;
        for (int i = 0; i < n; ++i) {
            if (!transfersWithin(H, a[i], b[i], roundBand)) continue;
            ++count;
            const double x = sa * (a[i].x - ca.x), y = sa * (a[i].y - ca.y);
            const double u = sb * (b[i].x - cb.x), v = sb * (b[i].y - cb.y);
            Eigen::Matrix<double, 8, 1> r0, r1;
            r0 << x, y, 1, 0, 0, 0, -u * x, -u * y;
            r1 << 0, 0, 0, x, y, 1, -v * x, -v * y;
            A.selfadjointView<Eigen::Lower>().rankUpdate(r0);
            A.selfadjointView<Eigen::Lower>().rankUpdate(r1);
            rhs += u * r0 + v * r1;
        }
        if (count < 8) return false;
        if (round > 1 && count <= previous) break;
        previous = count;
        A = A.selfadjointView<Eigen::Lower>();
        Eigen::Matrix<double, 8, 1> h;
        if (!optim::solvePartialPivot<8>(A, rhs, h)) return false;
        const Matx33d Hn(h[0], h[1], h[2], h[3], h[4], h[5], h[6], h[7], 1.0);
        H = TbInverse * Hn * Ta;
    }
    return true;
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
    Matx33d H;
    if (!planeLikely(a, b, band, rng, H) || !fitPlane(a, b, band, H)) return result;

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

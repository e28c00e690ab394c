// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Synthetic two-view scenes reproducing the failure modes of essential-matrix estimation on real
// pairs with few inliers (bench/hard_pairs.cpp, test/test_hard_scenes.cpp):
//
// - DominantPlane: most inliers on one world plane (a homography explains them, and several poses
//   fit a plane equally well), the rest off the plane at varied depths; outliers uniform.
// - RepeatedStructure: part of the outliers come in groups of wrong matches that are all shifted
//   by the same image offset (a repeated pattern's period) from their true position, the points
//   of a group on one planar patch, so that each group is a consistent wrong model with support;
//   the other outliers uniform.
// - ClusteredInliers: the inliers sit in 2-3 small discs of image 1 (textured patches), which
//   makes minimal samples ill-conditioned; outliers uniform.
//
// A pixel camera (800 x 600, f = 640 px by default) moves by a rotation of up to 15 degrees and a
// unit baseline in a random direction; scene depths 4 to 20 baselines give parallax of 30 to 160
// px. Every point is in front of both cameras and inside both images; noise is Gaussian on pixel
// coordinates (1 px). Each match carries a "descriptor distance" whose distribution depends on its
// kind (inliers and shifted outliers look alike, uniform outliers look worse), so that sorting by
// it gives PROSAC imperfect quality information. Header-only, like synthetic_scene.hpp, whose
// rotation helpers it uses.

#ifndef OPENCV_ESSENTIAL_TEST_HARD_SCENES_HPP
#define OPENCV_ESSENTIAL_TEST_HARD_SCENES_HPP

#include "synthetic_scene.hpp"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace essential_test {

/** Camera, motion, sizes and descriptor distances shared by the hard scenes. */
struct HardSceneConfig
{
    int numPoints = 1000;      //!< matches in total (inliers + outliers)
    double inlierRatio = 0.15; //!< fraction of correct matches (the bench uses 0.05 to 0.25)
    int width = 800, height = 600;
    double focal = 640.0;         //!< pixels; principal point at the image centre
    double noisePx = 1.0;         //!< Gaussian noise on every pixel coordinate of a true match
    double maxRotationDeg = 15.0; //!< rotation angle uniform in [0, max], axis uniform
    double baseline = 1.0;        //!< camera-2 centre at distance `baseline`, direction uniform
    double minDepth = 4.0;        //!< depths of free 3D points: inverse depth uniform in
    double maxDepth = 20.0;       //!< [1 / maxDepth, 1 / minDepth] (in baselines)
    /** A wrong match is redrawn while it lies within this many noise sigmas (Sampson distance) of
    the true E: it would be a correct match in all but name. */
    double outlierMinSigmas = 3.0;
    /** Descriptor distances: true matches and shifted (look-alike) outliers ~ N(goodMean, sigma),
    uniform outliers ~ N(badMean, sigma), clamped at 0. */
    double goodDistanceMean = 35.0, badDistanceMean = 50.0, distanceSigma = 12.0;
};

struct DominantPlaneConfig : HardSceneConfig
{
    double planeFraction = 0.8; //!< fraction of the inliers on the plane
    double maxTiltDeg = 45.0;   //!< angle between the plane's normal and camera 1's axis
    /** An off-plane inlier's noise-free image-2 point is at least this many noise sigmas from
    where the plane's homography sends its image-1 point (else it is on the plane in all but
    name). */
    double offPlaneMinSigmas = 6.0;
};

struct RepeatedStructureConfig : HardSceneConfig
{
    double shiftedFraction = 0.5; //!< fraction of the outliers that are shifted look-alikes
    int numGroups = 3;            //!< groups of shifted outliers, each with its own offset
    double minPeriodPx = 20.0, maxPeriodPx = 60.0; //!< length of a group's offset
    double groupRadiusFraction = 0.1;              //!< a group's disc in image 1, in image widths
    /** Least angle between a group's offset and the true epipolar line at its centre: an offset
    along the line would make the group consistent with the true E. */
    double minOffsetAngleDeg = 30.0;
};

struct ClusteredInliersConfig : HardSceneConfig
{
    int numClusters = 3;                //!< discs holding the inliers' image-1 points
    double clusterRadiusFraction = 0.1; //!< disc radius in image widths
};

/** What a match is. */
enum class MatchRole {
    Inlier,         //!< a true match of a free 3D point
    PlaneInlier,    //!< a true match of a point on the dominant plane
    UniformOutlier, //!< independent uniform points in both images
    ShiftedOutlier  //!< true image-2 point of a 3D point plus its group's offset
};

struct HardScene
{
    std::vector<cv::Point2d> x1, x2;   //!< normalised coordinates (K^-1 px)
    std::vector<cv::Point2d> px1, px2; //!< pixel coordinates
    std::vector<bool> inlier;
    std::vector<MatchRole> role;
    std::vector<int> group;      //!< shifted outliers: group; clustered inliers: cluster; else -1
    std::vector<float> distance; //!< descriptor distance (lower is better)
    cv::Matx33d K, R;            //!< X2 = R X1 + baseline * t
    cv::Vec3d t;                 //!< unit translation direction
    double baseline = 0.0;
    cv::Matx33d E, F; //!< [t]x R and K^-T E K^-1
    cv::Size imageSize;
    int numInliers = 0;

    // DominantPlane: n . X1 = planeOffset in camera 1's frame; its pixel homography image 1 -> 2.
    cv::Vec3d planeNormal = cv::Vec3d(0, 0, 0);
    double planeOffset = 0.0;
    cv::Matx33d planeHomography = cv::Matx33d::eye();

    // RepeatedStructure: per group its offset and its disc in image 1.
    std::vector<cv::Point2d> groupOffsets, groupCentres;
    double groupRadiusPx = 0.0;

    // ClusteredInliers: the discs in image 1.
    std::vector<cv::Point2d> clusterCentres;
    double clusterRadiusPx = 0.0;
};

/** Sampson distance in pixels of the pixel match (p1, p2) to the fundamental matrix F; HUGE_VAL
when the epipolar gradient vanishes. */
inline double sampsonPx(const cv::Matx33d& F, const cv::Point2d& p1, const cv::Point2d& p2)
{
    const cv::Vec3d a(p1.x, p1.y, 1.0), b(p2.x, p2.y, 1.0);
    const cv::Vec3d Fa = F * a, Ftb = F.t() * b;
    const double r = b.dot(Fa);
    const double g = Fa[0] * Fa[0] + Fa[1] * Fa[1] + Ftb[0] * Ftb[0] + Ftb[1] * Ftb[1];
    return g > 0.0 ? std::abs(r) / std::sqrt(g) : HUGE_VAL;
}

/** Where the pixel homography H sends p. */
inline cv::Point2d applyHomography(const cv::Matx33d& H, const cv::Point2d& p)
{
    const cv::Vec3d q = H * cv::Vec3d(p.x, p.y, 1.0);
    return cv::Point2d(q[0] / q[2], q[1] / q[2]);
}

namespace hard_detail {

/** The camera pair, the random source and the matches under construction. */
class Builder
{
public:
    Builder(const HardSceneConfig& cfg, uint64_t seed) : cfg_(cfg), g_(seed) {}

    const HardSceneConfig& cfg() const { return cfg_; }
    std::mt19937_64& rng() { return g_; }
    double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(g_); }

    int numInliers() const
    {
        return static_cast<int>(std::lround(cfg_.numPoints * cfg_.inlierRatio));
    }

    /** A new random motion; clears the matches. */
    void drawMotion()
    {
        s_ = HardScene();
        s_.imageSize = cv::Size(cfg_.width, cfg_.height);
        s_.K = cv::Matx33d(cfg_.focal, 0, 0.5 * (cfg_.width - 1), 0, cfg_.focal,
                           0.5 * (cfg_.height - 1), 0, 0, 1);
        s_.R = axisAngle(randomUnit(g_), uniform(0.0, cfg_.maxRotationDeg) * CV_PI / 180.0);
        s_.t = randomUnit(g_);
        s_.baseline = cfg_.baseline;
        s_.E = skewMatrix(s_.t) * s_.R;
        const cv::Matx33d Kinv = s_.K.inv();
        s_.F = Kinv.t() * s_.E * Kinv;
    }

    HardScene& scene() { return s_; }

    /** Camera-1 point at `depth` along the ray through pixel p of image 1. */
    cv::Vec3d backProject(const cv::Point2d& p, double depth) const
    {
        return depth *
               cv::Vec3d((p.x - s_.K(0, 2)) / cfg_.focal, (p.y - s_.K(1, 2)) / cfg_.focal, 1.0);
    }

    cv::Vec3d ray(const cv::Point2d& p) const { return backProject(p, 1.0); }

    /** Projects the camera-1 point X1 into image 2; false when behind camera 2. */
    bool projectToImage2(const cv::Vec3d& X1, cv::Point2d& p) const
    {
        const cv::Vec3d X2 = s_.R * X1 + s_.baseline * s_.t;
        if (X2[2] <= 1e-6) return false;
        p = cv::Point2d(cfg_.focal * X2[0] / X2[2] + s_.K(0, 2),
                        cfg_.focal * X2[1] / X2[2] + s_.K(1, 2));
        return true;
    }

    bool inside(const cv::Point2d& p) const
    {
        return p.x >= 0 && p.y >= 0 && p.x < cfg_.width && p.y < cfg_.height;
    }

    cv::Point2d uniformPixel() { return {uniform(0.0, cfg_.width), uniform(0.0, cfg_.height)}; }

    /** A pixel uniform in the disc (centre, radius). */
    cv::Point2d pixelInDisc(const cv::Point2d& centre, double radius)
    {
        const double r = radius * std::sqrt(uniform(0.0, 1.0)), a = uniform(0.0, 2 * CV_PI);
        return centre + cv::Point2d(r * std::cos(a), r * std::sin(a));
    }

    double freeDepth() { return 1.0 / uniform(1.0 / cfg_.maxDepth, 1.0 / cfg_.minDepth); }

    cv::Point2d noisy(const cv::Point2d& p)
    {
        std::normal_distribution<double> n(0.0, cfg_.noisePx);
        return p + cv::Point2d(n(g_), n(g_));
    }

    float distance(bool looksGood)
    {
        std::normal_distribution<double> n(looksGood ? cfg_.goodDistanceMean : cfg_.badDistanceMean,
                                           cfg_.distanceSigma);
        return static_cast<float>(std::max(0.0, n(g_)));
    }

    /** Noisy true match of the camera-1 point X1 seen at pixel p1 of image 1 (plus `shift` in
    image 2); false when it is not in front of camera 2 or leaves either image. */
    bool trueMatch(const cv::Point2d& p1, const cv::Vec3d& X1, const cv::Point2d& shift,
                   cv::Point2d& q1, cv::Point2d& q2)
    {
        cv::Point2d p2;
        if (X1[2] <= 1e-6 || !projectToImage2(X1, p2)) return false;
        q1 = noisy(p1);
        q2 = noisy(p2 + shift);
        return inside(q1) && inside(q2);
    }

    void add(const cv::Point2d& q1, const cv::Point2d& q2, MatchRole role, int group)
    {
        const bool in = role == MatchRole::Inlier || role == MatchRole::PlaneInlier;
        pending_.push_back({q1, q2, role, group, distance(role != MatchRole::UniformOutlier), in});
    }

    int pendingCount() const { return static_cast<int>(pending_.size()); }

    /** Drops the matches added since `count`. */
    void truncate(int count) { pending_.resize(static_cast<size_t>(count)); }

    /** Uniform outliers until numPoints matches, each redrawn while it fits the true E. */
    void fillUniformOutliers()
    {
        const double minDist = cfg_.outlierMinSigmas * cfg_.noisePx;
        while (pendingCount() < cfg_.numPoints) {
            const cv::Point2d q1 = uniformPixel(), q2 = uniformPixel();
            if (sampsonPx(s_.F, q1, q2) < minDist) continue;
            add(q1, q2, MatchRole::UniformOutlier, -1);
        }
    }

    /** Shuffles the matches into the scene and returns it. */
    HardScene finish()
    {
        std::shuffle(pending_.begin(), pending_.end(), g_);
        for (const Pending& m : pending_) {
            s_.px1.push_back(m.q1);
            s_.px2.push_back(m.q2);
            s_.x1.push_back(normalised(m.q1));
            s_.x2.push_back(normalised(m.q2));
            s_.inlier.push_back(m.inlier);
            s_.role.push_back(m.role);
            s_.group.push_back(m.group);
            s_.distance.push_back(m.distance);
            s_.numInliers += m.inlier ? 1 : 0;
        }
        pending_.clear();
        return s_;
    }

private:
    struct Pending
    {
        cv::Point2d q1, q2;
        MatchRole role;
        int group;
        float distance;
        bool inlier;
    };

    cv::Point2d normalised(const cv::Point2d& p) const
    {
        return {(p.x - s_.K(0, 2)) / cfg_.focal, (p.y - s_.K(1, 2)) / cfg_.focal};
    }

    HardSceneConfig cfg_;
    std::mt19937_64 g_;
    HardScene s_;
    std::vector<Pending> pending_;
};

/** A random plane normal tilted by up to maxTiltDeg from camera 1's axis, facing camera 1. */
inline cv::Vec3d tiltedNormal(Builder& b, double maxTiltDeg)
{
    const double azimuth = b.uniform(0.0, 2 * CV_PI);
    const cv::Vec3d axis(std::cos(azimuth), std::sin(azimuth), 0.0);
    return axisAngle(axis, b.uniform(0.0, maxTiltDeg) * CV_PI / 180.0) * cv::Vec3d(0, 0, -1);
}

/** Depth along `ray` of the plane n . X = offset; <= 0 when the ray does not meet it in front. */
inline double planeDepth(const cv::Vec3d& n, double offset, const cv::Vec3d& ray)
{
    const double d = n.dot(ray);
    return std::abs(d) < 1e-12 ? -1.0 : offset / d;
}

/** Adds `count` true matches of free 3D points (pixel from `pixel()`, inverse-uniform depth)
accepted by `keep(p1, X1, q2)`; false when too few are visible (the caller redraws). */
template <class Pixel, class Keep>
bool addFreeInliers(Builder& b, int count, int group, Pixel pixel, Keep keep)
{
    const long maxTries = 200L * count + 1000;
    int added = 0;
    for (long tries = 0; added < count && tries < maxTries; ++tries) {
        const cv::Point2d p1 = pixel();
        const cv::Vec3d X1 = b.backProject(p1, b.freeDepth());
        cv::Point2d q1, q2;
        if (!b.trueMatch(p1, X1, cv::Point2d(0, 0), q1, q2) || !keep(p1, X1)) continue;
        b.add(q1, q2, MatchRole::Inlier, group);
        ++added;
    }
    return added == count;
}

/** Up to 100 redraws of the whole scene; throws when none works (a config that cannot be met). */
template <class Attempt> HardScene build(Builder& b, const char* what, Attempt attempt)
{
    for (int redraw = 0; redraw < 100; ++redraw) {
        b.drawMotion();
        b.truncate(0);
        if (attempt()) {
            b.fillUniformOutliers();
            return b.finish();
        }
    }
    throw std::runtime_error(std::string(what) + ": no scene after 100 draws (config too strict)");
}

} // namespace hard_detail

/** planeFraction of the inliers on one plane (through a point 6 to 12 baselines deep in image 1's
central half, tilted by up to maxTiltDeg, both cameras on the same side, covering at least 30% of
image 1's pixels that image 2 sees), the rest free 3D points off the plane; uniform outliers. */
inline HardScene makeDominantPlane(const DominantPlaneConfig& cfg, uint64_t seed)
{
    hard_detail::Builder b(cfg, seed);
    return hard_detail::build(b, "makeDominantPlane", [&]() {
        HardScene& s = b.scene();
        const cv::Point2d c(b.uniform(0.25, 0.75) * cfg.width, b.uniform(0.25, 0.75) * cfg.height);
        const cv::Vec3d P0 = b.backProject(c, b.uniform(6.0, 12.0));
        const cv::Vec3d n = hard_detail::tiltedNormal(b, cfg.maxTiltDeg);
        const double offset = n.dot(P0);
        const cv::Vec3d C2 = -(s.R.t() * (s.baseline * s.t)); // camera 2's centre, frame 1
        if ((n.dot(C2) - offset) * (0.0 - offset) <= 0.0) return false;
        s.planeNormal = n;
        s.planeOffset = offset;
        const cv::Matx33d Hn = s.R + s.baseline * s.t * (n * (1.0 / offset)).t();
        s.planeHomography = s.K * Hn * s.K.inv();

        const int inliers = b.numInliers();
        const int onPlane = static_cast<int>(std::lround(inliers * cfg.planeFraction));
        int added = 0;
        long tries = 0;
        for (; added < onPlane && tries < 200L * onPlane + 1000; ++tries) {
            const cv::Point2d p1 = b.uniformPixel();
            const double depth = hard_detail::planeDepth(n, offset, b.ray(p1));
            if (!(depth > 0.5 * cfg.minDepth && depth < 3.0 * cfg.maxDepth)) continue;
            cv::Point2d q1, q2;
            if (!b.trueMatch(p1, b.backProject(p1, depth), cv::Point2d(0, 0), q1, q2)) continue;
            b.add(q1, q2, MatchRole::PlaneInlier, -1);
            ++added;
        }
        // Coverage: the plane must fill a good part of the image (acceptance of uniform pixels).
        if (added < onPlane || added < 0.3 * tries) return false;
        const double minOff = cfg.offPlaneMinSigmas * cfg.noisePx;
        return hard_detail::addFreeInliers(
            b, inliers - onPlane, -1, [&]() { return b.uniformPixel(); },
            [&](const cv::Point2d& p1, const cv::Vec3d& X1) {
                cv::Point2d p2;
                b.projectToImage2(X1, p2);
                return cv::norm(p2 - applyHomography(s.planeHomography, p1)) >= minOff;
            });
    });
}

/** Free 3D inliers over the whole image; shiftedFraction of the outliers in numGroups groups, each
a planar patch seen in a disc of image 1 whose image-2 points are their true projections plus the
group's offset (length minPeriodPx to maxPeriodPx, at least minOffsetAngleDeg from the true
epipolar line at the disc's centre; a point that still fits the true E is redrawn); the other
outliers uniform. */
inline HardScene makeRepeatedStructure(const RepeatedStructureConfig& cfg, uint64_t seed)
{
    hard_detail::Builder b(cfg, seed);
    return hard_detail::build(b, "makeRepeatedStructure", [&]() {
        HardScene& s = b.scene();
        const int inliers = b.numInliers();
        if (!hard_detail::addFreeInliers(
                b, inliers, -1, [&]() { return b.uniformPixel(); },
                [](const cv::Point2d&, const cv::Vec3d&) { return true; }))
            return false;
        const int shifted =
            static_cast<int>(std::lround((cfg.numPoints - inliers) * cfg.shiftedFraction));
        const double radius = cfg.groupRadiusFraction * cfg.width;
        const double minDist = cfg.outlierMinSigmas * cfg.noisePx;
        const double maxCos = std::cos(cfg.minOffsetAngleDeg * CV_PI / 180.0);
        s.groupRadiusPx = radius;
        for (int gi = 0; gi < cfg.numGroups; ++gi) {
            const int count = shifted / cfg.numGroups + (gi < shifted % cfg.numGroups ? 1 : 0);
            bool done = false;
            for (int redraw = 0; redraw < 50 && !done; ++redraw) {
                const cv::Point2d c(b.uniform(radius, cfg.width - radius),
                                    b.uniform(radius, cfg.height - radius));
                // The offset: away from the true epipolar line through the centre's match.
                const cv::Vec3d line = s.F * cv::Vec3d(c.x, c.y, 1.0);
                const cv::Point2d along =
                    cv::Point2d(line[1], -line[0]) * (1.0 / std::hypot(line[0], line[1]));
                const double angle = b.uniform(0.0, 2 * CV_PI);
                const cv::Point2d dir(std::cos(angle), std::sin(angle));
                if (std::abs(dir.dot(along)) > maxCos) continue;
                const cv::Point2d offset = dir * b.uniform(cfg.minPeriodPx, cfg.maxPeriodPx);
                // The patch: a plane at a free depth through the disc's centre ray.
                const cv::Vec3d n = hard_detail::tiltedNormal(b, 45.0);
                const double planeOffset = n.dot(b.backProject(c, b.freeDepth()));
                const int start = b.pendingCount();
                int added = 0;
                for (long tries = 0; added < count && tries < 200L * count + 1000; ++tries) {
                    const cv::Point2d p1 = b.pixelInDisc(c, radius);
                    const double depth = hard_detail::planeDepth(n, planeOffset, b.ray(p1));
                    if (!(depth > 0.5 * cfg.minDepth)) continue;
                    cv::Point2d q1, q2;
                    if (!b.trueMatch(p1, b.backProject(p1, depth), offset, q1, q2) ||
                        sampsonPx(s.F, q1, q2) < minDist)
                        continue;
                    b.add(q1, q2, MatchRole::ShiftedOutlier, gi);
                    ++added;
                }
                if (added < count) {
                    b.truncate(start);
                    continue;
                }
                s.groupCentres.push_back(c);
                s.groupOffsets.push_back(offset);
                done = true;
            }
            if (!done) return false;
        }
        return true;
    });
}

/** The inliers: free 3D points whose image-1 points lie in numClusters discs (radius
clusterRadiusFraction image widths, inside the image), as many per disc; uniform outliers. */
inline HardScene makeClusteredInliers(const ClusteredInliersConfig& cfg, uint64_t seed)
{
    hard_detail::Builder b(cfg, seed);
    return hard_detail::build(b, "makeClusteredInliers", [&]() {
        HardScene& s = b.scene();
        const int inliers = b.numInliers();
        const double radius = cfg.clusterRadiusFraction * cfg.width;
        s.clusterRadiusPx = radius;
        for (int ci = 0; ci < cfg.numClusters; ++ci) {
            const int count = inliers / cfg.numClusters + (ci < inliers % cfg.numClusters ? 1 : 0);
            bool done = false;
            for (int redraw = 0; redraw < 50 && !done; ++redraw) {
                const cv::Point2d c(b.uniform(radius, cfg.width - radius),
                                    b.uniform(radius, cfg.height - radius));
                const int start = b.pendingCount();
                done = hard_detail::addFreeInliers(
                    b, count, ci, [&]() { return b.pixelInDisc(c, radius); },
                    [](const cv::Point2d&, const cv::Vec3d&) { return true; });
                if (done)
                    s.clusterCentres.push_back(c);
                else
                    b.truncate(start);
            }
            if (!done) return false;
        }
        return true;
    });
}

} // namespace essential_test

#endif

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Two-view scenes with a chosen rotation angle, up to 90 degrees and beyond, that still overlap:
// both cameras look at one compact point cloud (converging cameras, as when walking around an
// object). The paper's protocol (synthetic_scene.hpp) draws the motion first and keeps the points
// both cameras happen to see, which with a 90 degree field of view leaves almost nothing beyond
// 45 degrees; here the geometry is built around the cloud instead, so every rotation angle has a
// full set of correspondences. Header-only, shared by tests and benches.

#ifndef OPENCV_ESSENTIAL_TEST_CONVERGING_SCENE_HPP
#define OPENCV_ESSENTIAL_TEST_CONVERGING_SCENE_HPP

#include "synthetic_scene.hpp"

namespace essential_test {

struct ConvergingConfig
{
    int numPoints = 500;      //!< correspondences in total (inliers + outliers)
    double inlierRatio = 0.5; //!< fraction of correct matches
    double noiseSigma = 0.001;
    double minRotationDeg = 45.0; //!< angle of R uniform in [min, max], axis uniform
    double maxRotationDeg = 90.0;
    /** The cloud: a ball of radius cloudRadius * D around the point C at depth D on camera 1's
    optic axis (D uniform in [2, 10]); 0.4 spans +-0.4 normalised units (+-22 degrees) of the
    image, well inside the 90 degree field of view from any direction. */
    double cloudRadius = 0.4;
    /** Camera 2 looks at a point within aimOffset * D of C from a distance of 0.7 D to 1.3 D;
    configurations with a baseline below minBaseline * D (a rotation about an axis close to the
    optic axis) are drawn again: they are nearly pure rotations. */
    double aimOffset = 0.2;
    double minBaseline = 0.15;
    double halfFov = 1.0;
    double focal = 500.0;
    double cx = 500.0, cy = 500.0;
};

/** A converging scene for the config and seed (the same seed gives the same scene). Outliers are
uniform over the bounding box of the inliers' projections in each image, where a matcher's wrong
matches would be. */
inline SyntheticScene makeConvergingScene(const ConvergingConfig& cfg, uint64_t seed)
{
    std::mt19937_64 g(seed);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    std::normal_distribution<double> noise(0.0, cfg.noiseSigma);
    SyntheticScene s;
    s.K = cv::Matx33d(cfg.focal, 0, cfg.cx, 0, cfg.focal, cfg.cy, 0, 0, 1);
    const double depth = 2.0 + 8.0 * uni(g);
    const cv::Vec3d centre(0.0, 0.0, depth);
    cv::Vec3d centre2; // camera 2's centre in camera 1's frame
    for (;;) {
        const double angle =
            (cfg.minRotationDeg + uni(g) * (cfg.maxRotationDeg - cfg.minRotationDeg)) * CV_PI /
            180.0;
        s.R = axisAngle(randomUnit(g), angle);
        const cv::Vec3d aim = centre + randomUnit(g) * (cfg.aimOffset * depth * uni(g));
        const double distance = depth * (0.7 + 0.6 * uni(g));
        // Camera 2's optic axis in camera 1's frame is R^T e3 (X2 = R X1 + t).
        const cv::Vec3d axis2(s.R(2, 0), s.R(2, 1), s.R(2, 2));
        centre2 = aim - distance * axis2;
        if (cv::norm(centre2) >= cfg.minBaseline * depth) break;
    }
    const cv::Vec3d translation = -(s.R * centre2);
    s.baseline = cv::norm(translation);
    s.t = translation / s.baseline;
    s.E = skewMatrix(s.t) * s.R;

    const int numInliers = static_cast<int>(std::lround(cfg.numPoints * cfg.inlierRatio));
    const double f = cfg.halfFov;
    struct Match
    {
        cv::Point2d a, b;
        bool in;
    };
    std::vector<Match> matches;
    matches.reserve(static_cast<size_t>(cfg.numPoints));
    cv::Point2d lo1(1e9, 1e9), hi1(-1e9, -1e9), lo2(1e9, 1e9), hi2(-1e9, -1e9);
    for (int tries = 0; static_cast<int>(matches.size()) < numInliers && tries < 1000000; ++tries) {
        cv::Vec3d offset(2 * uni(g) - 1, 2 * uni(g) - 1, 2 * uni(g) - 1);
        if (offset.dot(offset) > 1.0) continue; // uniform in the unit ball
        const cv::Vec3d X1 = centre + cfg.cloudRadius * depth * offset;
        const cv::Vec3d X2 = s.R * X1 + translation;
        if (X1[2] <= 1e-9 || X2[2] <= 1e-9) continue;
        const cv::Point2d a(X1[0] / X1[2], X1[1] / X1[2]), b(X2[0] / X2[2], X2[1] / X2[2]);
        if (std::abs(a.x) > f || std::abs(a.y) > f || std::abs(b.x) > f || std::abs(b.y) > f)
            continue;
        lo1 = cv::Point2d(std::min(lo1.x, a.x), std::min(lo1.y, a.y));
        hi1 = cv::Point2d(std::max(hi1.x, a.x), std::max(hi1.y, a.y));
        lo2 = cv::Point2d(std::min(lo2.x, b.x), std::min(lo2.y, b.y));
        hi2 = cv::Point2d(std::max(hi2.x, b.x), std::max(hi2.y, b.y));
        matches.push_back({cv::Point2d(a.x + noise(g), a.y + noise(g)),
                           cv::Point2d(b.x + noise(g), b.y + noise(g)), true});
    }
    if (matches.empty()) { // cannot happen with the defaults; keeps the boxes below defined
        lo1 = lo2 = cv::Point2d(-f, -f);
        hi1 = hi2 = cv::Point2d(f, f);
    }
    while (static_cast<int>(matches.size()) < cfg.numPoints) {
        const cv::Point2d a(lo1.x + uni(g) * (hi1.x - lo1.x), lo1.y + uni(g) * (hi1.y - lo1.y));
        const cv::Point2d b(lo2.x + uni(g) * (hi2.x - lo2.x), lo2.y + uni(g) * (hi2.y - lo2.y));
        matches.push_back({a, b, false});
    }
    std::shuffle(matches.begin(), matches.end(), g);
    for (const Match& m : matches) {
        s.x1.push_back(m.a);
        s.x2.push_back(m.b);
        s.px1.push_back(cv::Point2d(cfg.focal * m.a.x + cfg.cx, cfg.focal * m.a.y + cfg.cy));
        s.px2.push_back(cv::Point2d(cfg.focal * m.b.x + cfg.cx, cfg.focal * m.b.y + cfg.cy));
        s.inlier.push_back(m.in);
        s.numInliers += m.in ? 1 : 0;
    }
    return s;
}

/** The rotation angle of R in degrees. */
inline double rotationAngleDeg(const cv::Matx33d& R)
{
    return rotationErrorDeg(cv::Matx33d::eye(), R);
}

} // namespace essential_test

#endif

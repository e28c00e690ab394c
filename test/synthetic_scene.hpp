// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Synthetic two-view scenes following the protocol of Rosten et al. ("Synthetic data"): a camera
// with a 90 degree field of view (normalised coordinates in [-1, 1]), points uniform in image
// position and inverse depth from depth 1, a random motion (rotation up to 35 degrees, translation
// up to 1 unit), Gaussian noise of 0.001 normalised units on both projections, points not visible
// in the second view dropped, then a set number of correct and wrong matches, shuffled.
// Header-only so tests, perf programs and benches share it.

#ifndef OPENCV_ESSENTIAL_TEST_SYNTHETIC_SCENE_HPP
#define OPENCV_ESSENTIAL_TEST_SYNTHETIC_SCENE_HPP

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace essential_test {

struct SceneConfig
{
    int numPoints = 500;          //!< correspondences in total (inliers + outliers)
    double inlierRatio = 0.5;     //!< fraction of correct matches
    double noiseSigma = 0.001;    //!< Gaussian noise on each coordinate, normalised units
    double maxRotationDeg = 35.0; //!< rotation angle uniform in [0, max], axis uniform
    double minTranslation = 0.1;  //!< baseline length uniform in [min, max], direction uniform
    double maxTranslation = 1.0;
    double minDepth = 1.0; //!< inverse depth uniform in [1 / maxDepth, 1 / minDepth]
    double maxDepth = 1000.0;
    double halfFov = 1.0; //!< tan(half field of view): 1 for 90 degrees
    /** tan(half the vertical field of view) if positive; otherwise the field of view is square
    (halfFov both ways). */
    double halfFovY = 0.0;
    double focal = 500.0; //!< pixel focal length of the camera used for pixel coordinates
    double cx = 500.0, cy = 500.0;
};

struct SyntheticScene
{
    std::vector<cv::Point2d> x1, x2;   //!< normalised coordinates
    std::vector<cv::Point2d> px1, px2; //!< pixel coordinates with camera K
    std::vector<bool> inlier;
    cv::Matx33d R; //!< X2 = R X1 + t
    cv::Vec3d t;   //!< unit translation direction
    double baseline = 0.0;
    cv::Matx33d E; //!< [t]x R, Frobenius norm sqrt(2)
    cv::Matx33d K;
    int numInliers = 0;
};

/** Points as an N x 1 two-channel CV_64F Mat (a copy): what cv::Mat(vector) is in OpenCV 4. OpenCV
5 makes cv::Mat(vector) a 1-D Mat, so tests that mean the N x 1 layout say so with this. */
inline cv::Mat pointColumn(const std::vector<cv::Point2d>& points)
{
    return cv::Mat(points, true).reshape(2, static_cast<int>(points.size()));
}

inline cv::Matx33d skewMatrix(const cv::Vec3d& v)
{
    return cv::Matx33d(0, -v[2], v[1], v[2], 0, -v[0], -v[1], v[0], 0);
}

inline cv::Vec3d randomUnit(std::mt19937_64& g)
{
    std::normal_distribution<double> n(0.0, 1.0);
    for (;;) {
        cv::Vec3d v(n(g), n(g), n(g));
        const double len = cv::norm(v);
        if (len > 1e-9) return v / len;
    }
}

/** Rotation by `angle` radians about the unit `axis` (Rodrigues). */
inline cv::Matx33d axisAngle(const cv::Vec3d& axis, double angle)
{
    const cv::Matx33d W = skewMatrix(axis);
    return cv::Matx33d::eye() + std::sin(angle) * W + (1.0 - std::cos(angle)) * (W * W);
}

/** The wide-camera variant of the protocol: a 1280 x 720 image with a 60 degree horizontal field
of view (focal length 640 / tan(30 deg) = 1108.5 px, principal point at the image centre) and noise
0.0015 normalised units (1.66 px); motion and depths as in the paper's protocol. */
inline SceneConfig wideCameraConfig()
{
    SceneConfig cfg;
    cfg.halfFov = std::tan(30.0 * CV_PI / 180.0);
    cfg.halfFovY = cfg.halfFov * 720.0 / 1280.0;
    cfg.focal = 640.0 / cfg.halfFov;
    cfg.cx = 639.5;
    cfg.cy = 359.5;
    cfg.noiseSigma = 0.0015;
    return cfg;
}

/** A scene for the given config and seed; the same seed gives the same scene. */
inline SyntheticScene makeScene(const SceneConfig& cfg, uint64_t seed)
{
    std::mt19937_64 g(seed);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    std::normal_distribution<double> noise(0.0, cfg.noiseSigma);
    SyntheticScene s;
    const double angle = uni(g) * cfg.maxRotationDeg * CV_PI / 180.0;
    s.R = axisAngle(randomUnit(g), angle);
    s.baseline = cfg.minTranslation + uni(g) * (cfg.maxTranslation - cfg.minTranslation);
    s.t = randomUnit(g);
    s.E = skewMatrix(s.t) * s.R;
    s.K = cv::Matx33d(cfg.focal, 0, cfg.cx, 0, cfg.focal, cfg.cy, 0, 0, 1);

    const int numInliers = static_cast<int>(std::lround(cfg.numPoints * cfg.inlierRatio));
    const double invMin = 1.0 / cfg.maxDepth, invMax = 1.0 / cfg.minDepth;
    const double f = cfg.halfFov;
    const double fy = cfg.halfFovY > 0.0 ? cfg.halfFovY : cfg.halfFov;
    struct Match
    {
        cv::Point2d a, b;
        bool in;
    };
    std::vector<Match> matches;
    matches.reserve(static_cast<size_t>(cfg.numPoints));
    for (int tries = 0; static_cast<int>(matches.size()) < numInliers && tries < 1000000; ++tries) {
        const double u = (2.0 * uni(g) - 1.0) * f, v = (2.0 * uni(g) - 1.0) * fy;
        const double depth = 1.0 / (invMin + uni(g) * (invMax - invMin));
        const cv::Vec3d X1(u * depth, v * depth, depth);
        const cv::Vec3d X2 = s.R * X1 + s.baseline * s.t;
        if (X2[2] <= 1e-9) continue;
        const double u2 = X2[0] / X2[2], v2 = X2[1] / X2[2];
        if (std::abs(u2) > f || std::abs(v2) > fy) continue; // not visible in view 2
        matches.push_back({cv::Point2d(u + noise(g), v + noise(g)),
                           cv::Point2d(u2 + noise(g), v2 + noise(g)), true});
    }
    // Wrong matches: independent uniform positions in both images.
    while (static_cast<int>(matches.size()) < cfg.numPoints) {
        matches.push_back({cv::Point2d((2 * uni(g) - 1) * f, (2 * uni(g) - 1) * fy),
                           cv::Point2d((2 * uni(g) - 1) * f, (2 * uni(g) - 1) * fy), false});
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

/** Angle of the rotation R_a^T R_b, in degrees. */
inline double rotationErrorDeg(const cv::Matx33d& Ra, const cv::Matx33d& Rb)
{
    const cv::Matx33d D = Ra.t() * Rb;
    const double c = std::max(-1.0, std::min(1.0, (cv::trace(D) - 1.0) / 2.0));
    return std::acos(c) * 180.0 / CV_PI;
}

/** Angle between two translation directions, in degrees (sign-sensitive). */
inline double translationErrorDeg(const cv::Vec3d& a, const cv::Vec3d& b)
{
    const double c = a.dot(b) / (cv::norm(a) * cv::norm(b));
    return std::acos(std::max(-1.0, std::min(1.0, c))) * 180.0 / CV_PI;
}

/** Distance between two essential matrices up to scale and sign: min over the sign of the
Frobenius norm of the difference after scaling both to norm sqrt(2). */
inline double essentialDistance(const cv::Matx33d& A, const cv::Matx33d& B)
{
    const cv::Matx33d a = A * (std::sqrt(2.0) / cv::norm(A));
    const cv::Matx33d b = B * (std::sqrt(2.0) / cv::norm(B));
    return std::min(cv::norm(a - b), cv::norm(a + b));
}

} // namespace essential_test

#endif

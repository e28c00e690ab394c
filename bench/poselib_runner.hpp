// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The two estimators of the PoseLib comparison (bench/compare_poselib.cpp,
// bench/compare_poselib_real.cpp), on the same pixel correspondences and camera, each timed by the
// thread's CPU clock:
//  - ours: cv::essential::findEssentialMatIter(points, K, RANSAC, 0.999, threshold, maxIters, mask)
//    then cv::essential::recoverPoseIter(E, points, K, R, t, mask) (the drop-in pair);
//  - PoseLib: poselib::estimate_relative_pose with a pinhole camera, RANSAC min_iterations 0,
//    max_iterations as given, max_error = threshold (px), all else PoseLib's defaults (success
//    probability 0.9999, 3 times the dynamic trial count, LO by 25 LM iterations with a truncated
//    loss, final LM with a Cauchy loss on the inliers).

#ifndef OPENCV_ESSENTIAL_BENCH_POSELIB_RUNNER_HPP
#define OPENCV_ESSENTIAL_BENCH_POSELIB_RUNNER_HPP

#include "pose_accuracy.hpp"
#include "synthetic_scene.hpp"

#include <PoseLib/poselib.h>

#include <opencv2/essential.hpp>

#include <cstdint>
#include <vector>

namespace essential_bench {

template <typename Point>
PoseEstimate runOurs(const std::vector<Point>& px1, const std::vector<Point>& px2,
                     const cv::Matx33d& K, double threshold, int maxIters)
{
    PoseEstimate e;
    const cv::Mat Km(K);
    const double t0 = threadCpuMs();
    cv::Mat mask, R, t;
    const cv::Mat E = cv::essential::findEssentialMatIter(px1, px2, Km, cv::RANSAC, 0.999,
                                                          threshold, maxIters, mask);
    int inFront = 0;
    if (E.rows == 3 && E.cols == 3)
        inFront = cv::essential::recoverPoseIter(E, px1, px2, Km, R, t, mask);
    e.ms = threadCpuMs() - t0;
    if (inFront > 0) {
        e.ok = true;
        e.R = cv::Matx33d(R);
        e.t = cv::Vec3d(t);
    }
    return e;
}

template <typename Point>
PoseEstimate runPoseLib(const std::vector<Point>& px1, const std::vector<Point>& px2,
                        const cv::Matx33d& K, double threshold, int maxIters,
                        std::uint64_t seed = 0)
{
    PoseEstimate e;
    const double t0 = threadCpuMs();
    std::vector<Eigen::Vector2d> a(px1.size()), b(px2.size());
    for (size_t i = 0; i < a.size(); ++i) {
        a[i] = Eigen::Vector2d(px1[i].x, px1[i].y);
        b[i] = Eigen::Vector2d(px2[i].x, px2[i].y);
    }
    const std::vector<double> params = {K(0, 0), K(1, 1), K(0, 2), K(1, 2)};
    const poselib::Camera camera("PINHOLE", params);
    poselib::RelativePoseOptions opt;
    opt.ransac.min_iterations = 0;
    opt.ransac.max_iterations = static_cast<size_t>(maxIters);
    opt.max_error = threshold;
    // PoseLib's sampler takes a 64-bit state; 0 is its default.
    opt.ransac.seed = static_cast<decltype(opt.ransac.seed)>(seed);
    poselib::CameraPose pose;
    std::vector<char> inliers;
    const poselib::RansacStats stats =
        poselib::estimate_relative_pose(a, b, camera, camera, opt, &pose, &inliers);
    e.ms = threadCpuMs() - t0;
    if (stats.num_inliers >= 5) {
        e.ok = true;
        const Eigen::Matrix3d R = pose.R();
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                e.R(i, j) = R(i, j);
        e.t = cv::Vec3d(pose.t.x(), pose.t.y(), pose.t.z());
    }
    return e;
}

/** The errors of an estimate against the true pose (180 degrees each for a failure). */
inline PoseOutcome outcomeOf(const PoseEstimate& e, const cv::Matx33d& trueR,
                             const cv::Vec3d& trueT)
{
    PoseOutcome o;
    o.ms = e.ms;
    if (e.ok) {
        o.rotErr = essential_test::rotationErrorDeg(e.R, trueR);
        o.transErr = essential_test::translationErrorDeg(e.t, trueT);
    }
    return o;
}

} // namespace essential_bench

#endif

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Invalid input raises cv::Exception naming the problem; degenerate but valid input (all points the
// same, no consistent geometry) returns an empty E and an all-zero mask.

#include "opencv2/essential.hpp"
#include "synthetic_scene.hpp"

#include "essential_test.hpp"

#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using essential_test::makeScene;
using essential_test::SceneConfig;
using essential_test::SyntheticScene;

/** Runs `call`, expects a cv::Exception whose message contains every one of `needles`. */
void expectThrowsWith(const std::function<void()>& call, const std::vector<std::string>& needles)
{
    try {
        call();
        ADD_FAILURE() << "no exception; expected one mentioning '" << needles.front() << "'";
    } catch (const cv::Exception& e) {
        for (const std::string& needle : needles)
            EXPECT_NE(e.err.find(needle), std::string::npos)
                << "message '" << e.err << "' lacks '" << needle << "'";
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not a cv::Exception: " << e.what();
    }
}

const SyntheticScene& scene()
{
    static const SyntheticScene s = [] {
        SceneConfig cfg;
        cfg.numPoints = 100;
        cfg.inlierRatio = 0.8;
        return makeScene(cfg, 7);
    }();
    return s;
}

cv::Mat K()
{
    return cv::Mat(scene().K).clone();
}

TEST(BadInput, FewerThanFivePoints)
{
    const std::vector<cv::Point2d> p1(scene().px1.begin(), scene().px1.begin() + 4);
    const std::vector<cv::Point2d> p2(scene().px2.begin(), scene().px2.begin() + 4);
    expectThrowsWith([&] { cv::essential::findEssentialMatIter(p1, p2, K()); },
                     {"at least 5", "got 4"});
    const std::vector<cv::Point2d> none;
    expectThrowsWith([&] { cv::essential::findEssentialMatIter(none, none, K()); },
                     {"points1", "empty"});
}

TEST(BadInput, SizeMismatch)
{
    const std::vector<cv::Point2d> p1(scene().px1.begin(), scene().px1.begin() + 10);
    const std::vector<cv::Point2d> p2(scene().px2.begin(), scene().px2.begin() + 12);
    expectThrowsWith([&] { cv::essential::findEssentialMatIter(p1, p2, K()); },
                     {"differ in size", "10", "12"});
}

TEST(BadInput, NonFiniteCoordinates)
{
    for (const double bad :
         {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()}) {
        std::vector<cv::Point2d> p1 = scene().px1, p2 = scene().px2;
        p2[17].y = bad;
        expectThrowsWith([&] { cv::essential::findEssentialMatIter(p1, p2, K()); },
                         {"points2", "non-finite", "17"});
        // Same in a float Mat of points1.
        cv::Mat m;
        essential_test::pointColumn(scene().px1).convertTo(m, CV_32FC2);
        m.at<cv::Vec2f>(3)[0] = static_cast<float>(bad);
        expectThrowsWith([&] { cv::essential::findEssentialMatIter(m, scene().px2, K()); },
                         {"points1", "non-finite", "3"});
    }
}

TEST(BadInput, IntegerDepthsAsOpenCV)
{
    // cv::findEssentialMat converts the points to double whatever their depth, except in the form
    // with distortion coefficients, whose cv::undistortPoints takes CV_32F or CV_64F only.
    const int N = static_cast<int>(scene().px1.size());
    for (const int depth : {CV_32S, CV_16U}) {
        SCOPED_TRACE(depth);
        cv::Mat p1, p2;
        essential_test::pointColumn(scene().px1).convertTo(p1, CV_MAKETYPE(depth, 2));
        essential_test::pointColumn(scene().px2).convertTo(p2, CV_MAKETYPE(depth, 2));
        ASSERT_EQ(p1.rows, N);
        cv::Mat mask;
        const cv::Mat E =
            cv::essential::findEssentialMatIter(p1, p2, K(), cv::RANSAC, 0.999, 1.0, 1000, mask);
        // Whole pixels (rounding noise of 0.3 px rms): still the scene's geometry.
        ASSERT_FALSE(E.empty());
        EXPECT_LT(essential_test::essentialDistance(cv::Matx33d(E), scene().E), 0.05);
        expectThrowsWith(
            [&] {
                cv::essential::findEssentialMatIter(p1, p2, K(), cv::Mat(), K(), cv::Mat(),
                                                    cv::RANSAC, 0.999, 1.0, cv::noArray());
            },
            {"points1", "CV_32F or CV_64F"});
    }
    std::vector<cv::Point2i> ip(scene().px1.begin(), scene().px1.end());
    expectThrowsWith(
        [&] {
            cv::essential::findEssentialMatIter(ip, ip, K(), cv::Mat(), K(), cv::Mat(), cv::RANSAC,
                                                0.999, 1.0, cv::noArray());
        },
        {"points1", "std::vector", "CV_32F or CV_64F"});
}

TEST(BadInput, WrongChannelCount)
{
    // RANSAC reads 2D points only (as cv::findEssentialMat; the USAC flags would take the first
    // two coordinates of these).
    const int N = static_cast<int>(scene().px1.size());
    cv::Mat three(N, 1, CV_64FC3, cv::Scalar(1, 2, 3));
    expectThrowsWith([&] { cv::essential::findEssentialMatIter(three, three, K()); },
                     {"points1", "2D points", "CV_64FC3"});
    cv::Mat nx3(N, 3, CV_64F, cv::Scalar(1));
    expectThrowsWith([&] { cv::essential::findEssentialMatIter(nx3, nx3, K()); },
                     {"points1", "2D points", "USAC flags only"});
    std::vector<cv::Point3d> p3(static_cast<size_t>(N), cv::Point3d(1, 2, 3));
    expectThrowsWith([&] { cv::essential::findEssentialMatIter(p3, p3, K()); },
                     {"std::vector", "2D points"});
}

TEST(BadInput, LayoutMessagesDescribeTheArrayAndTheRule)
{
    // The message names the array as it is (shape, type, a view) and the rule of this overload and
    // method, without contradicting itself (it once said "must be N x 2 ... got 200 x 2").
    const int N = static_cast<int>(scene().px1.size());
    const cv::Mat rows = cv::Mat(scene().px1, true).reshape(1, N); // N x 2
    const cv::Mat columns = rows.t();                              // 2 x N
    expectThrowsWith(
        [&] { cv::essential::findEssentialMatIter(columns, columns, K(), cv::RANSAC); },
        {"points1 is a 2 x " + std::to_string(N) + " CV_64FC1 array", "with RANSAC or LMEDS",
         "USAC flags only"});
    // The USAC flags read it.
    EXPECT_NO_THROW(cv::essential::findEssentialMatIter(columns, columns, K(), cv::USAC_DEFAULT));
    cv::Mat wide(N, 3, CV_64F, cv::Scalar(1));
    rows.copyTo(wide.colRange(0, 2));
    const cv::Mat view = wide.colRange(0, 2);
    expectThrowsWith(
        [&] {
            cv::essential::findEssentialMatIter(view, view, K(), cv::Mat(), K(), cv::Mat(),
                                                cv::RANSAC, 0.999, 1.0, cv::noArray());
        },
        {"points1 is a " + std::to_string(N) +
             " x 2 CV_64FC1 array (a view, not continuous in "
             "memory)",
         "cv::undistortPoints", "continuous in memory"});
    // Without distortion the same view is read.
    EXPECT_NO_THROW(cv::essential::findEssentialMatIter(view, view, K(), cv::RANSAC));
}

TEST(BadInput, CameraMatrixNot3x3)
{
    const std::vector<cv::Mat> bad = {cv::Mat::eye(2, 3, CV_64F), cv::Mat::eye(4, 4, CV_64F),
                                      cv::Mat(9, 1, CV_64F, cv::Scalar(1)),
                                      cv::Mat(3, 3, CV_64FC2, cv::Scalar(1, 0))};
    for (size_t k = 0; k < bad.size(); ++k) {
        SCOPED_TRACE(k);
        expectThrowsWith(
            [&] { cv::essential::findEssentialMatIter(scene().px1, scene().px2, bad[k]); },
            {"cameraMatrix", "3 x 3"});
    }
    expectThrowsWith(
        [&] { cv::essential::findEssentialMatIter(scene().px1, scene().px2, cv::Mat()); },
        {"cameraMatrix", "empty"});
    // Same checks in the two-camera form, naming which camera.
    const cv::Mat d;
    expectThrowsWith(
        [&] { cv::essential::findEssentialMatIter(scene().px1, scene().px2, K(), d, bad[0], d); },
        {"cameraMatrix2", "3 x 3"});
}

TEST(BadInput, SingularCameraMatrix)
{
    // Zero focal length.
    cv::Mat k0 = K();
    k0.at<double>(0, 0) = 0;
    expectThrowsWith([&] { cv::essential::findEssentialMatIter(scene().px1, scene().px2, k0); },
                     {"cameraMatrix", "focal"});
    // Non-zero focal lengths but dependent rows.
    const cv::Mat ks = cv::Mat(cv::Matx<double, 3, 3>(500, 1000, 0, 250, 500, 0, 0, 0, 1));
    expectThrowsWith([&] { cv::essential::findEssentialMatIter(scene().px1, scene().px2, ks); },
                     {"cameraMatrix", "singular"});
    // The focal form with focal 0.
    expectThrowsWith(
        [&] {
            cv::essential::findEssentialMatIter(scene().px1, scene().px2, 0.0, cv::Point2d(0, 0));
        },
        {"focal"});
    // Non-finite entry.
    cv::Mat kn = K();
    kn.at<double>(0, 2) = std::numeric_limits<double>::quiet_NaN();
    expectThrowsWith([&] { cv::essential::findEssentialMatIter(scene().px1, scene().px2, kn); },
                     {"cameraMatrix", "non-finite"});
}

TEST(BadInput, ProbOutOfRange)
{
    for (const double prob : {0.0, -0.5, 1.0, 1.5, std::numeric_limits<double>::quiet_NaN()}) {
        SCOPED_TRACE(prob);
        expectThrowsWith(
            [&] {
                cv::essential::findEssentialMatIter(scene().px1, scene().px2, K(), cv::RANSAC, prob,
                                                    1.0, 1000);
            },
            {"prob"});
        cv::essential::EssentialParams params;
        params.confidence = prob;
        expectThrowsWith(
            [&] { cv::essential::findEssentialMatIter(scene().px1, scene().px2, K(), params); },
            {"prob"});
    }
}

TEST(BadInput, ThresholdNotPositive)
{
    for (const double threshold : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                                   std::numeric_limits<double>::infinity()}) {
        SCOPED_TRACE(threshold);
        expectThrowsWith(
            [&] {
                cv::essential::findEssentialMatIter(scene().px1, scene().px2, K(), cv::RANSAC,
                                                    0.999, threshold, 1000);
            },
            {"threshold"});
        cv::essential::EssentialParams params;
        params.threshold = threshold;
        expectThrowsWith(
            [&] { cv::essential::findEssentialMatIter(scene().px1, scene().px2, K(), params); },
            {"threshold"});
    }
}

TEST(BadInput, MaxItersNotPositive)
{
    for (const int maxIters : {0, -1}) {
        SCOPED_TRACE(maxIters);
        expectThrowsWith(
            [&] {
                cv::essential::findEssentialMatIter(scene().px1, scene().px2, K(), cv::RANSAC,
                                                    0.999, 1.0, maxIters);
            },
            {"maxIters"});
        cv::UsacParams usac;
        usac.maxIterations = maxIters;
        usac.threshold = 1.0;
        const cv::Mat d;
        expectThrowsWith(
            [&] {
                cv::Mat mask;
                cv::essential::findEssentialMatIter(scene().px1, scene().px2, K(), K(), d, d, mask,
                                                    usac);
            },
            {"UsacParams::maxIterations"});
    }
}

TEST(BadInput, UnknownMethod)
{
    for (const int method : {12345, -1, 1}) {
        SCOPED_TRACE(method);
        expectThrowsWith(
            [&] {
                cv::essential::findEssentialMatIter(scene().px1, scene().px2, K(), method, 0.999,
                                                    1.0, 1000);
            },
            {"method", std::to_string(method)});
        // The params form's score cannot hold a method flag; its bad values are in
        // BadInputTable.UnknownSolverEngineSamplerOrOption.
    }
}

TEST(BadInput, UnknownSolverName)
{
    cv::essential::EssentialParams params;
    params.solver = "no-such-solver";
    expectThrowsWith(
        [&] { cv::essential::findEssentialMatIter(scene().px1, scene().px2, K(), params); },
        {"unknown solver", "no-such-solver"});
}

/** Expects the documented failure result: an empty E and an N x 1 CV_8U all-zero mask. */
void expectEmptyResult(const cv::Mat& E, const cv::Mat& mask, int N)
{
    EXPECT_TRUE(E.empty()) << "E is " << E.rows << " x " << E.cols << ":\n" << E;
    ASSERT_EQ(mask.rows, N);
    ASSERT_EQ(mask.cols, 1);
    ASSERT_EQ(mask.type(), CV_8U);
    EXPECT_EQ(cv::countNonZero(mask), 0);
}

TEST(BadInput, AllPointsIdentical)
{
    const int N = 50;
    const std::vector<cv::Point2d> p1(N, cv::Point2d(321.5, 123.25));
    const std::vector<cv::Point2d> p2(N, cv::Point2d(300.0, 140.0));
    cv::Mat mask(3, 3, CV_32F, cv::Scalar(9)); // a stale mask of another shape is replaced
    const cv::Mat E =
        cv::essential::findEssentialMatIter(p1, p2, K(), cv::RANSAC, 0.999, 1.0, 1000, mask);
    expectEmptyResult(E, mask, N);
    cv::Mat maskLmeds;
    const cv::Mat El =
        cv::essential::findEssentialMatIter(p1, p2, K(), cv::LMEDS, 0.999, 1.0, 1000, maskLmeds);
    expectEmptyResult(El, maskLmeds, N);
    // Also the same point in both images (zero motion).
    cv::Mat mask2;
    const cv::Mat E2 =
        cv::essential::findEssentialMatIter(p1, p1, K(), cv::RANSAC, 0.999, 1.0, 1000, mask2);
    expectEmptyResult(E2, mask2, N);
}

TEST(BadInput, AllOutliers)
{
    // Independent uniform positions in both images: no geometry to find. Any five points fit some
    // E exactly, so the estimate must be rejected for having no support beyond its sample.
    for (const uint64_t seed : {1ULL, 2ULL, 3ULL}) {
        SCOPED_TRACE(seed);
        SceneConfig cfg;
        cfg.numPoints = 200;
        cfg.inlierRatio = 0.0;
        const SyntheticScene s = makeScene(cfg, seed);
        ASSERT_EQ(s.numInliers, 0);
        cv::Mat mask;
        cv::essential::EssentialReport report;
        cv::essential::EssentialParams params;
        const cv::Mat E =
            cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), params, mask, &report);
        expectEmptyResult(E, mask, cfg.numPoints);
        EXPECT_FALSE(report.success);
        EXPECT_EQ(report.inliers, 0);
        cv::Mat mask2;
        const cv::Mat E2 = cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K),
                                                               cv::RANSAC, 0.999, 1.0, 1000, mask2);
        expectEmptyResult(E2, mask2, cfg.numPoints);
    }
}

} // namespace

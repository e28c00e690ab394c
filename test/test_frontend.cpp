// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The sample front end (samples/frontend) on two bundled frames of the rail-a horizontal sequence
// (data/rail/horizontal, frames 0 and 10, known poses): enough matches, and most of them agree with
// the true essential matrix; its SIFT mode on a synthetic texture and a known homography. Built
// only when the samples are (the test links essential_frontend).

#if __has_include("frontend/frontend.hpp")

#include "frontend/frontend.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "essential_test.hpp"

#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>

namespace {

const std::string kRailDir = std::string(ESSENTIAL_DATA_DIR) + "/rail/horizontal";

struct Pose
{
    cv::Matx33d R;
    cv::Vec3d C;
};

// Reads line `frame` of poses.txt (`k r00 .. r22 Cx Cy Cz`).
bool readPose(int frame, Pose& pose)
{
    std::ifstream file(kRailDir + "/poses.txt");
    int k;
    while (file >> k) {
        for (int i = 0; i < 9; ++i)
            file >> pose.R.val[i];
        file >> pose.C[0] >> pose.C[1] >> pose.C[2];
        if (k == frame) return static_cast<bool>(file);
    }
    return false;
}

// Fraction of the matches whose Sampson distance to the true fundamental matrix is below 1 pixel.
double trueInlierRate(const essential_samples::Matches& matches)
{
    cv::Matx33d K;
    std::ifstream camera(kRailDir + "/camera.txt");
    for (int i = 0; i < 9; ++i)
        camera >> K.val[i];
    Pose a, b;
    EXPECT_TRUE(camera && readPose(0, a) && readPose(10, b));
    const cv::Matx33d R = b.R * a.R.t();
    const cv::Vec3d t = -(b.R * (b.C - a.C));
    const cv::Matx33d tx(0, -t[2], t[1], t[2], 0, -t[0], -t[1], t[0], 0);
    const cv::Matx33d F = K.inv().t() * tx * R * K.inv();
    int good = 0;
    for (size_t m = 0; m < matches.points1.size(); ++m) {
        const cv::Vec3d x1(matches.points1[m].x, matches.points1[m].y, 1.0);
        const cv::Vec3d x2(matches.points2[m].x, matches.points2[m].y, 1.0);
        const cv::Vec3d Fx1 = F * x1, Ftx2 = F.t() * x2;
        const double d = Fx1[0] * Fx1[0] + Fx1[1] * Fx1[1] + Ftx2[0] * Ftx2[0] + Ftx2[1] * Ftx2[1];
        good += std::abs(x2.dot(Fx1)) < 1.0 * std::sqrt(d);
    }
    return matches.points1.empty() ? 0.0 : double(good) / matches.points1.size();
}

essential_samples::Matches matchRailPair(const essential_samples::FrontEndParams& params)
{
    const cv::Mat image1 = cv::imread(kRailDir + "/000.jpg", cv::IMREAD_GRAYSCALE);
    const cv::Mat image2 = cv::imread(kRailDir + "/010.jpg", cv::IMREAD_GRAYSCALE);
    EXPECT_FALSE(image1.empty());
    EXPECT_FALSE(image2.empty());
    const auto features1 = essential_samples::detectAndDescribe(image1, params);
    const auto features2 = essential_samples::detectAndDescribe(image2, params);
    EXPECT_EQ(features1.levels, 6); // 640 x 480 down to 1/8 (60 rows would be below 80)
    return essential_samples::matchFeatures(features1, features2, params);
}

// A 640 x 480 texture with blobs at many scales (uniform noise smoothed at sigma 2 and 6, summed
// and stretched to 0-255), and the same texture seen through the homography `H` (image 2 = H
// applied to image 1: rotation 4 degrees, scale 0.95, a shift and a little perspective).
struct WarpedTexture
{
    cv::Mat image1, image2;
    cv::Matx33d H;
};

WarpedTexture warpedTexture()
{
    WarpedTexture scene;
    cv::RNG rng(20250601);
    cv::Mat noise(480, 640, CV_32F), fine, coarse;
    rng.fill(noise, cv::RNG::UNIFORM, 0.0, 1.0);
    cv::GaussianBlur(noise, fine, cv::Size(), 2.0);
    rng.fill(noise, cv::RNG::UNIFORM, 0.0, 1.0);
    cv::GaussianBlur(noise, coarse, cv::Size(), 6.0);
    cv::Mat texture = fine + 2.0 * coarse;
    cv::normalize(texture, texture, 0, 255, cv::NORM_MINMAX);
    texture.convertTo(scene.image1, CV_8U);
    const double a = 4.0 * CV_PI / 180.0, s = 0.95;
    scene.H = cv::Matx33d(s * std::cos(a), -s * std::sin(a), 30.0, s * std::sin(a), s * std::cos(a),
                          -10.0, 2e-5, -1e-5, 1.0);
    cv::warpPerspective(scene.image1, scene.image2, cv::Mat(scene.H), scene.image1.size(),
                        cv::INTER_LINEAR, cv::BORDER_REFLECT_101);
    return scene;
}

// Fraction of the matches whose point in image 2 is within `tolerancePx` of H applied to the point
// in image 1.
double agreeWithHomography(const essential_samples::Matches& matches, const cv::Matx33d& H,
                           double tolerancePx)
{
    int good = 0;
    for (size_t m = 0; m < matches.points1.size(); ++m) {
        const cv::Vec3d x = H * cv::Vec3d(matches.points1[m].x, matches.points1[m].y, 1.0);
        const double dx = x[0] / x[2] - matches.points2[m].x;
        const double dy = x[1] / x[2] - matches.points2[m].y;
        good += std::sqrt(dx * dx + dy * dy) < tolerancePx;
    }
    return matches.points1.empty() ? 0.0 : double(good) / matches.points1.size();
}

} // namespace

// Measured: 2534 matches (20% of the corners of frame 10), 95.8% within 1 px of the true E.
TEST(FrontEnd, DefaultDescriptorMatchesTheRailPairWithFewOutliers)
{
    const essential_samples::FrontEndParams params;
    EXPECT_EQ(params.descriptor, essential_samples::Descriptor::UprightBrief);
    const essential_samples::Matches matches = matchRailPair(params);
    ASSERT_EQ(matches.points1.size(), matches.points2.size());
    EXPECT_GE(matches.points1.size(), 2000u);
    EXPECT_GE(trueInlierRate(matches), 0.93);
}

// Measured: rBRIEF 90.3%, patch 88.0% on this pair; both below upright BRIEF (95.8%).
TEST(FrontEnd, OtherDescriptorsAlsoMatchTheRailPair)
{
    essential_samples::FrontEndParams params;
    params.descriptor = essential_samples::Descriptor::RotatedBrief;
    const double rotated = trueInlierRate(matchRailPair(params));
    params.descriptor = essential_samples::Descriptor::Patch;
    const essential_samples::Matches patch = matchRailPair(params);
    EXPECT_GE(patch.points1.size(), 2000u);
    EXPECT_GE(rotated, 0.85);
    EXPECT_GE(trueInlierRate(patch), 0.83);
}

TEST(FrontEnd, DescriptorNamesRoundTrip)
{
    using essential_samples::Descriptor;
    for (Descriptor d : {Descriptor::UprightBrief, Descriptor::RotatedBrief, Descriptor::Patch,
                         Descriptor::Sift}) {
        Descriptor parsed = d == Descriptor::Patch ? Descriptor::UprightBrief : Descriptor::Patch;
        EXPECT_TRUE(
            essential_samples::parseDescriptor(essential_samples::descriptorName(d), parsed));
        EXPECT_EQ(parsed, d);
    }
    EXPECT_STREQ(essential_samples::descriptorName(Descriptor::Sift), "sift");
    Descriptor unused;
    EXPECT_FALSE(essential_samples::parseDescriptor("surf", unused));
}

TEST(FrontEnd, DetectorNamesRoundTrip)
{
    using essential_samples::Detector;
    EXPECT_STREQ(essential_samples::detectorName(Detector::Fast9Pyramid), "fast");
    EXPECT_STREQ(essential_samples::detectorName(Detector::Sift), "sift");
    for (Detector d : {Detector::Fast9Pyramid, Detector::Sift}) {
        Detector parsed = d == Detector::Sift ? Detector::Fast9Pyramid : Detector::Sift;
        EXPECT_TRUE(essential_samples::parseDetector(essential_samples::detectorName(d), parsed));
        EXPECT_EQ(parsed, d);
    }
    Detector unchanged = Detector::Sift;
    EXPECT_FALSE(essential_samples::parseDetector("orb", unchanged));
    EXPECT_FALSE(essential_samples::parseDetector("SIFT", unchanged));
    EXPECT_EQ(unchanged, Detector::Sift);
    EXPECT_EQ(essential_samples::FrontEndParams().detector, Detector::Fast9Pyramid);
}

// SIFT + ratio test on a texture and its warp by a known homography. Measured: 4000 and 4002
// keypoints (siftFeatures 4000; cv::SIFT keeps the ties at the cut), 4002 candidates, 2827 pass the
// ratio test, 99.8% of them within 1.5 px of H; with ratio 1 (no test) all 4002, 71% within 1.5 px.
TEST(FrontEnd, SiftRatioTestMatchesAgreeWithTheHomography)
{
    const WarpedTexture scene = warpedTexture();
    essential_samples::FrontEndParams params;
    params.detector = essential_samples::Detector::Sift;
    params.keepFraction = 1.0;
    const auto features1 = essential_samples::detectAndDescribe(scene.image1, params);
    const auto features2 = essential_samples::detectAndDescribe(scene.image2, params);
    EXPECT_EQ(features1.descriptor, essential_samples::Descriptor::Sift);
    EXPECT_EQ(features1.descriptors.type(), CV_32F);
    EXPECT_EQ(features1.descriptors.cols, 128);
    EXPECT_EQ(features1.descriptors.rows, static_cast<int>(features1.keypoints.size()));
    EXPECT_EQ(features2.descriptors.rows, static_cast<int>(features2.keypoints.size()));
    for (const auto* features : {&features1, &features2}) {
        EXPECT_GE(features->keypoints.size(), 3500u); // about siftFeatures
        EXPECT_LE(features->keypoints.size(), 4100u);
        EXPECT_EQ(features->cornersDetected, static_cast<int>(features->keypoints.size()));
    }
    EXPECT_GE(features1.levels, 2);

    const essential_samples::Matches matches =
        essential_samples::matchFeatures(features1, features2, params);
    // A candidate per keypoint of image 2 (image 1 has two neighbours for each of them).
    EXPECT_EQ(matches.candidates, static_cast<int>(features2.keypoints.size()));
    EXPECT_EQ(matches.ratioTestPassed, static_cast<int>(matches.points1.size()));
    EXPECT_LT(matches.ratioTestPassed, matches.candidates);
    EXPECT_GE(matches.points1.size(), 2000u);
    EXPECT_GE(agreeWithHomography(matches, scene.H, 1.5), 0.95);

    // Without the test (ratio 1: only exact ties dropped) more matches, and more of them wrong.
    params.ratio = 1.0;
    const essential_samples::Matches all =
        essential_samples::matchFeatures(features1, features2, params);
    EXPECT_GT(all.points1.size(), matches.points1.size());
    EXPECT_LT(agreeWithHomography(all, scene.H, 1.5),
              agreeWithHomography(matches, scene.H, 1.5) - 0.2);

    // keepFraction then takes the best by distance of the survivors.
    params.ratio = 0.8;
    params.keepFraction = 0.5;
    const essential_samples::Matches half =
        essential_samples::matchFeatures(features1, features2, params);
    EXPECT_EQ(half.ratioTestPassed, matches.ratioTestPassed);
    EXPECT_EQ(static_cast<int>(half.points1.size()), (matches.ratioTestPassed + 1) / 2);
    EXPECT_LE(half.maxDistance, matches.maxDistance);
}

// The faster matchers with SIFT: Flann (k-d trees, two neighbours) and Grid (the keypoints of
// highest response per cell) still give matches that agree with the homography. Measured, all
// 5382 and 5859 keypoints: flann 4182 matches, 99.4% within 1.5 px of H (brute force 4178,
// 99.8%); grid 2048 keypoints per image, 1390 matches, 99.6%.
TEST(FrontEnd, SiftWithFlannAndGridMatchers)
{
    const WarpedTexture scene = warpedTexture();
    essential_samples::FrontEndParams params;
    params.detector = essential_samples::Detector::Sift;
    params.siftFeatures = 0; // all
    params.keepFraction = 1.0;
    for (essential_samples::Matcher matcher :
         {essential_samples::Matcher::Flann, essential_samples::Matcher::Grid}) {
        params.matcher = matcher;
        const auto features1 = essential_samples::detectAndDescribe(scene.image1, params);
        const auto features2 = essential_samples::detectAndDescribe(scene.image2, params);
        if (matcher == essential_samples::Matcher::Grid) {
            EXPECT_LE(features1.keypoints.size(), size_t(essential_samples::kGridCorners));
            EXPECT_LT(features1.keypoints.size(), size_t(features1.cornersDetected));
        }
        const essential_samples::Matches matches =
            essential_samples::matchFeatures(features1, features2, params);
        EXPECT_GE(matches.points1.size(), 1000u) << essential_samples::matcherName(matcher);
        EXPECT_GE(agreeWithHomography(matches, scene.H, 1.5), 0.95)
            << essential_samples::matcherName(matcher);
    }
}

// SIFT's options are checked: its descriptor only with its detector, a ratio in (0, 1].
TEST(FrontEnd, SiftSettingsAreChecked)
{
    const WarpedTexture scene = warpedTexture();
    essential_samples::FrontEndParams params;
    params.descriptor = essential_samples::Descriptor::Sift; // with the FAST detector
    EXPECT_THROW(essential_samples::detectAndDescribe(scene.image1, params), std::invalid_argument);
    params.detector = essential_samples::Detector::Sift;
    EXPECT_NO_THROW(essential_samples::detectAndDescribe(scene.image1, params));
    params.descriptor = essential_samples::Descriptor::Patch;
    EXPECT_THROW(essential_samples::detectAndDescribe(scene.image1, params), std::invalid_argument);
    params.descriptor = essential_samples::Descriptor::UprightBrief; // the default: SIFT's own
    for (double ratio : {0.0, -0.5, 1.5, std::nan("")}) {
        params.ratio = ratio;
        EXPECT_THROW(essential_samples::detectAndDescribe(scene.image1, params),
                     std::invalid_argument)
            << ratio;
    }
    params.ratio = 0.8;
    params.siftFeatures = -1;
    EXPECT_THROW(essential_samples::detectAndDescribe(scene.image1, params), std::invalid_argument);
    // SIFT features cannot be matched against BRIEF ones.
    params.siftFeatures = 4000;
    const auto sift = essential_samples::detectAndDescribe(scene.image1, params);
    const auto brief =
        essential_samples::detectAndDescribe(scene.image1, essential_samples::FrontEndParams());
    EXPECT_THROW(essential_samples::matchFeatures(sift, brief, params), std::invalid_argument);
}

#endif // __has_include("frontend/frontend.hpp")

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The sample front end (samples/frontend) on two bundled frames of the rail-a horizontal sequence
// (data/rail/horizontal, frames 0 and 10, known poses): enough matches, and most of them agree with
// the true essential matrix. Built only when the samples are (the test links essential_frontend).

#if __has_include("frontend/frontend.hpp")

#include "frontend/frontend.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "essential_test.hpp"

#include <cmath>
#include <fstream>
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
    for (Descriptor d : {Descriptor::UprightBrief, Descriptor::RotatedBrief, Descriptor::Patch}) {
        Descriptor parsed = d == Descriptor::Patch ? Descriptor::UprightBrief : Descriptor::Patch;
        EXPECT_TRUE(
            essential_samples::parseDescriptor(essential_samples::descriptorName(d), parsed));
        EXPECT_EQ(parsed, d);
    }
    Descriptor unused;
    EXPECT_FALSE(essential_samples::parseDescriptor("sift", unused));
}

#endif // __has_include("frontend/frontend.hpp")

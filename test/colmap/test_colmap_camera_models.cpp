// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// COLMAP's camera models (samples/colmap/camera_models): the supported models read with their
// parameter order, unsupported ones refused by name, undistortion inverting projection, and the
// projection checked against COLMAP itself: a model whose observations are our projections of known
// points has zero reprojection error in `colmap bundle_adjuster` exactly when our formula is
// COLMAP's.

#include "colmap/camera_models.hpp"
#include "colmap/sqlite_connection.hpp"
#include "colmap_test_support.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <regex>
#include <string>

using essential_colmap::CameraIntrinsics;
using essential_colmap::ColmapCamera;

namespace {

ColmapCamera cameraOf(int model, std::vector<double> params)
{
    ColmapCamera c;
    c.id = 7;
    c.modelId = model;
    c.width = 640;
    c.height = 480;
    c.params = params;
    return c;
}

// One camera of each supported model with a strong but invertible distortion over a 640 x 480
// image.
std::vector<ColmapCamera> supportedCameras()
{
    return {cameraOf(0, {500, 320, 240}), cameraOf(1, {500, 520, 321, 239}),
            cameraOf(2, {500, 320, 240, -0.15}), cameraOf(3, {500, 320, 240, 0.3, -0.05}),
            cameraOf(4, {500, 520, 321, 239, -0.28, 0.07, 0.01, -0.01})};
}

} // namespace

TEST(ColmapCameraModels, ParametersReadInTheModelsOrder)
{
    const CameraIntrinsics simpleRadial =
        essential_colmap::cameraIntrinsics(cameraOf(2, {500, 320, 240, -0.3}));
    EXPECT_EQ(simpleRadial.fx, 500);
    EXPECT_EQ(simpleRadial.fy, 500);
    EXPECT_EQ(simpleRadial.cx, 320);
    EXPECT_EQ(simpleRadial.cy, 240);
    EXPECT_EQ(simpleRadial.k1, -0.3);
    const CameraIntrinsics opencv = essential_colmap::cameraIntrinsics(
        cameraOf(4, {500, 520, 321, 239, -0.28, 0.07, 0.01, -0.02}));
    EXPECT_EQ(opencv.fy, 520);
    EXPECT_EQ(opencv.cx, 321);
    EXPECT_EQ(opencv.k2, 0.07);
    EXPECT_EQ(opencv.p1, 0.01);
    EXPECT_EQ(opencv.p2, -0.02);
}

TEST(ColmapCameraModels, UnsupportedModelRefusedByName)
{
    try {
        essential_colmap::cameraIntrinsics(cameraOf(5, {500, 500, 320, 240, 0, 0, 0, 0}));
        FAIL() << "OPENCV_FISHEYE was accepted";
    } catch (const essential_colmap::DatabaseError& e) {
        EXPECT_NE(std::string(e.what()).find("OPENCV_FISHEYE"), std::string::npos) << e.what();
    }
    EXPECT_THROW(essential_colmap::cameraIntrinsics(cameraOf(42, {1, 2, 3})),
                 essential_colmap::DatabaseError);
    // A parameter count that is not the model's.
    EXPECT_THROW(essential_colmap::cameraIntrinsics(cameraOf(1, {500, 320, 240})),
                 essential_colmap::DatabaseError);
}

TEST(ColmapCameraModels, UndistortionInvertsProjectionOverTheImage)
{
    for (const ColmapCamera& camera : supportedCameras()) {
        const CameraIntrinsics c = essential_colmap::cameraIntrinsics(camera);
        double worst = 0;
        // Every pixel of a 16-pixel grid over the whole image, corners included.
        for (int y = 0; y <= 480; y += 16)
            for (int x = 0; x <= 640; x += 16) {
                cv::Point2d normalised;
                ASSERT_TRUE(essential_colmap::undistortPixel(c, cv::Point2d(x, y), normalised))
                    << essential_colmap::cameraModelName(camera.modelId) << " at " << x << ", "
                    << y;
                const cv::Point2d back = essential_colmap::projectNormalised(c, normalised);
                worst = std::max(worst, cv::norm(back - cv::Point2d(x, y)));
            }
        // Newton stops at steps below 1e-12 normalised units, 5e-10 px at f = 500.
        EXPECT_LT(worst, 1e-8) << essential_colmap::cameraModelName(camera.modelId);
    }
}

TEST(ColmapCameraModels, BeyondTheFoldOfABarrelDistortionIsRefused)
{
    // k1 = -0.3: u (1 + k1 u^2) peaks at u = 1.05 (distorted 0.70), so a distorted point at 0.9
    // focal lengths from the centre has no preimage.
    const CameraIntrinsics c = essential_colmap::cameraIntrinsics(cameraOf(2, {500, 0, 0, -0.3}));
    cv::Point2d normalised;
    EXPECT_FALSE(essential_colmap::undistortPixel(c, cv::Point2d(450, 0), normalised));
    EXPECT_TRUE(essential_colmap::undistortPixel(c, cv::Point2d(300, 0), normalised));
}

namespace {

/** Writes a COLMAP text model: one camera, two images 0.5 apart, 60 points whose observations are
our projections (with the camera's parameters as written, or `writtenParams` if given); runs
`colmap bundle_adjuster` on it and returns its initial cost in pixels (-1 if not found). */
double colmapInitialCost(const ColmapCamera& camera, const std::string& name,
                         const std::vector<double>& writtenParams = {})
{
    const std::string dir = std::string(COLMAP_TEST_WORK) + "/model_" + name;
    std::string output;
    colmap_test::runCommand(
        name + "_mkdir", "rm -rf " + dir + " && mkdir -p " + dir + "/in " + dir + "/out", output);
    const CameraIntrinsics c = essential_colmap::cameraIntrinsics(camera);
    std::ofstream cameras(dir + "/in/cameras.txt");
    cameras.precision(17);
    cameras << "1 " << essential_colmap::cameraModelName(camera.modelId) << " " << camera.width
            << " " << camera.height;
    for (double p : writtenParams.empty() ? camera.params : writtenParams)
        cameras << " " << p;
    cameras << "\n";
    cameras.close();
    cv::RNG rng(3);
    std::vector<cv::Point3d> points;
    for (int i = 0; i < 60; ++i)
        points.emplace_back(rng.uniform(-2.0, 2.0), rng.uniform(-1.5, 1.5), rng.uniform(4.0, 8.0));
    std::ofstream images(dir + "/in/images.txt");
    images.precision(17);
    for (int image = 0; image < 2; ++image) {
        const double tx = -0.5 * image; // world to camera: X_cam = X + (tx, 0, 0)
        images << image + 1 << " 1 0 0 0 " << tx << " 0 0 1 im" << image << ".jpg\n";
        for (int i = 0; i < 60; ++i) {
            const cv::Point3d X = points[i] + cv::Point3d(tx, 0, 0);
            const cv::Point2d pixel =
                essential_colmap::projectNormalised(c, cv::Point2d(X.x / X.z, X.y / X.z));
            images << pixel.x << " " << pixel.y << " " << i + 1 << (i + 1 < 60 ? " " : "\n");
        }
    }
    images.close();
    std::ofstream points3D(dir + "/in/points3D.txt");
    points3D.precision(17);
    for (int i = 0; i < 60; ++i)
        points3D << i + 1 << " " << points[i].x << " " << points[i].y << " " << points[i].z
                 << " 0 0 0 0 1 " << i << " 2 " << i << "\n";
    points3D.close();
    colmap_test::runCommand(name,
                            "QT_QPA_PLATFORM=offscreen colmap bundle_adjuster --input_path " + dir +
                                "/in --output_path " + dir + "/out",
                            output);
    std::smatch match;
    if (!std::regex_search(output, match, std::regex("Initial cost : ([0-9.eE+-]+) \\[px\\]")))
        return -1;
    return std::stod(match[1]);
}

} // namespace

TEST(ColmapCameraModels, ProjectionIsColmapsOwn)
{
    if (!colmap_test::colmapInstalled())
        GTEST_SKIP() << "colmap is not installed (scripts/bootstrap.sh installs it)";
    // Measured: initial costs of 8e-15 to 1.3e-14 px for the five models (rounding of the 17-digit
    // text), and 1.7 px for the control below.
    int i = 0;
    for (const ColmapCamera& camera : supportedCameras()) {
        const double cost = colmapInitialCost(camera, "camera_model_" + std::to_string(i++));
        ASSERT_GE(cost, 0) << "no bundle adjustment report";
        EXPECT_LT(cost, 1e-6) << essential_colmap::cameraModelName(camera.modelId);
    }
    // Control: the same observations under swapped tangential coefficients are not COLMAP's
    // projection, so the check can fail.
    const ColmapCamera opencv = supportedCameras()[4];
    std::vector<double> swapped = opencv.params;
    std::swap(swapped[6], swapped[7]);
    EXPECT_GT(colmapInitialCost(opencv, "camera_model_swapped", swapped), 0.1);
}

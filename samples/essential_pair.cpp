// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// essential_pair: the relative pose of two calibrated images. FAST-9 corners and BRIEF descriptors
// on an image pyramid (or SIFT with Lowe's ratio test, --detector sift), matching, then
// cv::essential::findEssentialMatIter; or the correspondences of any other front end from a file
// (--matches). The same matches also go through cv::findEssentialMat + cv::recoverPose for
// comparison (unless --no-opencv). Prints text or one JSON object (--json), optionally writes E,
// R, t and the inlier mask to a FileStorage file (--output) and draws the matches and epipolar
// lines (--draw).

#include "cli_camera.hpp"
#include "cli_common.hpp"
#include "cli_estimator.hpp"
#include "cli_frontend_options.hpp"
#include "cli_matches.hpp"
#include "cli_parser.hpp"
#include "frontend/frontend.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/essential.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using essential_samples::directionAngleDeg;
using essential_samples::elapsedMs;
using essential_samples::fail;
using essential_samples::parseDouble;
using essential_samples::rotationAngleDeg;

std::string usage()
{
    return "usage: essential_pair IMG1 IMG2 CAMERA [options]\n"
           "       essential_pair --matches FILE [IMG1 IMG2] CAMERA [options]\n"
           "  CAMERA: --camera fx,fy,cx,cy [--distortion k1,k2,p1,p2[,k3...]]\n"
           "        | --camera-file FILE\n"
           "\n"
           "The relative pose of two views taken by one calibrated camera, by cv::essential and\n"
           "(for comparison) by cv::findEssentialMat + cv::recoverPose on the same matches.\n"
           "\n"
           "input:\n"
           "  IMG1 IMG2              two images (any format OpenCV reads: JPEG, PNG, ...); the\n"
           "                         sample front end matches them (FAST-9 pyramid + BRIEF, or\n"
           "                         SIFT + ratio test with --detector sift)\n"
           "  --matches FILE         correspondences of any front end instead, in pixels: CSV,\n"
           "                         one `x1,y1,x2,y2` per line (optional header line\n"
           "                         x1,y1,x2,y2; '#' comments), or an OpenCV FileStorage file\n"
           "                         (.yml/.yaml/.json/.xml) with two N x 2 matrices points1 and\n"
           "                         points2. Images, if given, are then only drawn (--draw)\n"
           "  --camera fx,fy,cx,cy   intrinsics of both views, in pixels\n"
           "  --camera-file FILE     OpenCV FileStorage (.yml/.yaml/.json/.xml) as written after\n"
           "                         cv::calibrateCamera: camera_matrix (or K) and optionally\n"
           "                         distortion_coefficients (or D), image_width, image_height;\n"
           "                         or text: `fx fy cx cy [width height]` on one line, or the\n"
           "                         3 x 3 camera matrix as three lines of three numbers; or\n"
           "                         KITTI's calib.txt (P0)\n"
           "  --distortion LIST      distortion coefficients k1,k2,p1,p2[,k3[,k4,k5,k6[,...]]]\n"
           "                         (4, 5, 8, 12 or 14, OpenCV's model); the points are\n"
           "                         undistorted (cv::undistortPoints) before both estimators\n"
           "\n"
           "front end (images only):\n" +
           essential_samples::detectorHelp() + essential_samples::frontEndHelp() + "\n" +
           essential_samples::estimatorHelp(false) +
           "\n"
           "output:\n"
           "  --no-opencv            skip the comparison run with cv::findEssentialMat\n"
           "  --json                 print the results as one JSON object instead of text\n"
           "  --output FILE          write E, R, t, the inlier mask (N x 1, 1 = inlier, in the\n"
           "                         order of the matches), the inlier count and the camera\n"
           "                         matrix to an OpenCV FileStorage file; the format follows the\n"
           "                         extension: .yml, .yaml, .json or .xml\n"
           "  --draw OUT.png         write both images side by side: inlier matches green,\n"
           "                         outliers red (a sample of at most 200), epipolar lines of 8\n"
           "                         inliers in both images in other colours\n"
           "  -h, --help             this help\n"
           "\n"
           "exit status: 0 pose found, 1 input error, 2 usage error, 3 no essential matrix found\n";
}

cv::Mat readImage(const std::string& path)
{
    if (!std::ifstream(path))
        fail("cannot open image '" + path + "' (no such file or not readable)");
    cv::Mat image = cv::imread(path, cv::IMREAD_GRAYSCALE);
    if (image.empty())
        fail("cannot read image '" + path + "' (not an image format OpenCV can decode)");
    return image;
}

struct Options
{
    std::string image1, image2;
    std::string camera, cameraFile, distortion;
    std::string matchesFile;
    essential_samples::FrontEndOptions frontEnd;
    essential_samples::EstimatorOptions estimator;
    bool opencv = true;
    bool json = false;
    std::string draw;
    std::string output;
};

Options parseOptions(int argc, char** argv)
{
    std::vector<essential_samples::OptionSpec> specs = essential_samples::estimatorOptionSpecs();
    for (const essential_samples::OptionSpec& spec : essential_samples::detectorOptionSpecs())
        specs.push_back(spec);
    for (const essential_samples::OptionSpec& spec : essential_samples::frontEndOptionSpecs())
        specs.push_back(spec);
    const std::vector<essential_samples::OptionSpec> own = {
        {"camera", true, ""},  {"camera-file", true, ""}, {"distortion", true, ""},
        {"matches", true, ""}, {"no-opencv", false, ""},  {"json", false, ""},
        {"output", true, ""},  {"draw", true, ""}};
    specs.insert(specs.end(), own.begin(), own.end());
    const essential_samples::CommandLine line =
        essential_samples::parseCommandLine("essential_pair", argc, argv, specs);
    if (line.help) {
        std::cout << usage();
        std::exit(0);
    }

    Options options;
    bool frontEndGiven = false;
    for (const essential_samples::GivenOption& option : line.options) {
        const std::string& value = option.value;
        if (essential_samples::applyEstimatorOption(option, false, options.estimator)) continue;
        if (essential_samples::applyDetectorOption(option, options.frontEnd) ||
            essential_samples::applyFrontEndOption(option, options.frontEnd)) {
            frontEndGiven = true;
            continue;
        }
        if (option.name == "camera") {
            options.camera = value;
        } else if (option.name == "camera-file") {
            options.cameraFile = value;
        } else if (option.name == "distortion") {
            options.distortion = value;
        } else if (option.name == "matches") {
            if (value.empty()) fail("--matches needs a file name", 2);
            options.matchesFile = value;
        } else if (option.name == "no-opencv") {
            options.opencv = false;
        } else if (option.name == "json") {
            options.json = true;
        } else if (option.name == "output") {
            if (!essential_samples::isFileStoragePath(value))
                fail("--output '" + value + "': the name must end in .yml, .yaml, .json or .xml",
                     2);
            options.output = value;
        } else if (option.name == "draw") {
            if (value.empty()) fail("--draw needs an output file name", 2);
            options.draw = value;
        }
    }

    const size_t images = line.positional.size();
    if (options.matchesFile.empty() && images != 2)
        fail("expected two images, got " + std::to_string(images) + " (see --help)", 2);
    if (!options.matchesFile.empty() && images != 0 && images != 2)
        fail("with --matches, give two images (for --draw) or none, not " + std::to_string(images),
             2);
    if (images == 2) {
        options.image1 = line.positional[0];
        options.image2 = line.positional[1];
    }
    if (!options.matchesFile.empty() && frontEndGiven)
        fail("--detector, --sift-features, --ratio, --descriptor, --matcher and --keep-fraction "
             "are front-end options; with --matches there is no front end",
             2);
    essential_samples::finishDetectorOptions(line.options, options.frontEnd);
    if (!options.draw.empty() && options.image1.empty())
        fail("--draw needs the two images (give IMG1 IMG2 with --matches)", 2);
    essential_samples::checkEstimatorCombination(options.estimator);
    if (options.camera.empty() == options.cameraFile.empty())
        fail(options.camera.empty()
                 ? "missing camera: give --camera fx,fy,cx,cy or --camera-file FILE"
                 : "give only one of --camera and --camera-file",
             2);
    return options;
}

std::string formatMatrix(const cv::Mat& m)
{
    std::string text;
    char buffer[64];
    for (int r = 0; r < m.rows; ++r) {
        text += r == 0 ? "  [" : "   ";
        for (int c = 0; c < m.cols; ++c) {
            std::snprintf(buffer, sizeof(buffer), "%s%10.6f", c == 0 ? "" : ", ",
                          m.at<double>(r, c));
            text += buffer;
        }
        text += r + 1 == m.rows ? "]\n" : ";\n";
    }
    return text;
}

double percent(int part, int whole)
{
    return whole > 0 ? 100.0 * part / whole : 0.0;
}

nlohmann::json matrixJson(const cv::Matx33d& m)
{
    nlohmann::json rows = nlohmann::json::array();
    for (int r = 0; r < 3; ++r)
        rows.push_back({m(r, 0), m(r, 1), m(r, 2)});
    return rows;
}

nlohmann::json vectorJson(const cv::Vec3d& v)
{
    return {v[0], v[1], v[2]};
}

// Draws the line a x + b y + c = 0 across the image region `roi` of `canvas` (line coordinates are
// those of the image, whose top-left corner is at roi.tl()).
void drawLineInRegion(cv::Mat& canvas, const cv::Rect& roi, const cv::Vec3d& line,
                      const cv::Scalar& colour)
{
    const double a = line[0], b = line[1], c = line[2];
    cv::Point2d p1, p2;
    if (std::abs(b) > std::abs(a)) { // closer to horizontal: intersect x = 0 and x = width - 1
        p1 = cv::Point2d(0, -c / b);
        p2 = cv::Point2d(roi.width - 1, -(c + a * (roi.width - 1)) / b);
    } else if (a != 0.0) {
        p1 = cv::Point2d(-c / a, 0);
        p2 = cv::Point2d(-(c + b * (roi.height - 1)) / a, roi.height - 1);
    } else {
        return;
    }
    cv::Mat region = canvas(roi);
    // Fixed-point coordinates (4 fractional bits) keep the sub-pixel position; clipLine inside
    // cv::line handles points far outside the region.
    const double s = 16.0;
    const auto clamp = [](double v) { return std::max(-1e8, std::min(1e8, v)); };
    cv::line(region, cv::Point(cvRound(clamp(p1.x * s)), cvRound(clamp(p1.y * s))),
             cv::Point(cvRound(clamp(p2.x * s)), cvRound(clamp(p2.y * s))), colour, 1, cv::LINE_AA,
             4);
}

// Both (grey) images side by side; inlier matches green, outliers red (at most 200 drawn; inliers
// at most 400), the epipolar lines of up to 8 inliers spread over image 1 in both images, one
// colour per correspondence.
void drawResult(const std::string& path, const cv::Mat& image1, const cv::Mat& image2,
                const essential_samples::Matches& matches, const cv::Mat& mask,
                const cv::Matx33d& K, const cv::Matx33d& E, bool found)
{
    const int width = image1.cols + image2.cols;
    const int height = std::max(image1.rows, image2.rows);
    cv::Mat canvas(height, width, CV_8UC3, cv::Scalar::all(0));
    const cv::Rect roi1(0, 0, image1.cols, image1.rows);
    const cv::Rect roi2(image1.cols, 0, image2.cols, image2.rows);
    cv::cvtColor(image1, canvas(roi1), cv::COLOR_GRAY2BGR);
    cv::cvtColor(image2, canvas(roi2), cv::COLOR_GRAY2BGR);
    canvas *= 0.75; // dim the images a little so that the lines stand out

    const int n = static_cast<int>(matches.points1.size());
    const auto isInlier = [&](int i) { return found && !mask.empty() && mask.at<uchar>(i) != 0; };
    const cv::Point2f shift(static_cast<float>(image1.cols), 0.f);
    const int shiftBits = 4;
    const auto fixedPoint = [&](cv::Point2f p) {
        return cv::Point(cvRound(p.x * (1 << shiftBits)), cvRound(p.y * (1 << shiftBits)));
    };

    // Outliers first (a sample: the matches are in random order), then the inliers on top.
    const int maxOutliers = 200;
    int outliersDrawn = 0;
    for (int i = 0; i < n && outliersDrawn < maxOutliers; ++i) {
        if (isInlier(i)) continue;
        cv::line(canvas, fixedPoint(matches.points1[i]), fixedPoint(matches.points2[i] + shift),
                 cv::Scalar(0, 0, 255), 1, cv::LINE_AA, shiftBits);
        ++outliersDrawn;
    }
    const int maxInliers = 400;
    int inliersDrawn = 0;
    for (int i = 0; i < n && inliersDrawn < maxInliers; ++i) {
        if (!isInlier(i)) continue;
        cv::line(canvas, fixedPoint(matches.points1[i]), fixedPoint(matches.points2[i] + shift),
                 cv::Scalar(0, 220, 0), 1, cv::LINE_AA, shiftBits);
        ++inliersDrawn;
    }

    if (found) {
        // Up to 8 inliers, picked on a 4 x 2 grid of image 1 so that the lines spread out.
        const cv::Matx33d Kinv = K.inv();
        const cv::Matx33d F = Kinv.t() * E * Kinv;
        const cv::Scalar palette[] = {{255, 255, 0}, {0, 255, 255},  {255, 0, 255},
                                      {255, 160, 0}, {0, 160, 255},  {255, 255, 255},
                                      {160, 0, 255}, {128, 255, 128}};
        int drawn = 0;
        for (int cell = 0; cell < 8; ++cell) {
            const cv::Rect2f area(float(image1.cols * (cell % 4) / 4.0),
                                  float(image1.rows * (cell / 4) / 2.0), float(image1.cols / 4.0),
                                  float(image1.rows / 2.0));
            for (int i = 0; i < n; ++i) {
                if (!isInlier(i) || !area.contains(matches.points1[i])) continue;
                const cv::Vec3d x1(matches.points1[i].x, matches.points1[i].y, 1.0);
                const cv::Vec3d x2(matches.points2[i].x, matches.points2[i].y, 1.0);
                const cv::Scalar& colour = palette[drawn % 8];
                drawLineInRegion(canvas, roi2, F * x1, colour);     // in image 2
                drawLineInRegion(canvas, roi1, F.t() * x2, colour); // in image 1
                cv::circle(canvas, fixedPoint(matches.points1[i]), 4 << shiftBits, colour, 2,
                           cv::LINE_AA, shiftBits);
                cv::circle(canvas, fixedPoint(matches.points2[i] + shift), 4 << shiftBits, colour,
                           2, cv::LINE_AA, shiftBits);
                ++drawn;
                break;
            }
        }
    }

    bool written = false;
    try {
        written = cv::imwrite(path, canvas);
    } catch (const cv::Exception& e) {
        fail("cannot write '" + path + "': " + e.err);
    }
    if (!written) fail("cannot write '" + path + "' (unknown extension or unwritable path)");
}

// The inlier mask, estimate and camera as an OpenCV FileStorage file (format by extension).
void writeOutput(const std::string& path, const cv::Matx33d& K, const cv::Mat& distortion,
                 const cv::essential::EssentialReport& report, bool found, const cv::Mat& mask,
                 int n)
{
    cv::FileStorage fs;
    try {
        fs.open(path, cv::FileStorage::WRITE);
    } catch (const cv::Exception& e) {
        fail("cannot write '" + path + "': " + e.err);
    }
    if (!fs.isOpened()) fail("cannot write '" + path + "'");
    fs << "found" << int(found);
    fs << "pose_recovered" << int(found && report.poseRecovered);
    fs << "matches" << n;
    fs << "inliers" << (found ? report.inliers : 0);
    fs << "camera_matrix" << cv::Mat(K);
    if (!distortion.empty()) fs << "distortion_coefficients" << distortion;
    if (found) fs << "E" << cv::Mat(report.E);
    if (found && report.poseRecovered) {
        fs << "R" << cv::Mat(report.R);
        fs << "t" << cv::Mat(report.t);
    }
    fs << "mask" << (mask.empty() ? cv::Mat::zeros(n, 1, CV_8U) : mask.reshape(1, n));
    fs.release();
}

int run(int argc, char** argv)
{
    const Options options = parseOptions(argc, argv);

    essential_samples::Camera camera;
    if (options.camera.empty())
        camera = essential_samples::readCameraFile(options.cameraFile);
    else
        camera.K = essential_samples::parseCameraOption(options.camera);
    if (!options.distortion.empty()) {
        if (!camera.distortion.empty())
            fail("--distortion: the camera file '" + options.cameraFile +
                     "' has distortion coefficients already",
                 2);
        camera.distortion = essential_samples::parseDistortionOption(options.distortion);
    }
    const cv::Matx33d K = camera.K;
    const bool haveImages = !options.image1.empty();
    cv::Mat image1, image2;
    if (haveImages) {
        image1 = readImage(options.image1);
        image2 = readImage(options.image2);
    }
    // Different image sizes are fine for the estimator (one camera matrix, pixel coordinates);
    // what matters is that the camera file, when it states a size, is for these images.
    std::vector<std::string> warnings;
    if (haveImages && camera.imageSize.area() > 0 &&
        (image1.size() != camera.imageSize || image2.size() != camera.imageSize))
        warnings.push_back("the camera file is for " + std::to_string(camera.imageSize.width) +
                           " x " + std::to_string(camera.imageSize.height) + " images");
    if (haveImages && image1.size() != image2.size())
        warnings.push_back("the images differ in size; one camera matrix is used for both");
    for (const std::string& warning : warnings)
        std::cerr << "essential_pair: warning: " << warning << "\n";

    // Front end, or the matches of the file.
    const essential_samples::FrontEndParams& frontParams = options.frontEnd;
    essential_samples::Features features1, features2;
    essential_samples::Matches matches;
    double timeFeatures1 = 0, timeFeatures2 = 0, timeMatching = 0;
    auto start = std::chrono::steady_clock::now();
    if (options.matchesFile.empty()) {
        features1 = essential_samples::detectAndDescribe(image1, frontParams);
        timeFeatures1 = elapsedMs(start);
        start = std::chrono::steady_clock::now();
        features2 = essential_samples::detectAndDescribe(image2, frontParams);
        timeFeatures2 = elapsedMs(start);
        start = std::chrono::steady_clock::now();
        matches = essential_samples::matchFeatures(features1, features2, frontParams);
        timeMatching = elapsedMs(start);
    } else {
        essential_samples::readMatchesFile(options.matchesFile, matches.points1, matches.points2);
        matches.candidates = static_cast<int>(matches.points1.size());
    }
    const int n = static_cast<int>(matches.points1.size());
    if (n < 5) fail("only " + std::to_string(n) + " matches; at least 5 are needed");
    if (!camera.distortion.empty()) {
        // Both estimators then see the points of an ideal camera K.
        cv::undistortPoints(std::vector<cv::Point2f>(matches.points1), matches.points1, K,
                            camera.distortion, cv::noArray(), K);
        cv::undistortPoints(std::vector<cv::Point2f>(matches.points2), matches.points2, K,
                            camera.distortion, cv::noArray(), K);
    }

    // cv::essential.
    const essential_samples::EstimatorOptions& estimator = options.estimator;
    const double budgetMs = estimator.budgetsMs.front();
    const cv::essential::EssentialParams params =
        essential_samples::estimatorParams(estimator, estimator.solvers.front(), budgetMs);
    cv::essential::EssentialReport report;
    cv::Mat mask;
    start = std::chrono::steady_clock::now();
    cv::Mat E;
    if (estimator.sampler == cv::SAMPLING_PROSAC && !matches.distances.empty()) {
        // PROSAC reads the order as quality: hand the matches over best first, and put the mask
        // back in the matches' order. (A matches file is taken in its own order.)
        const std::vector<int> order = essential_samples::orderByDistance(matches.distances);
        cv::Mat sortedMask;
        E = cv::essential::findEssentialMatIter(essential_samples::permuted(matches.points1, order),
                                                essential_samples::permuted(matches.points2, order),
                                                K, params, sortedMask, &report);
        mask = cv::Mat::zeros(n, 1, CV_8U);
        if (!sortedMask.empty())
            for (int k = 0; k < n; ++k)
                mask.at<uchar>(order[k]) = sortedMask.at<uchar>(k);
    } else {
        E = cv::essential::findEssentialMatIter(matches.points1, matches.points2, K, params, mask,
                                                &report);
    }
    const double timeEssential = elapsedMs(start);
    const bool found = !E.empty() && report.success;
    // A model that does not determine the pose (no parallax, or a plane) is still printed, with
    // this warning: docs/ROBUSTNESS.md, "Degenerate scenes".
    std::string degenerateNote;
    if (found && report.degenerate)
        degenerateNote = cv::format(
            "degenerate estimate: a rotation explains %.0f%% and a homography %.0f%% of the "
            "inliers; %s",
            100.0 * report.rotationOnlyFraction, 100.0 * report.homographyFraction,
            report.rotationOnlyFraction >= 0.9
                ? "no parallax, the translation direction is undetermined"
                : "a planar scene, two poses fit and this one may be the wrong one");
    if (!degenerateNote.empty()) std::cerr << "essential_pair: warning: " << degenerateNote << "\n";
    if (!options.output.empty())
        writeOutput(options.output, K, camera.distortion, report, found, mask, n);

    // OpenCV on the same matches.
    const int cvMethod = essential_samples::opencvMethod(estimator);
    const char* cvMethodName = cvMethod == cv::LMEDS ? "LMEDS" : "RANSAC";
    cv::Mat cvMask, cvE, cvR, cvT;
    double timeCvEssential = 0.0, timeCvPose = 0.0;
    int cvInliers = 0, cvInFront = 0;
    bool cvFound = false;
    if (options.opencv) {
        start = std::chrono::steady_clock::now();
        cvE = cv::findEssentialMat(matches.points1, matches.points2, K, cvMethod, 0.999,
                                   estimator.thresholdPx, estimator.maxIterations, cvMask);
        timeCvEssential = elapsedMs(start);
        cvInliers = cvMask.empty() ? 0 : cv::countNonZero(cvMask);
        cvFound = cvE.rows == 3 && cvE.cols == 3;
        if (cvFound) {
            start = std::chrono::steady_clock::now();
            cvInFront = cv::recoverPose(cvE, matches.points1, matches.points2, K, cvR, cvT, cvMask);
            timeCvPose = elapsedMs(start);
        }
    }
    const bool compared = found && report.poseRecovered && cvFound;
    const double rotationDiff = compared ? rotationAngleDeg(report.R, cv::Matx33d(cvR)) : 0.0;
    const double translationDiff =
        compared ? directionAngleDeg(report.t, cv::Vec3d(cvT), 0.0) : 0.0;

    if (!options.draw.empty())
        drawResult(options.draw, image1, image2, matches, mask, K, report.E, found);

    const bool fromFile = !options.matchesFile.empty();
    const bool sift = frontParams.detector == essential_samples::Detector::Sift;
    const char* distanceName =
        features1.descriptor == essential_samples::Descriptor::Patch ? "L2" : "Hamming";
    const std::string budgetNote =
        budgetMs > 0
            ? "time budget " + cv::format("%g", budgetMs) +
                  " ms: the search stops when the budget is spent or at confidence 1 - 1e-12 (" +
                  (estimator.maxIterationsGiven ? "cap --max-iterations" : "no iteration cap") + ")"
            : std::string("no time budget: the search stops at confidence 0.999 or at its cap, the "
                          "samples that fit in 3/4 of OpenCV's time for --max-iterations "
                          "iterations (local and uniform samples in turn past the confidence "
                          "cap)");
    const std::string planeNote =
        report.planeParallaxKept
            ? "plane check: the winner's inliers were dominated by a plane; a model fixed by "
              "the points off it had clearly more support and replaced it"
            : "plane check: the winner was kept";
    const std::string methodName = estimator.lmeds ? "lmeds" : "ransac";

    if (options.json) {
        nlohmann::json out;
        nlohmann::json images = nlohmann::json::array();
        if (haveImages)
            images = {{{"path", options.image1}, {"width", image1.cols}, {"height", image1.rows}},
                      {{"path", options.image2}, {"width", image2.cols}, {"height", image2.rows}}};
        out["images"] = images;
        out["camera"] = {{"fx", K(0, 0)}, {"fy", K(1, 1)}, {"cx", K(0, 2)}, {"cy", K(1, 2)}};
        std::vector<double> distortion;
        for (int i = 0; i < camera.distortion.cols; ++i)
            distortion.push_back(camera.distortion.at<double>(i));
        out["camera"]["distortion"] = distortion;
        out["warnings"] = warnings;
        if (fromFile)
            out["frontend"] = {{"matches_file", options.matchesFile}, {"matches", n}};
        else
            out["frontend"] = {
                {"detector", sift ? "SIFT" : "FAST-9 pyramid"},
                {"levels", features1.levels},
                {"descriptor", essential_samples::descriptorName(features1.descriptor)},
                {"matcher", essential_samples::matcherName(frontParams.matcher)},
                {"corners", {features1.keypoints.size(), features2.keypoints.size()}},
                {"candidates", matches.candidates},
                {"keep_fraction", frontParams.keepFraction},
                {"matches", n},
                {"max_distance", matches.maxDistance}};
        if (!fromFile && sift) {
            out["frontend"]["sift_features"] = frontParams.siftFeatures;
            out["frontend"]["ratio"] = frontParams.ratio;
            out["frontend"]["ratio_test_passed"] = matches.ratioTestPassed;
        }
        nlohmann::json ours = {{"solver", params.solver},
                               {"engine", essential_samples::engineName(estimator.engine)},
                               {"method", methodName},
                               {"sampler", essential_samples::samplerName(estimator.sampler)},
                               {"threshold_px", params.threshold},
                               {"seed", params.seed},
                               {"max_iterations", estimator.maxIterations},
                               {"confidence", params.confidence},
                               {"budget_ms", budgetMs},
                               {"stopping", budgetNote},
                               {"found", found},
                               {"pose_recovered", found && report.poseRecovered},
                               {"degenerate", found && report.degenerate},
                               {"rotation_only_fraction", report.rotationOnlyFraction},
                               {"homography_fraction", report.homographyFraction},
                               {"inliers", report.inliers},
                               {"inlier_ratio", n > 0 ? double(report.inliers) / n : 0.0},
                               {"points_in_front", report.pointsInFront},
                               {"iterations", report.iterations},
                               {"hypotheses_generated", report.hypothesesGenerated},
                               {"hypotheses_converged", report.hypothesesConverged},
                               {"hypotheses_scored", report.hypothesesScored},
                               {"refine_iterations", report.refineIterations},
                               {"plane_check_replaced", report.planeParallaxKept},
                               {"in_front_search", report.inFrontSearch},
                               {"in_front_search_replaced", report.inFrontSearchKept}};
        if (found) ours["E"] = matrixJson(report.E);
        if (found && report.poseRecovered) {
            ours["R"] = matrixJson(report.R);
            ours["t"] = vectorJson(report.t);
        }
        out["essential"] = ours;
        if (options.opencv) {
            nlohmann::json reference = {{"method", cvMethodName},
                                        {"confidence", 0.999},
                                        {"threshold_px", estimator.thresholdPx},
                                        {"max_iterations", estimator.maxIterations},
                                        {"found", cvFound},
                                        {"inliers", cvInliers},
                                        {"inlier_ratio", n > 0 ? double(cvInliers) / n : 0.0},
                                        {"points_in_front", cvInFront}};
            if (cvFound) {
                const cv::Mat cvEn = cvE / cv::norm(cvE); // unit norm, as ours
                reference["E"] = matrixJson(cv::Matx33d(cvEn));
                reference["R"] = matrixJson(cv::Matx33d(cvR));
                reference["t"] = vectorJson(cv::Vec3d(cvT));
            }
            out["opencv"] = reference;
        } else {
            out["opencv"] = nullptr;
        }
        out["difference"] = compared
                                ? nlohmann::json{{"rotation_deg", rotationDiff},
                                                 {"translation_direction_deg", translationDiff}}
                                : nlohmann::json(nullptr);
        out["times_ms"] = {{"frontend",
                            {{"total", timeFeatures1 + timeFeatures2 + timeMatching},
                             {"image1", timeFeatures1},
                             {"image2", timeFeatures2},
                             {"matching", timeMatching}}},
                           {"essential",
                            {{"total", timeEssential},
                             {"setup", report.timeSetupMs},
                             {"search", report.timeSearchMs},
                             {"refine", report.timeRefineMs},
                             {"pose", report.timePoseMs}}},
                           {"opencv",
                            {{"total", timeCvEssential + timeCvPose},
                             {"findEssentialMat", timeCvEssential},
                             {"recoverPose", timeCvPose}}}};
        if (!options.draw.empty()) out["drawing"] = options.draw;
        if (!options.output.empty()) out["output"] = options.output;
        std::cout << out.dump(2) << "\n";
        return found ? 0 : 3;
    }

    if (haveImages)
        std::printf("images: %s (%d x %d), %s (%d x %d)\n", options.image1.c_str(), image1.cols,
                    image1.rows, options.image2.c_str(), image2.cols, image2.rows);
    std::printf("camera: fx %.3f, fy %.3f, cx %.3f, cy %.3f", K(0, 0), K(1, 1), K(0, 2), K(1, 2));
    std::printf(camera.distortion.empty() ? "\n"
                                          : ", %d distortion coefficients (points undistorted)\n",
                camera.distortion.cols);
    if (fromFile) {
        std::printf("matches: %d from %s\n", n, options.matchesFile.c_str());
    } else if (sift) {
        std::printf("keypoints: %zu in image 1, %zu in image 2 (SIFT, %d octaves, %s)\n",
                    features1.keypoints.size(), features2.keypoints.size(), features1.levels,
                    frontParams.siftFeatures > 0
                        ? cv::format("the %d strongest", frontParams.siftFeatures).c_str()
                        : "all");
        std::printf("matches: %d (%d of %d pass the ratio test %g; best %.0f%% of these by L2 "
                    "distance, up to %g; matcher %s)\n",
                    n, matches.ratioTestPassed, matches.candidates, frontParams.ratio,
                    100.0 * frontParams.keepFraction, static_cast<double>(matches.maxDistance),
                    essential_samples::matcherName(frontParams.matcher));
    } else {
        std::printf("corners: %zu in image 1, %zu in image 2 (FAST-9 on %d pyramid levels, %s)\n",
                    features1.keypoints.size(), features2.keypoints.size(), features1.levels,
                    essential_samples::descriptorName(features1.descriptor));
        std::printf("matches: %d (best %.0f%% of %d by %s distance, up to %g; matcher %s)\n", n,
                    100.0 * frontParams.keepFraction, matches.candidates, distanceName,
                    static_cast<double>(matches.maxDistance),
                    essential_samples::matcherName(frontParams.matcher));
    }

    std::printf("\ncv::essential::findEssentialMatIter (solver %s, engine %s, method %s, sampler "
                "%s, threshold %g px, seed 0x%llx)\n",
                params.solver.c_str(), essential_samples::engineName(estimator.engine),
                methodName.c_str(), essential_samples::samplerName(estimator.sampler),
                params.threshold, static_cast<unsigned long long>(params.seed));
    std::printf("%s\n%s\n", budgetNote.c_str(), planeNote.c_str());
    if (report.inFrontSearch)
        std::printf("in-front check: over 5%% of the winner's inliers lay behind the cameras; a "
                    "second search scoring only inliers in front %s\n",
                    report.inFrontSearchKept ? "found a better model, returned" : "kept the first");
    if (found) {
        std::printf("E =\n%s", formatMatrix(cv::Mat(report.E)).c_str());
        if (report.poseRecovered) {
            std::printf("R =\n%s", formatMatrix(cv::Mat(report.R)).c_str());
            std::printf("t =\n%s", formatMatrix(cv::Mat(report.t).t()).c_str());
        } else {
            std::printf("R, t: not recovered\n");
        }
    } else {
        std::printf("no essential matrix found\n");
    }
    std::printf("inliers: %d of %d (%.1f%%), %d in front of both cameras\n", report.inliers, n,
                percent(report.inliers, n), report.pointsInFront);
    if (!degenerateNote.empty()) std::printf("warning: %s\n", degenerateNote.c_str());
    std::printf("hypotheses: %d generated, %d converged, %d scored; %d iterations, "
                "%d refinement iterations\n",
                report.hypothesesGenerated, report.hypothesesConverged, report.hypothesesScored,
                report.iterations, report.refineIterations);

    if (options.opencv) {
        std::printf("\ncv::findEssentialMat + cv::recoverPose (%s, prob 0.999, threshold %g px)\n",
                    cvMethodName, estimator.thresholdPx);
        if (cvFound) {
            std::printf("E =\n%s", formatMatrix(cvE / cv::norm(cvE)).c_str());
            std::printf("R =\n%s", formatMatrix(cvR).c_str());
            std::printf("t =\n%s", formatMatrix(cvT.t()).c_str());
        } else {
            std::printf("no essential matrix found\n");
        }
        std::printf("inliers: %d of %d (%.1f%%), %d in front of both cameras\n", cvInliers, n,
                    percent(cvInliers, n), cvInFront);
        if (compared)
            std::printf("difference: rotation %.3f deg, translation direction %.3f deg\n",
                        rotationDiff, translationDiff);
    }

    std::printf("\ntimes (ms):\n");
    if (!fromFile)
        std::printf("  front end        %9.2f  (image 1 %.2f, image 2 %.2f, matching %.2f)\n",
                    timeFeatures1 + timeFeatures2 + timeMatching, timeFeatures1, timeFeatures2,
                    timeMatching);
    std::printf("  cv::essential    %9.2f  (setup %.2f, search %.2f, refine %.2f, pose %.2f)\n",
                timeEssential, report.timeSetupMs, report.timeSearchMs, report.timeRefineMs,
                report.timePoseMs);
    if (options.opencv)
        std::printf("  OpenCV           %9.2f  (findEssentialMat %.2f, recoverPose %.2f)\n",
                    timeCvEssential + timeCvPose, timeCvEssential, timeCvPose);
    if (!options.draw.empty()) std::printf("\ndrawing: %s\n", options.draw.c_str());
    if (!options.output.empty()) std::printf("output: %s\n", options.output.c_str());
    return found ? 0 : 3;
}

} // namespace

int main(int argc, char** argv)
{
    return essential_samples::runCli("essential_pair", run, argc, argv);
}

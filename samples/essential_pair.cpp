// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// essential_pair: the relative pose of two calibrated images. FAST-9 corners and BRIEF descriptors
// on an image pyramid, brute-force matching, then cv::essential::findEssentialMatIter; the same
// matches also go through cv::findEssentialMat + cv::recoverPose for comparison. Prints text or one
// JSON object (--json), and optionally draws the matches and epipolar lines (--draw).

#include "cli_common.hpp"
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
using essential_samples::isOption;
using essential_samples::optionValue;
using essential_samples::parseDouble;
using essential_samples::parseInt;
using essential_samples::parseSeed;
using essential_samples::readNumberRows;
using essential_samples::rotationAngleDeg;
using essential_samples::split;

const char* const kUsage =
    "usage: essential_pair IMG1 IMG2 (--camera fx,fy,cx,cy | --camera-file F)\n"
    "                      [--solver NAME] [--threshold PX] [--seed S] [--keep FRACTION]\n"
    "                      [--max-iters N] [--budget-ms T] [--descriptor brief|orb|patch]\n"
    "                      [--sampler uniform|prosac|napsac|pnapsac]\n"
    "                      [--json] [--draw OUT.png]\n"
    "\n"
    "  --camera fx,fy,cx,cy  intrinsics of both images, in pixels\n"
    "  --camera-file F       a file holding `fx fy cx cy [width height]` on one line,\n"
    "                        or a 3 x 3 camera matrix as three lines of three numbers\n"
    "  --solver NAME         solver of cv::essential, or a mix such as gn+nister\n"
    "                        (default: the module's default, gn+nister)\n"
    "  --threshold PX        inlier threshold on the Sampson distance, pixels (default 1)\n"
    "  --seed S              seed of the estimator's random generator (decimal or 0x hex)\n"
    "  --keep FRACTION       fraction of the matches kept, the best by descriptor distance,\n"
    "                        in (0, 1] (default 0.2)\n"
    "  --max-iters N         iteration cap of both estimators (default 1000, as OpenCV)\n"
    "  --budget-ms T         time budget of cv::essential in milliseconds: the search then\n"
    "                        stops when the budget is spent (or, on easy data, once it is\n"
    "                        1 - 1e-12 confident; no iteration cap unless --max-iters is\n"
    "                        given); OpenCV has no budget\n"
    "  --descriptor D        front-end descriptor: brief (upright, default), orb (rBRIEF)\n"
    "                        or patch (normalised 8 x 8 grey patch)\n"
    "  --sampler S           how cv::essential draws samples: uniform (default, the module's\n"
    "                        own: uniform until the confidence cap, then local and uniform in\n"
    "                        turn for the rest of OpenCV's time), prosac (the matches handed\n"
    "                        over sorted by descriptor distance, best first), napsac (all\n"
    "                        samples local) or pnapsac (local and uniform in turn); OpenCV\n"
    "                        always gets the matches in their random order\n"
    "  --json                print the results as one JSON object instead of text\n"
    "  --draw OUT.png        write both images side by side: inlier matches green, outliers\n"
    "                        red (a sample of at most 200), epipolar lines of 8 inliers in\n"
    "                        both images in other colours\n"
    "\n"
    "exit status: 0 pose found, 1 input error, 2 usage error, 3 no essential matrix found\n";

cv::Matx33d cameraFromValues(double fx, double fy, double cx, double cy)
{
    return cv::Matx33d(fx, 0, cx, 0, fy, cy, 0, 0, 1);
}

void checkCamera(const cv::Matx33d& K, const std::string& origin)
{
    for (int i = 0; i < 9; ++i)
        if (!std::isfinite(K.val[i])) fail("malformed camera (" + origin + "): non-finite value");
    if (!(K(0, 0) > 0.0) || !(K(1, 1) > 0.0))
        fail("malformed camera (" + origin + "): fx and fy must be positive");
    if (K(2, 0) != 0.0 || K(2, 1) != 0.0 || K(2, 2) != 1.0)
        fail("malformed camera (" + origin + "): the last row of the matrix must be 0 0 1");
}

// --camera fx,fy,cx,cy
cv::Matx33d parseCameraOption(const std::string& text)
{
    const std::vector<std::string> parts = split(text, ',');
    double v[4];
    if (parts.size() != 4)
        fail("malformed camera '" + text + "': expected --camera fx,fy,cx,cy (four numbers)", 2);
    for (int i = 0; i < 4; ++i)
        if (!parseDouble(parts[i], v[i]))
            fail("malformed camera '" + text + "': '" + parts[i] + "' is not a number", 2);
    const cv::Matx33d K = cameraFromValues(v[0], v[1], v[2], v[3]);
    checkCamera(K, "--camera " + text);
    return K;
}

// --camera-file F: `fx fy cx cy [width height]` on one line, or a 3 x 3 matrix on three lines.
// Blank lines and lines starting with '#' are ignored.
cv::Matx33d readCameraFile(const std::string& path, cv::Size& imageSize)
{
    std::ifstream file(path);
    if (!file) fail("cannot open camera file '" + path + "'");

    const std::vector<std::vector<double>> rows =
        readNumberRows(file, "malformed camera file '" + path + "'");

    cv::Matx33d K;
    imageSize = cv::Size();
    if (rows.size() == 1 && (rows[0].size() == 4 || rows[0].size() == 6)) {
        const std::vector<double>& r = rows[0];
        K = cameraFromValues(r[0], r[1], r[2], r[3]);
        if (r.size() == 6) {
            if (r[4] < 1 || r[5] < 1 || r[4] != std::floor(r[4]) || r[5] != std::floor(r[5]))
                fail("malformed camera file '" + path +
                     "': width and height must be positive "
                     "integers");
            imageSize = cv::Size(static_cast<int>(r[4]), static_cast<int>(r[5]));
        }
    } else if (rows.size() == 3 && rows[0].size() == 3 && rows[1].size() == 3 &&
               rows[2].size() == 3) {
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                K(i, j) = rows[i][j];
    } else {
        fail("malformed camera file '" + path +
             "': expected one line `fx fy cx cy [width height]` or three lines of three numbers");
    }
    checkCamera(K, path);
    return K;
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
    std::string camera, cameraFile;
    std::string solver = cv::essential::EssentialParams().solver;
    double threshold = cv::essential::EssentialParams().threshold;
    std::uint64_t seed = cv::essential::EssentialParams().seed;
    double keep = essential_samples::FrontEndParams().keepFraction;
    int maxIters = cv::essential::EssentialParams().maxIterations;
    bool maxItersGiven = false;
    double budgetMs = 0;
    essential_samples::Descriptor descriptor = essential_samples::FrontEndParams().descriptor;
    /** The module's default (uniform, with local samples past the confidence cap). PROSAC on the
    descriptor order is an option, not the default: on the front end's best 20% of the rail
    matches it took twice the time and got one pose of 54 wrong where uniform got none
    (docs/HARD_PAIRS.md). */
    cv::SamplingMethod sampler = cv::SAMPLING_UNIFORM;
    bool json = false;
    std::string draw;
};

Options parseOptions(int argc, char** argv)
{
    Options options;
    std::vector<std::string> positional;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg == "-h" || arg == "--help") {
            std::cout << kUsage;
            std::exit(0);
        }
        if (arg == "--json") {
            options.json = true;
            continue;
        }
        if (!isOption(arg)) {
            positional.push_back(arg);
            continue;
        }
        const std::string value = optionValue(arg, i, argc, argv);

        if (arg == "--camera") {
            options.camera = value;
        } else if (arg == "--camera-file") {
            options.cameraFile = value;
        } else if (arg == "--solver") {
            options.solver = value;
        } else if (arg == "--threshold") {
            if (!parseDouble(value, options.threshold) || !(options.threshold > 0.0))
                fail("--threshold must be a positive number of pixels, not '" + value + "'", 2);
        } else if (arg == "--seed") {
            if (!parseSeed(value, options.seed))
                fail("--seed must be a non-negative integer, not '" + value + "'", 2);
        } else if (arg == "--keep") {
            if (!parseDouble(value, options.keep) || !(options.keep > 0.0 && options.keep <= 1.0))
                fail("--keep must be a fraction in (0, 1], not '" + value + "'", 2);
        } else if (arg == "--max-iters") {
            long long iters;
            if (!parseInt(value, iters) || iters < 1 || iters > 100000000)
                fail("--max-iters must be a positive integer, not '" + value + "'", 2);
            options.maxIters = static_cast<int>(iters);
            options.maxItersGiven = true;
        } else if (arg == "--budget-ms") {
            if (!parseDouble(value, options.budgetMs) || !(options.budgetMs > 0.0))
                fail("--budget-ms must be a positive number of milliseconds, not '" + value + "'",
                     2);
        } else if (arg == "--descriptor") {
            if (!essential_samples::parseDescriptor(value, options.descriptor))
                fail("--descriptor must be brief, orb or patch, not '" + value + "'", 2);
        } else if (arg == "--sampler") {
            if (!essential_samples::parseSampler(value, options.sampler))
                fail("--sampler must be prosac, uniform, napsac or pnapsac, not '" + value + "'",
                     2);
        } else if (arg == "--draw") {
            if (value.empty()) fail("--draw needs an output file name", 2);
            options.draw = value;
        } else {
            fail("unknown option '" + arg + "' (see --help)", 2);
        }
    }

    if (positional.size() != 2)
        fail("expected two images, got " + std::to_string(positional.size()) + " (see --help)", 2);
    options.image1 = positional[0];
    options.image2 = positional[1];
    if (options.camera.empty() == options.cameraFile.empty())
        fail(options.camera.empty() ? "missing camera: give --camera fx,fy,cx,cy or --camera-file F"
                                    : "give only one of --camera and --camera-file",
             2);

    // createSolver accepts registered names and composites ("gn+nister"); its message lists the
    // registered solvers.
    try {
        cv::essential::createSolver(options.solver);
    } catch (const cv::Exception& e) {
        fail(e.err, 2);
    }
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

int run(int argc, char** argv)
{
    const Options options = parseOptions(argc, argv);

    cv::Size cameraImageSize;
    const cv::Matx33d K = options.camera.empty()
                              ? readCameraFile(options.cameraFile, cameraImageSize)
                              : parseCameraOption(options.camera);
    const cv::Mat image1 = readImage(options.image1);
    const cv::Mat image2 = readImage(options.image2);
    // Different image sizes are fine for the estimator (one camera matrix, pixel coordinates);
    // what matters is that the camera file, when it states a size, is for these images.
    std::vector<std::string> warnings;
    if (cameraImageSize.area() > 0 &&
        (image1.size() != cameraImageSize || image2.size() != cameraImageSize))
        warnings.push_back("the camera file is for " + std::to_string(cameraImageSize.width) +
                           " x " + std::to_string(cameraImageSize.height) + " images");
    if (image1.size() != image2.size())
        warnings.push_back("the images differ in size; one camera matrix is used for both");
    for (const std::string& warning : warnings)
        std::cerr << "essential_pair: warning: " << warning << "\n";

    // Front end.
    essential_samples::FrontEndParams frontParams;
    frontParams.keepFraction = options.keep;
    frontParams.descriptor = options.descriptor;
    auto start = std::chrono::steady_clock::now();
    const essential_samples::Features features1 =
        essential_samples::detectAndDescribe(image1, frontParams);
    const double timeFeatures1 = elapsedMs(start);
    start = std::chrono::steady_clock::now();
    const essential_samples::Features features2 =
        essential_samples::detectAndDescribe(image2, frontParams);
    const double timeFeatures2 = elapsedMs(start);
    start = std::chrono::steady_clock::now();
    const essential_samples::Matches matches =
        essential_samples::matchFeatures(features1, features2, frontParams);
    const double timeMatching = elapsedMs(start);
    const int n = static_cast<int>(matches.points1.size());
    if (n < 5) fail("only " + std::to_string(n) + " matches; at least 5 are needed");

    // cv::essential.
    cv::essential::EssentialParams params;
    params.solver = options.solver;
    params.threshold = options.threshold;
    params.seed = options.seed;
    params.maxIterations = options.maxIters;
    if (options.budgetMs > 0) {
        // The budget, not the confidence or (unless given) the cap, ends the search.
        params.timeBudgetMs = options.budgetMs;
        params.confidence = 1.0 - 1e-12;
        if (!options.maxItersGiven) params.maxIterations = 100000000;
    }
    params.sampler = options.sampler;
    cv::essential::EssentialReport report;
    cv::Mat mask;
    start = std::chrono::steady_clock::now();
    cv::Mat E;
    if (options.sampler == cv::SAMPLING_PROSAC) {
        // PROSAC reads the order as quality: hand the matches over best first, and put the mask
        // back in the matches' order.
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

    // OpenCV on the same matches.
    cv::Mat cvMask;
    start = std::chrono::steady_clock::now();
    const cv::Mat cvE = cv::findEssentialMat(matches.points1, matches.points2, K, cv::RANSAC, 0.999,
                                             options.threshold, options.maxIters, cvMask);
    const double timeCvEssential = elapsedMs(start);
    const int cvInliers = cvMask.empty() ? 0 : cv::countNonZero(cvMask);
    cv::Mat cvR, cvT;
    int cvInFront = 0;
    double timeCvPose = 0.0;
    const bool cvFound = cvE.rows == 3 && cvE.cols == 3;
    if (cvFound) {
        start = std::chrono::steady_clock::now();
        cvInFront = cv::recoverPose(cvE, matches.points1, matches.points2, K, cvR, cvT, cvMask);
        timeCvPose = elapsedMs(start);
    }
    const bool compared = found && report.poseRecovered && cvFound;
    const double rotationDiff = compared ? rotationAngleDeg(report.R, cv::Matx33d(cvR)) : 0.0;
    const double translationDiff =
        compared ? directionAngleDeg(report.t, cv::Vec3d(cvT), 0.0) : 0.0;

    if (!options.draw.empty())
        drawResult(options.draw, image1, image2, matches, mask, K, report.E, found);

    const char* distanceName =
        features1.descriptor == essential_samples::Descriptor::Patch ? "L2" : "Hamming";
    const std::string budgetNote =
        options.budgetMs > 0
            ? "time budget " + cv::format("%g", options.budgetMs) +
                  " ms: the search stops when the budget is spent or at confidence 1 - 1e-12 (" +
                  (options.maxItersGiven ? "cap --max-iters" : "no iteration cap") + ")"
            : std::string("no time budget: the search stops at confidence 0.999 or at its cap, the "
                          "samples that fit in 3/4 of OpenCV's time for --max-iters iterations "
                          "(local and uniform samples in turn past the confidence cap)");
    const std::string planeNote =
        report.planeParallaxKept
            ? "plane check: the winner's inliers were dominated by a plane; a model fixed by "
              "the points off it had clearly more support and replaced it"
            : "plane check: the winner was kept";

    if (options.json) {
        nlohmann::json out;
        out["images"] = {
            {{"path", options.image1}, {"width", image1.cols}, {"height", image1.rows}},
            {{"path", options.image2}, {"width", image2.cols}, {"height", image2.rows}}};
        out["camera"] = {{"fx", K(0, 0)}, {"fy", K(1, 1)}, {"cx", K(0, 2)}, {"cy", K(1, 2)}};
        out["warnings"] = warnings;
        out["frontend"] = {{"detector", "FAST-9 pyramid"},
                           {"levels", features1.levels},
                           {"descriptor", essential_samples::descriptorName(features1.descriptor)},
                           {"corners", {features1.keypoints.size(), features2.keypoints.size()}},
                           {"candidates", matches.candidates},
                           {"keep_fraction", options.keep},
                           {"matches", n},
                           {"max_distance", matches.maxDistance}};
        nlohmann::json ours = {{"solver", params.solver},
                               {"sampler", essential_samples::samplerName(params.sampler)},
                               {"threshold_px", params.threshold},
                               {"seed", params.seed},
                               {"max_iters", params.maxIterations},
                               {"confidence", params.confidence},
                               {"budget_ms", options.budgetMs},
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
                               {"plane_check_replaced", report.planeParallaxKept}};
        if (found) ours["E"] = matrixJson(report.E);
        if (found && report.poseRecovered) {
            ours["R"] = matrixJson(report.R);
            ours["t"] = vectorJson(report.t);
        }
        out["essential"] = ours;
        nlohmann::json reference = {{"method", "RANSAC"},
                                    {"confidence", 0.999},
                                    {"threshold_px", options.threshold},
                                    {"max_iters", options.maxIters},
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
        std::cout << out.dump(2) << "\n";
        return found ? 0 : 3;
    }

    std::printf("images: %s (%d x %d), %s (%d x %d)\n", options.image1.c_str(), image1.cols,
                image1.rows, options.image2.c_str(), image2.cols, image2.rows);
    std::printf("camera: fx %.3f, fy %.3f, cx %.3f, cy %.3f\n", K(0, 0), K(1, 1), K(0, 2), K(1, 2));
    std::printf("corners: %zu in image 1, %zu in image 2 (FAST-9 on %d pyramid levels, %s)\n",
                features1.keypoints.size(), features2.keypoints.size(), features1.levels,
                essential_samples::descriptorName(features1.descriptor));
    std::printf("matches: %d (best %.0f%% of %d by %s distance, up to %g)\n", n,
                100.0 * options.keep, matches.candidates, distanceName,
                static_cast<double>(matches.maxDistance));

    std::printf("\ncv::essential::findEssentialMatIter (solver %s, sampler %s, threshold %g px, "
                "seed 0x%llx)\n",
                params.solver.c_str(), essential_samples::samplerName(params.sampler),
                params.threshold, static_cast<unsigned long long>(params.seed));
    std::printf("%s\n%s\n", budgetNote.c_str(), planeNote.c_str());
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

    std::printf("\ncv::findEssentialMat + cv::recoverPose (RANSAC, prob 0.999, threshold %g px)\n",
                options.threshold);
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
        std::printf("difference: rotation %.3f deg, translation direction %.3f deg\n", rotationDiff,
                    translationDiff);

    std::printf("\ntimes (ms):\n");
    std::printf("  front end        %9.2f  (image 1 %.2f, image 2 %.2f, matching %.2f)\n",
                timeFeatures1 + timeFeatures2 + timeMatching, timeFeatures1, timeFeatures2,
                timeMatching);
    std::printf("  cv::essential    %9.2f  (setup %.2f, search %.2f, refine %.2f, pose %.2f)\n",
                timeEssential, report.timeSetupMs, report.timeSearchMs, report.timeRefineMs,
                report.timePoseMs);
    std::printf("  OpenCV           %9.2f  (findEssentialMat %.2f, recoverPose %.2f)\n",
                timeCvEssential + timeCvPose, timeCvEssential, timeCvPose);
    if (!options.draw.empty()) std::printf("\ndrawing: %s\n", options.draw.c_str());
    return found ? 0 : 3;
}

} // namespace

int main(int argc, char** argv)
{
    return essential_samples::runCli("essential_pair", run, argc, argv);
}

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// essential_sequence: relative poses of frame pairs (t - N, t) of an image sequence. The sample
// front end (features cached per frame) feeds cv::essential::findEssentialMatIter with each solver
// and time budget, optionally cv::findEssentialMat + cv::recoverPose as a reference; with ground
// truth poses (rail, TUM or KITTI format) a pair is correct when the estimated translation
// direction is within a threshold of the true one. Writes one CSV row per (pair, solver, budget)
// and a summary table on stdout.

#include "cli_camera.hpp"
#include "cli_common.hpp"
#include "cli_estimator.hpp"
#include "cli_frontend_options.hpp"
#include "cli_parser.hpp"
#include "cli_sequence_input.hpp"
#include "frontend/frontend.hpp"
#include "frontend/sequence_io.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/essential.hpp>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using essential_samples::directionAngleDeg;
using essential_samples::elapsedMs;
using essential_samples::fail;
using essential_samples::parseDouble;
using essential_samples::parseInt;
using essential_samples::Pose;
using essential_samples::rotationAngleDeg;
using essential_samples::sampsonPx;
using essential_samples::split;

std::string usage()
{
    return "usage: essential_sequence DIR [options]\n"
           "\n"
           "Relative poses of the frame pairs (t - N, t) of a sequence by cv::essential (each\n"
           "solver and time budget), optionally cv::findEssentialMat as a reference; with ground\n"
           "truth, how often the translation direction is right. One CSV row per estimate\n"
           "(--csv), a Markdown summary on stdout.\n"
           "\n"
           "DIR holds the frames NNN.jpg, NNN.jpeg or NNN.png (numbered by their names, any "
           "number\n"
           "of digits), or DIR/rgb.txt lists them (`timestamp path` per line, the TUM RGB-D\n"
           "layout; numbered 0, 1, ... in that order). Camera: DIR/camera.txt unless --camera or\n"
           "--camera-file is given (same formats as there). Ground truth (optional): --poses, or\n"
           "else DIR/poses.txt or DIR/groundtruth.txt, in one of the formats:\n"
           "  rail   `k r00 r01 .. r22 Cx Cy Cz`: frame k, world-to-camera rotation, camera "
           "centre\n"
           "  tum    `timestamp tx ty tz qx qy qz qw`: camera-to-world (TUM RGB-D); a frame gets\n"
           "         the pose of the nearest timestamp within 0.02 s (needs DIR/rgb.txt)\n"
           "  kitti  12 numbers per line, the 3 x 4 camera-to-world matrix (KITTI odometry);\n"
           "         line i is frame i\n"
           "\n"
           "pairs and ground truth:\n"
           "  --offsets LIST         frame offsets N: numbers and ranges A..B, comma separated\n"
           "                         (default 1,5,10,20,40,60)\n"
           "  --frames-step K        use every K-th frame t = first, first + K, ... as the later\n"
           "                         frame of the pairs (default 1: every frame)\n"
           "  --poses FILE           ground-truth poses (default DIR/poses.txt, else\n"
           "                         DIR/groundtruth.txt, if present)\n"
           "  --pose-format F        auto (default: by the values per line, 13 rail, 12 kitti,\n"
           "                         8 tum), rail, tum or kitti\n"
           "  --threshold-deg D      a pair is correct when the translation direction is within\n"
           "                         D degrees of the truth (default 10)\n"
           "  --camera fx,fy,cx,cy   intrinsics, in pixels (instead of DIR/camera.txt)\n"
           "  --camera-file FILE     a camera file: OpenCV FileStorage (.yml/.yaml/.json/.xml,\n"
           "                         camera_matrix or K, distortion_coefficients or D), KITTI's\n"
           "                         calib.txt (P0) or text (`fx fy cx cy [width height]`, or\n"
           "                         three lines of three)\n"
           "  --distortion LIST      distortion coefficients k1,k2,p1,p2[,k3...]; the matches are\n"
           "                         undistorted before the estimators\n"
           "\n"
           "front end:\n" +
           essential_samples::frontEndHelp() + "\n" + essential_samples::estimatorHelp(true) +
           "\n"
           "output:\n"
           "  --opencv               also run cv::findEssentialMat + cv::recoverPose (--method,\n"
           "                         prob 0.999, --threshold-px, --max-iterations) as a reference\n"
           "                         row\n"
           "  --csv OUT.csv          write one row per (pair, solver, budget)\n"
           "  -h, --help             this help\n"
           "\n"
           "exit status: 0 done, 1 input error, 2 usage error\n";
}

// "1..60", "1,5,10", "1..5,10": sorted, without repeats; all >= 1.
std::vector<int> parseOffsets(const std::string& text)
{
    std::vector<int> offsets;
    for (const std::string& part : split(text, ',')) {
        const size_t dots = part.find("..");
        long long a, b;
        if (dots == std::string::npos) {
            if (!parseInt(part, a)) fail("--offsets: '" + part + "' is not a number", 2);
            b = a;
        } else if (!parseInt(part.substr(0, dots), a) || !parseInt(part.substr(dots + 2), b)) {
            fail("--offsets: '" + part + "' is not a range A..B", 2);
        }
        if (a < 1 || b < a || b > 100000)
            fail("--offsets: '" + part + "' must be offsets >= 1 (A..B with A <= B)", 2);
        for (long long n = a; n <= b; ++n)
            offsets.push_back(static_cast<int>(n));
    }
    std::sort(offsets.begin(), offsets.end());
    offsets.erase(std::unique(offsets.begin(), offsets.end()), offsets.end());
    if (offsets.empty()) fail("--offsets: no offset given", 2);
    return offsets;
}

struct Options
{
    std::string dir;
    std::vector<int> offsets = {1, 5, 10, 20, 40, 60};
    double thresholdDeg = 10.0;
    int framesStep = 1;
    std::string csv;
    bool opencv = false;
    std::string camera, cameraFile, distortion;
    std::string poses;
    essential_samples::PoseFormat poseFormat = essential_samples::PoseFormat::Auto;
    essential_samples::FrontEndOptions frontEnd;
    essential_samples::EstimatorOptions estimator;
};

Options parseOptions(int argc, char** argv)
{
    std::vector<essential_samples::OptionSpec> specs = essential_samples::estimatorOptionSpecs();
    for (const essential_samples::OptionSpec& spec : essential_samples::frontEndOptionSpecs())
        specs.push_back(spec);
    const std::vector<essential_samples::OptionSpec> own = {
        {"offsets", true, ""},     {"frames-step", true, ""},   {"poses", true, ""},
        {"pose-format", true, ""}, {"threshold-deg", true, ""}, {"camera", true, ""},
        {"camera-file", true, ""}, {"distortion", true, ""},    {"opencv", false, ""},
        {"csv", true, ""}};
    specs.insert(specs.end(), own.begin(), own.end());
    const essential_samples::CommandLine line =
        essential_samples::parseCommandLine("essential_sequence", argc, argv, specs);
    if (line.help) {
        std::cout << usage();
        std::exit(0);
    }

    Options options;
    for (const essential_samples::GivenOption& option : line.options) {
        const std::string& value = option.value;
        if (essential_samples::applyEstimatorOption(option, true, options.estimator)) continue;
        if (essential_samples::applyFrontEndOption(option, options.frontEnd)) continue;
        long long integer = 0;
        if (option.name == "offsets") {
            options.offsets = parseOffsets(value);
        } else if (option.name == "frames-step") {
            if (!parseInt(value, integer) || integer < 1 || integer > 1000000)
                fail("--frames-step must be a positive integer, not '" + value + "'", 2);
            options.framesStep = static_cast<int>(integer);
        } else if (option.name == "poses") {
            if (value.empty()) fail("--poses needs a file name", 2);
            options.poses = value;
        } else if (option.name == "pose-format") {
            if (!essential_samples::parsePoseFormat(value, options.poseFormat))
                fail("--pose-format must be auto, rail, tum or kitti, not '" + value + "'", 2);
        } else if (option.name == "threshold-deg") {
            if (!parseDouble(value, options.thresholdDeg) || !(options.thresholdDeg > 0))
                fail("--threshold-deg must be a positive angle, not '" + value + "'", 2);
        } else if (option.name == "camera") {
            options.camera = value;
        } else if (option.name == "camera-file") {
            options.cameraFile = value;
        } else if (option.name == "distortion") {
            options.distortion = value;
        } else if (option.name == "opencv") {
            options.opencv = true;
        } else if (option.name == "csv") {
            if (value.empty()) fail("--csv needs a file name", 2);
            options.csv = value;
        }
    }
    if (line.positional.size() != 1)
        fail("expected one sequence directory, got " + std::to_string(line.positional.size()) +
                 " (see --help)",
             2);
    options.dir = line.positional[0];
    essential_samples::checkEstimatorCombination(options.estimator);
    if (!options.camera.empty() && !options.cameraFile.empty())
        fail("give only one of --camera and --camera-file", 2);
    return options;
}

std::string budgetLabel(double budget)
{
    if (budget <= 0) return "none";
    std::ostringstream s;
    s << budget << " ms";
    return s.str();
}

// One estimate of one pair.
struct Row
{
    std::string solver;
    double budget = 0;
    int inliers = 0;
    double timeMs = 0;
    bool posed = false;
    double tErr = NAN, rErr = NAN;
    bool correct = false;
};

// Per (solver, budget): the results, for the summary.
struct Cell
{
    int total = 0, correct = 0, failed = 0;
    std::vector<double> times;
    double inlierRate = 0;
    std::map<int, std::pair<int, int>> bins; // motion bin -> (correct, total)
};

// Pixel-motion bins of the summary: [0, 5), [5, 10), [10, 20), [20, 40), [40, 80), [80, inf).
const double kBinEdges[] = {5, 10, 20, 40, 80};
const int kBins = 6;

int motionBin(double motion)
{
    int bin = 0;
    while (bin < kBins - 1 && motion >= kBinEdges[bin])
        ++bin;
    return bin;
}

std::string binLabel(int bin)
{
    const std::string low = bin == 0 ? "0" : std::to_string(int(kBinEdges[bin - 1]));
    return bin == kBins - 1 ? ">= " + low + " px"
                            : low + "-" + std::to_string(int(kBinEdges[bin])) + " px";
}

double median(std::vector<double> v)
{
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    const size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

int run(int argc, char** argv)
{
    const Options options = parseOptions(argc, argv);
    const essential_samples::SequenceFrames sequenceFrames =
        essential_samples::listFrames(options.dir);
    const std::map<int, std::string>& frames = sequenceFrames.paths;
    if (frames.empty())
        fail("no frames in '" + options.dir + "' (NNN.jpg, NNN.jpeg, NNN.png or rgb.txt)");

    essential_samples::Camera camera;
    if (!options.camera.empty()) {
        camera.K = essential_samples::parseCameraOption(options.camera);
    } else if (!options.cameraFile.empty()) {
        camera = essential_samples::readCameraFile(options.cameraFile);
    } else {
        const std::string path = options.dir + "/camera.txt";
        if (!essential_samples::fileExists(path))
            fail("missing camera: no '" + path +
                 "'; give --camera fx,fy,cx,cy or --camera-file FILE");
        camera = essential_samples::readCameraFile(path);
    }
    if (!options.distortion.empty()) {
        if (!camera.distortion.empty())
            fail("--distortion: the camera file has distortion coefficients already", 2);
        camera.distortion = essential_samples::parseDistortionOption(options.distortion);
    }
    const cv::Matx33d K = camera.K;

    std::string posesPath = options.poses;
    if (posesPath.empty())
        for (const char* name : {"/poses.txt", "/groundtruth.txt"})
            if (posesPath.empty() && essential_samples::fileExists(options.dir + name))
                posesPath = options.dir + name;
    essential_samples::PoseFormat poseFormat = options.poseFormat;
    std::map<int, Pose> poses;
    const bool haveTruth = !posesPath.empty();
    if (haveTruth) poses = essential_samples::readPoses(posesPath, poseFormat, sequenceFrames);

    std::string sequence = options.dir;
    while (sequence.size() > 1 && sequence.back() == '/')
        sequence.pop_back();
    sequence = sequence.substr(
        sequence.find_last_of('/') == std::string::npos ? 0 : sequence.find_last_of('/') + 1);

    // The pairs (t - N, t): t = first, first + K, ...; both frames present.
    const int first = frames.begin()->first;
    std::vector<std::pair<int, int>> pairs;
    for (const auto& frame : frames) {
        const int t = frame.first;
        if ((t - first) % options.framesStep != 0) continue;
        for (int n : options.offsets)
            if (frames.count(t - n)) pairs.emplace_back(t - n, t);
    }
    if (pairs.empty()) fail("no frame pair (t - N, t) with both frames in '" + options.dir + "'");

    std::unique_ptr<std::ofstream> csv;
    if (!options.csv.empty()) {
        csv.reset(new std::ofstream(options.csv));
        if (!*csv) fail("cannot write '" + options.csv + "'");
        *csv << "sequence,frame1,frame2,offset,matches,motion_px,true_inlier_rate,solver,budget_ms,"
                "inliers,inlier_rate,time_ms,t_err_deg,r_err_deg,correct\n";
    }

    const essential_samples::FrontEndParams& frontParams = options.frontEnd;
    const essential_samples::EstimatorOptions& estimator = options.estimator;
    std::map<int, essential_samples::Features> features;
    double detectMs = 0, matchMs = 0;
    int detections = 0;
    auto featuresOf = [&](int k) -> const essential_samples::Features& {
        auto it = features.find(k);
        if (it == features.end()) {
            const std::string& path = frames.at(k);
            const cv::Mat image = cv::imread(path, cv::IMREAD_GRAYSCALE);
            if (image.empty())
                fail("cannot read image '" + path + "' (missing, or not a format OpenCV decodes)");
            const auto start = std::chrono::steady_clock::now();
            it =
                features.emplace(k, essential_samples::detectAndDescribe(image, frontParams)).first;
            detectMs += elapsedMs(start);
            ++detections;
        }
        return it->second;
    };

    std::vector<std::pair<std::string, double>> configs;
    for (const std::string& solver : estimator.solvers)
        for (double budget : estimator.budgetsMs)
            configs.emplace_back(solver, budget);
    if (options.opencv) configs.emplace_back("opencv", 0.0);
    std::map<std::pair<std::string, double>, Cell> cells;

    int done = 0;
    for (const auto& pair : pairs) {
        const int i = pair.first, j = pair.second;
        std::fprintf(stderr, "\ressential_sequence: %s pair %d / %zu (frames %d, %d)   ",
                     sequence.c_str(), done + 1, pairs.size(), i, j);
        std::fflush(stderr);
        const auto& f1 = featuresOf(i);
        const auto& f2 = featuresOf(j);
        auto start = std::chrono::steady_clock::now();
        auto matches = essential_samples::matchFeatures(f1, f2, frontParams);
        matchMs += elapsedMs(start);
        if (!camera.distortion.empty()) {
            // The estimators and the ground truth then see the points of an ideal camera K.
            cv::undistortPoints(std::vector<cv::Point2f>(matches.points1), matches.points1, K,
                                camera.distortion, cv::noArray(), K);
            cv::undistortPoints(std::vector<cv::Point2f>(matches.points2), matches.points2, K,
                                camera.distortion, cv::noArray(), K);
        }
        const int n = static_cast<int>(matches.points1.size());

        // Ground truth: the relative pose, and which matches agree with it (Sampson < threshold).
        cv::Matx33d Rtrue = cv::Matx33d::eye();
        cv::Vec3d tTrue(0, 0, 0);
        const bool truth = haveTruth && poses.count(i) && poses.count(j);
        double trueInlierRate = NAN;
        double motionSum = 0;
        int motionCount = 0;
        if (truth) {
            const Pose& a = poses.at(i);
            const Pose& b = poses.at(j);
            Rtrue = essential_samples::relativeRotation(a, b);
            tTrue = essential_samples::relativeTranslation(a, b);
            const cv::Matx33d Kinv = K.inv();
            const cv::Matx33d F = Kinv.t() * essential_samples::crossMatrix(tTrue) * Rtrue * Kinv;
            int good = 0;
            for (int m = 0; m < n; ++m) {
                if (sampsonPx(F, matches.points1[m], matches.points2[m]) >= estimator.thresholdPx)
                    continue;
                ++good;
                motionSum += cv::norm(matches.points2[m] - matches.points1[m]);
                ++motionCount;
            }
            trueInlierRate = n > 0 ? double(good) / n : 0.0;
        }
        if (motionCount == 0) { // no ground truth (or no agreeing match): all matches
            for (int m = 0; m < n; ++m)
                motionSum += cv::norm(matches.points2[m] - matches.points1[m]);
            motionCount = n;
        }
        const double motion = motionCount > 0 ? motionSum / motionCount : 0.0;

        for (const auto& config : configs) {
            Row row;
            row.solver = config.first;
            row.budget = config.second;
            if (n >= 5 && row.solver == "opencv") {
                cv::Mat mask, R, t;
                start = std::chrono::steady_clock::now();
                const cv::Mat E = cv::findEssentialMat(
                    matches.points1, matches.points2, K, essential_samples::opencvMethod(estimator),
                    0.999, estimator.thresholdPx, estimator.maxIterations, mask);
                row.inliers = mask.empty() ? 0 : cv::countNonZero(mask);
                if (E.rows == 3 && E.cols == 3) {
                    cv::recoverPose(E, matches.points1, matches.points2, K, R, t, mask);
                    row.posed = true;
                    if (truth) {
                        row.tErr = directionAngleDeg(cv::Vec3d(t), tTrue, 180.0);
                        row.rErr = rotationAngleDeg(cv::Matx33d(R), Rtrue);
                    }
                }
                row.timeMs = elapsedMs(start);
            } else if (n >= 5) {
                const cv::essential::EssentialParams params =
                    essential_samples::estimatorParams(estimator, row.solver, row.budget);
                cv::essential::EssentialReport report;
                start = std::chrono::steady_clock::now();
                // PROSAC reads the order as quality: the matches best first.
                const std::vector<int> order =
                    estimator.sampler == cv::SAMPLING_PROSAC
                        ? essential_samples::orderByDistance(matches.distances)
                        : std::vector<int>();
                const cv::Mat E =
                    order.empty()
                        ? cv::essential::findEssentialMatIter(matches.points1, matches.points2, K,
                                                              params, cv::noArray(), &report)
                        : cv::essential::findEssentialMatIter(
                              essential_samples::permuted(matches.points1, order),
                              essential_samples::permuted(matches.points2, order), K, params,
                              cv::noArray(), &report);
                row.timeMs = elapsedMs(start);
                row.inliers = report.inliers;
                row.posed = !E.empty() && report.success && report.poseRecovered;
                if (row.posed && truth) {
                    row.tErr = directionAngleDeg(report.t, tTrue, 180.0);
                    row.rErr = rotationAngleDeg(report.R, Rtrue);
                }
            }
            row.correct = row.posed && truth && row.tErr < options.thresholdDeg;

            Cell& cell = cells[config];
            ++cell.total;
            cell.correct += row.correct;
            cell.failed += !row.posed;
            cell.times.push_back(row.timeMs);
            cell.inlierRate += n > 0 ? double(row.inliers) / n : 0.0;
            auto& bin = cell.bins[motionBin(motion)];
            bin.first += row.correct;
            ++bin.second;

            if (csv) {
                char line[512];
                std::snprintf(
                    line, sizeof(line), "%s,%d,%d,%d,%d,%.2f,%s,%s,%g,%d,%.4f,%.3f,%s,%s,%s\n",
                    sequence.c_str(), i, j, j - i, n, motion,
                    truth ? cv::format("%.4f", trueInlierRate).c_str() : "", row.solver.c_str(),
                    row.budget, row.inliers, n > 0 ? double(row.inliers) / n : 0.0, row.timeMs,
                    std::isnan(row.tErr) ? "" : cv::format("%.3f", row.tErr).c_str(),
                    std::isnan(row.rErr) ? "" : cv::format("%.4f", row.rErr).c_str(),
                    truth ? (row.correct ? "1" : "0") : "");
                *csv << line;
            }
        }
        ++done;
    }
    std::fprintf(stderr, "\ressential_sequence: %s: %zu pairs done%40s\n", sequence.c_str(),
                 pairs.size(), "");

    // Summary.
    const std::string truthNote =
        haveTruth
            ? "ground truth " + posesPath + " (" + essential_samples::poseFormatName(poseFormat) +
                  " format, " + std::to_string(poses.size()) + " frames with a pose)"
            : std::string("no ground truth");
    std::printf("sequence %s: %zu frames, %zu pairs (offsets %d..%d, frame step %d), %s\n",
                sequence.c_str(), frames.size(), pairs.size(), options.offsets.front(),
                options.offsets.back(), options.framesStep, truthNote.c_str());
    std::printf("front end (%s, matcher %s): %.1f ms per image (detection and description, %d "
                "images), %.1f ms per pair (matching)\n\n",
                essential_samples::descriptorName(frontParams.descriptor),
                essential_samples::matcherName(frontParams.matcher),
                detectMs / std::max(1, detections), detections, matchMs / pairs.size());
    std::printf("cv::essential: engine %s, method %s, sampler %s; without a time budget the search "
                "stops at confidence 0.999 or at its cap, the samples that fit in 3/4 of OpenCV's "
                "time for --max-iterations iterations (local and uniform samples in turn past the "
                "confidence cap); the plane check is on (docs/HARD_PAIRS.md)\n",
                essential_samples::engineName(estimator.engine),
                estimator.lmeds ? "lmeds" : "ransac",
                essential_samples::samplerName(estimator.sampler));
    if (haveTruth)
        std::printf("correct: translation direction within %g deg of the truth\n\n",
                    options.thresholdDeg);
    std::printf(
        "| sequence | solver | budget | reliability | median ms | mean inlier rate | no pose "
        "|\n|---|---|---|---|---|---|---|\n");
    for (const auto& config : configs) {
        const Cell& cell = cells[config];
        const std::string reliability =
            haveTruth ? cv::format("%.3f (%d of %d)", double(cell.correct) / cell.total,
                                   cell.correct, cell.total)
                      : std::string("n/a");
        std::printf("| %s | %s | %s | %s | %.2f | %.3f | %d |\n", sequence.c_str(),
                    config.first.c_str(), budgetLabel(config.second).c_str(), reliability.c_str(),
                    median(cell.times), cell.inlierRate / std::max(1, cell.total), cell.failed);
    }
    if (haveTruth) {
        std::printf(
            "\nreliability by mean pixel motion of the true inliers:\n\n| solver | budget |");
        for (int b = 0; b < kBins; ++b)
            std::printf(" %s |", binLabel(b).c_str());
        std::printf("\n|---|---|");
        for (int b = 0; b < kBins; ++b)
            std::printf("---|");
        std::printf("\n");
        for (const auto& config : configs) {
            const Cell& cell = cells[config];
            std::printf("| %s | %s |", config.first.c_str(), budgetLabel(config.second).c_str());
            for (int b = 0; b < kBins; ++b) {
                const auto it = cell.bins.find(b);
                if (it == cell.bins.end() || it->second.second == 0)
                    std::printf(" - |");
                else
                    std::printf(" %.2f (%d) |", double(it->second.first) / it->second.second,
                                it->second.second);
            }
            std::printf("\n");
        }
    }
    if (csv) {
        csv->close();
        if (!*csv) fail("cannot write '" + options.csv + "'");
    }
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    return essential_samples::runCli("essential_sequence", run, argc, argv);
}

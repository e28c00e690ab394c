// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// essential_sequence: relative poses of frame pairs (t - N, t) of an image sequence. The sample
// front end (features cached per frame) feeds cv::essential::findEssentialMatIter with each solver
// and time budget, optionally cv::findEssentialMat + cv::recoverPose as a reference; with ground
// truth poses a pair is correct when the estimated translation direction is within a threshold of
// the true one. Writes one CSV row per (pair, solver, budget) and a summary table on stdout.

#include "cli_common.hpp"
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
using essential_samples::isOption;
using essential_samples::optionValue;
using essential_samples::parseDouble;
using essential_samples::parseInt;
using essential_samples::parseSeed;
using essential_samples::parseSolverList;
using essential_samples::Pose;
using essential_samples::readNumberRows;
using essential_samples::rotationAngleDeg;
using essential_samples::sampsonPx;
using essential_samples::split;

const char* const kUsage =
    "usage: essential_sequence DIR [--offsets 1..60 | --offsets 1,5,10] [--solvers gn,nister,...]\n"
    "                          [--budgets-ms 10,1000] [--threshold-deg 10] [--frames-step K]\n"
    "                          [--csv OUT.csv] [--opencv] [--descriptor brief|orb|patch]\n"
    "                          [--threshold PX] [--max-iters N] [--seed S]\n"
    "                          [--sampler uniform|prosac|napsac|pnapsac]\n"
    "\n"
    "DIR holds the frames NNN.jpg (numbered from 0, three or more digits), camera.txt (the 3 x 3\n"
    "camera matrix, three lines of three numbers) and optionally poses.txt (one line per frame:\n"
    "`k r00 r01 .. r22 Cx Cy Cz`, world-to-camera rotation and camera centre, as rail-a).\n"
    "\n"
    "  --offsets LIST        frame offsets N: numbers and ranges A..B, comma separated\n"
    "                        (default 1,5,10,20,40,60)\n"
    "  --solvers LIST        cv::essential solvers or mixes, comma separated (default gn+nister)\n"
    "  --budgets-ms LIST     time budgets in ms, 0 for none (default 0). With a budget the search\n"
    "                        stops when the budget is spent or at confidence 1 - 1e-12 (no\n"
    "                        iteration cap); without, at confidence 0.999 or --max-iters\n"
    "  --threshold-deg D     a pair is correct when the translation direction is within D\n"
    "                        degrees of the truth (default 10; needs poses.txt)\n"
    "  --frames-step K       use every K-th frame t = first, first + K, ... as the later frame\n"
    "                        of the pairs (default 1: every frame)\n"
    "  --csv OUT.csv         write one row per (pair, solver, budget)\n"
    "  --opencv              also run cv::findEssentialMat + cv::recoverPose (RANSAC, prob\n"
    "                        0.999, --threshold, --max-iters) as a reference row\n"
    "  --descriptor D        front-end descriptor (default brief)\n"
    "  --threshold PX        inlier threshold on the Sampson distance, pixels (default 1)\n"
    "  --max-iters N         iteration cap without a budget (default 1000, as OpenCV)\n"
    "  --seed S              seed of the estimator (default: the module's)\n"
    "  --sampler S           how cv::essential draws samples: uniform (default, the module's\n"
    "                        own, with local samples past the confidence cap), prosac (the\n"
    "                        matches sorted by descriptor distance, best first), napsac or\n"
    "                        pnapsac. OpenCV gets the matches in their random order\n"
    "\n"
    "exit status: 0 done, 1 input error, 2 usage error\n";

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
    std::vector<std::string> solvers = {cv::essential::EssentialParams().solver};
    std::vector<double> budgets = {0.0};
    /** The module's default (uniform, with local samples past the confidence cap); PROSAC on the
    descriptor order is an option (docs/HARD_PAIRS.md: slower, and once wrong, on the best 20%). */
    cv::SamplingMethod sampler = cv::SAMPLING_UNIFORM;
    double thresholdDeg = 10.0;
    int framesStep = 1;
    std::string csv;
    bool opencv = false;
    essential_samples::Descriptor descriptor = essential_samples::FrontEndParams().descriptor;
    double threshold = cv::essential::EssentialParams().threshold;
    int maxIters = cv::essential::EssentialParams().maxIterations;
    std::uint64_t seed = cv::essential::EssentialParams().seed;
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
        if (arg == "--opencv") {
            options.opencv = true;
            continue;
        }
        if (!isOption(arg)) {
            positional.push_back(arg);
            continue;
        }
        const std::string value = optionValue(arg, i, argc, argv);

        long long integer = 0;
        if (arg == "--offsets") {
            options.offsets = parseOffsets(value);
        } else if (arg == "--solvers") {
            options.solvers = parseSolverList("--solvers", value);
        } else if (arg == "--budgets-ms") {
            options.budgets.clear();
            for (const std::string& part : split(value, ',')) {
                double budget;
                if (!parseDouble(part, budget) || budget < 0)
                    fail("--budgets-ms: '" + part + "' is not a budget in ms (>= 0)", 2);
                options.budgets.push_back(budget);
            }
        } else if (arg == "--threshold-deg") {
            if (!parseDouble(value, options.thresholdDeg) || !(options.thresholdDeg > 0))
                fail("--threshold-deg must be a positive angle, not '" + value + "'", 2);
        } else if (arg == "--frames-step") {
            if (!parseInt(value, integer) || integer < 1 || integer > 1000000)
                fail("--frames-step must be a positive integer, not '" + value + "'", 2);
            options.framesStep = static_cast<int>(integer);
        } else if (arg == "--csv") {
            options.csv = value;
        } else if (arg == "--descriptor") {
            if (!essential_samples::parseDescriptor(value, options.descriptor))
                fail("--descriptor must be brief, orb or patch, not '" + value + "'", 2);
        } else if (arg == "--threshold") {
            if (!parseDouble(value, options.threshold) || !(options.threshold > 0))
                fail("--threshold must be a positive number of pixels, not '" + value + "'", 2);
        } else if (arg == "--max-iters") {
            if (!parseInt(value, integer) || integer < 1 || integer > 100000000)
                fail("--max-iters must be a positive integer, not '" + value + "'", 2);
            options.maxIters = static_cast<int>(integer);
        } else if (arg == "--seed") {
            if (!parseSeed(value, options.seed))
                fail("--seed must be a non-negative integer, not '" + value + "'", 2);
        } else if (arg == "--sampler") {
            if (!essential_samples::parseSampler(value, options.sampler))
                fail("--sampler must be prosac, uniform, napsac or pnapsac, not '" + value + "'",
                     2);
        } else {
            fail("unknown option '" + arg + "' (see --help)", 2);
        }
    }
    if (positional.size() != 1)
        fail("expected one sequence directory, got " + std::to_string(positional.size()) +
                 " (see --help)",
             2);
    options.dir = positional[0];
    return options;
}

// Numbers of a file: every whitespace-separated token must be a finite number.
std::vector<std::vector<double>> readNumberLines(const std::string& path, const std::string& what)
{
    std::ifstream file(path);
    if (!file) fail("missing " + what + ": cannot open '" + path + "'");
    return readNumberRows(file, "malformed " + what + " '" + path + "'");
}

cv::Matx33d readCamera(const std::string& path)
{
    const auto rows = readNumberLines(path, "camera");
    if (rows.size() != 3 || rows[0].size() != 3 || rows[1].size() != 3 || rows[2].size() != 3)
        fail("malformed camera '" + path +
             "': expected a 3 x 3 matrix, three lines of three "
             "numbers");
    cv::Matx33d K;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            K(i, j) = rows[i][j];
    if (!(K(0, 0) > 0) || !(K(1, 1) > 0) || K(2, 0) != 0 || K(2, 1) != 0 || K(2, 2) != 1)
        fail("malformed camera '" + path + "': fx, fy must be positive and the last row 0 0 1");
    return K;
}

std::map<int, Pose> readPoses(const std::string& path)
{
    std::map<int, Pose> poses;
    for (const auto& row : readNumberLines(path, "poses")) {
        if (row.size() != 13 || row[0] < 0 || row[0] != std::floor(row[0]))
            fail("malformed poses '" + path + "': expected `k r00 .. r22 Cx Cy Cz` (13 numbers)");
        Pose pose;
        for (int i = 0; i < 9; ++i)
            pose.R.val[i] = row[1 + i];
        pose.C = cv::Vec3d(row[10], row[11], row[12]);
        poses[static_cast<int>(row[0])] = pose;
    }
    return poses;
}

// Frames DIR/NNN.jpg (digits only), by number.
std::map<int, std::string> listFrames(const std::string& dir)
{
    std::vector<cv::String> files;
    try {
        cv::glob(dir + "/*.jpg", files, false);
    } catch (const cv::Exception&) {
        fail("cannot open directory '" + dir + "'");
    }
    std::map<int, std::string> frames;
    for (const cv::String& file : files) {
        const size_t slash = file.find_last_of("/\\");
        const std::string name = file.substr(slash == std::string::npos ? 0 : slash + 1);
        const std::string stem = name.substr(0, name.size() - 4);
        if (stem.empty() || stem.size() > 9 ||
            stem.find_first_not_of("0123456789") != std::string::npos)
            continue;
        frames[std::stoi(stem)] = file;
    }
    return frames;
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
    const std::map<int, std::string> frames = listFrames(options.dir);
    if (frames.empty()) fail("no frames NNN.jpg in '" + options.dir + "'");
    const cv::Matx33d K = readCamera(options.dir + "/camera.txt");
    std::map<int, Pose> poses;
    const bool haveTruth = static_cast<bool>(std::ifstream(options.dir + "/poses.txt"));
    if (haveTruth) poses = readPoses(options.dir + "/poses.txt");

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

    essential_samples::FrontEndParams frontParams;
    frontParams.descriptor = options.descriptor;
    std::map<int, essential_samples::Features> features;
    double detectMs = 0, matchMs = 0;
    int detections = 0;
    auto featuresOf = [&](int k) -> const essential_samples::Features& {
        auto it = features.find(k);
        if (it == features.end()) {
            const std::string& path = frames.at(k);
            const cv::Mat image = cv::imread(path, cv::IMREAD_GRAYSCALE);
            if (image.empty()) fail("cannot read image '" + path + "'");
            const auto start = std::chrono::steady_clock::now();
            it =
                features.emplace(k, essential_samples::detectAndDescribe(image, frontParams)).first;
            detectMs += elapsedMs(start);
            ++detections;
        }
        return it->second;
    };

    std::vector<std::pair<std::string, double>> configs;
    for (const std::string& solver : options.solvers)
        for (double budget : options.budgets)
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
        const auto matches = essential_samples::matchFeatures(f1, f2, frontParams);
        matchMs += elapsedMs(start);
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
                if (sampsonPx(F, matches.points1[m], matches.points2[m]) >= options.threshold)
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
                const cv::Mat E =
                    cv::findEssentialMat(matches.points1, matches.points2, K, cv::RANSAC, 0.999,
                                         options.threshold, options.maxIters, mask);
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
                cv::essential::EssentialParams params;
                params.solver = row.solver;
                params.threshold = options.threshold;
                params.maxIterations = options.maxIters;
                params.seed = options.seed;
                params.sampler = options.sampler;
                if (row.budget > 0) {
                    // The budget, not the confidence or the cap, ends the search.
                    params.timeBudgetMs = row.budget;
                    params.confidence = 1.0 - 1e-12;
                    params.maxIterations = 100000000;
                }
                cv::essential::EssentialReport report;
                start = std::chrono::steady_clock::now();
                // PROSAC reads the order as quality: the matches best first.
                const std::vector<int> order =
                    options.sampler == cv::SAMPLING_PROSAC
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
    std::printf("sequence %s: %zu frames, %zu pairs (offsets %d..%d, frame step %d), %s\n",
                sequence.c_str(), frames.size(), pairs.size(), options.offsets.front(),
                options.offsets.back(), options.framesStep,
                haveTruth ? "ground truth poses.txt" : "no ground truth");
    std::printf("front end (%s): %.1f ms per image (detection and description, %d images), "
                "%.1f ms per pair (matching)\n\n",
                essential_samples::descriptorName(options.descriptor),
                detectMs / std::max(1, detections), detections, matchMs / pairs.size());
    std::printf("cv::essential: sampler %s; without a time budget the search stops at confidence "
                "0.999 or at its cap, the samples that fit in 3/4 of OpenCV's time for "
                "--max-iters iterations (local and uniform samples in turn past the confidence "
                "cap); the plane check is on (docs/HARD_PAIRS.md)\n",
                essential_samples::samplerName(options.sampler));
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

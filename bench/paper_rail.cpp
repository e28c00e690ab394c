// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// The paper's real-data experiment ("Real data", results figure) on rail sequences with known
// camera poses: for frame pairs (i, i + N) the sample front end matches every corner of frame
// i + N to its nearest corner of frame i once per pair (cached on disk with --cache); match-set
// variants are drawn from those matches (the paper's best 20% by descriptor distance, or a random
// subset of the same size, which keeps the unfiltered matches' lower inlier rate); then every
// solver runs in the paper's preemptive RANSAC (ENGINE_PREEMPTIVE) at each time budget, and
// cv::findEssentialMat + cv::recoverPose runs once as a reference. A result is correct when its
// translation direction is within 10 degrees of the true one (the paper's criterion, no rotation
// threshold). One CSV row per (pair, variant, solver, budget); scripts/plot_rail.py draws the
// figures from it.
//
//   essential_paper_rail --data DIR --csv OUT.csv [options]   (see kUsage)

#include "bench_common.hpp"
#include "bench_options.hpp"
#include "cli_common.hpp"
#include "frontend/frontend.hpp"
#include "frontend/sequence_io.hpp"
#include "match_cache.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/essential.hpp>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include <time.h>

namespace {

using essential_bench::loadMatches;
using essential_bench::saveMatches;
using essential_samples::elapsedMs;
using essential_samples::fail;
using essential_samples::parseDouble;
using essential_samples::parseInt;
using essential_samples::parseSolverList;
using essential_samples::Pose;
using essential_samples::split;

const char* const kUsage =
    "usage: essential_paper_rail --data DIR --csv OUT.csv [--sequences horizontal,optic]\n"
    "           [--offsets 1..60 | 1,2,5] [--pairs-per-offset P] [--variants best20,random20]\n"
    "           [--solvers gn,lm,nister,robust,gn+nister] [--budgets-ms 2,3,5,10,30,100,1000]\n"
    "           [--no-opencv] [--cache DIR] [--threshold-deg 10] [--threshold PX] [--seed S]\n"
    "\n"
    "DIR holds one folder per sequence with frames NNN.jpg, camera.txt (3 x 3 K) and poses.txt\n"
    "(`k r00 .. r22 Cx Cy Cz`: frame number, world-to-camera rotation, camera centre), as rail-a.\n"
    "\n"
    "  --offsets LIST          frame offsets N (numbers and ranges A..B; default\n"
    "                          1,2,3,4,5,6,8,10,12,15,20,25,30,40,50,60)\n"
    "  --pairs-per-offset P    pairs (i, i + N) per offset, first frames spread evenly over the\n"
    "                          sequence (default 4; all pairs when fewer exist)\n"
    "  --variants LIST         match sets: bestF (the best F% of the matches by descriptor\n"
    "                          distance, the front end's rule) or randomF (F% of the matches "
    "drawn\n"
    "                          at random: the unfiltered matches' inlier rate); default "
    "best20,random20\n"
    "  --solvers LIST          solvers or mixes, run in ENGINE_PREEMPTIVE (default\n"
    "                          gn,lm,nister,robust,gn+nister)\n"
    "  --budgets-ms LIST       time budgets per pair in ms (default 2,3,5,10,30,100,1000)\n"
    "  --no-opencv             skip the cv::findEssentialMat + cv::recoverPose reference\n"
    "  --cache DIR             keep each pair's matches in DIR and reuse them on the next run\n"
    "  --threshold-deg D       correct: translation direction within D degrees (default 10)\n"
    "  --threshold PX          inlier threshold, Sampson distance in pixels (default 1); also\n"
    "                          the distance to the true E below which a match counts as an inlier\n"
    "  --seed S                base seed of the estimators and of the random variants (default "
    "1)\n";

struct Options
{
    std::string data, csv, cache;
    std::vector<std::string> sequences = {"horizontal", "optic"};
    std::vector<int> offsets = {1, 2, 3, 4, 5, 6, 8, 10, 12, 15, 20, 25, 30, 40, 50, 60};
    int pairsPerOffset = 4;
    std::vector<std::string> variants = {"best20", "random20"};
    std::vector<std::string> solvers = {"gn", "lm", "nister", "robust", "gn+nister"};
    std::vector<double> budgets = {2, 3, 5, 10, 30, 100, 1000};
    bool opencv = true;
    double thresholdDeg = 10, threshold = 1;
    long long seed = 1;
};

std::vector<int> parseOffsets(const std::string& text)
{
    std::vector<int> offsets;
    for (const std::string& part : split(text, ',')) {
        const size_t dots = part.find("..");
        long long a = 0, b = 0;
        const bool ok = dots == std::string::npos ? parseInt(part, a) && parseInt(part, b)
                                                  : parseInt(part.substr(0, dots), a) &&
                                                        parseInt(part.substr(dots + 2), b);
        if (!ok || a < 1 || b < a || b > 100000) fail("--offsets: bad offset '" + part + "'", 2);
        for (long long n = a; n <= b; ++n)
            offsets.push_back(static_cast<int>(n));
    }
    std::sort(offsets.begin(), offsets.end());
    offsets.erase(std::unique(offsets.begin(), offsets.end()), offsets.end());
    return offsets;
}

// "best20" -> (true, 0.20); "random20" -> (false, 0.20); fails otherwise.
std::pair<bool, double> parseVariant(const std::string& name)
{
    const bool best = name.rfind("best", 0) == 0;
    const bool random = name.rfind("random", 0) == 0;
    double percent = 0;
    if ((!best && !random) || !parseDouble(name.substr(best ? 4 : 6), percent) || !(percent > 0) ||
        percent > 100)
        fail("--variants: '" + name + "' is not bestF or randomF with F in (0, 100]", 2);
    return {best, percent / 100.0};
}

Options parseOptions(int argc, char** argv)
{
    Options o;
    essential_bench::Options opts("essential_paper_rail", kUsage);
    long long integer = 0;
    bool noOpencv = false;
    opts.flag("no-opencv", noOpencv);
    opts.add("data", o.data);
    opts.add("csv", o.csv);
    opts.add("cache", o.cache);
    opts.add("sequences", o.sequences);
    opts.custom("offsets", "", [&](const std::string& value) { o.offsets = parseOffsets(value); });
    opts.custom("pairs-per-offset", "", [&](const std::string& value) {
        if (!parseInt(value, integer) || integer < 1 || integer > 100000)
            fail("--pairs-per-offset must be a positive integer", 2);
        o.pairsPerOffset = static_cast<int>(integer);
    });
    opts.custom("variants", "", [&](const std::string& value) {
        o.variants = split(value, ',');
        for (const std::string& v : o.variants)
            parseVariant(v);
    });
    opts.custom("solvers", "",
                [&](const std::string& value) { o.solvers = parseSolverList("--solvers", value); });
    opts.custom("budgets-ms", "", [&](const std::string& value) {
        o.budgets.clear();
        for (const std::string& part : split(value, ',')) {
            double b = 0;
            if (!parseDouble(part, b) || !(b > 0))
                fail("--budgets-ms: '" + part + "' is not a positive budget in ms", 2);
            o.budgets.push_back(b);
        }
    });
    opts.custom("threshold-deg", "", [&](const std::string& value) {
        if (!parseDouble(value, o.thresholdDeg) || !(o.thresholdDeg > 0))
            fail("--threshold-deg must be a positive angle", 2);
    });
    opts.custom("threshold", "", [&](const std::string& value) {
        if (!parseDouble(value, o.threshold) || !(o.threshold > 0))
            fail("--threshold must be a positive number of pixels", 2);
    });
    opts.custom("seed", "", [&](const std::string& value) {
        if (!parseInt(value, o.seed) || o.seed < 0) fail("--seed must be >= 0", 2);
    });
    opts.parse(argc, argv);
    if (noOpencv) o.opencv = false;
    if (o.data.empty() || o.csv.empty()) fail("--data and --csv are required (see --help)", 2);
    return o;
}

// poses.txt by frame number (the bundled two-frame copy holds frames 0 and 10 only).
std::map<int, Pose> readPoses(const std::string& path)
{
    std::ifstream file(path);
    if (!file) fail("cannot open '" + path + "'");
    std::map<int, Pose> poses;
    for (const auto& row : essential_samples::readNumberRows(file, "malformed '" + path + "'")) {
        if (row.size() != 13) fail("malformed '" + path + "': expected 13 numbers per line");
        Pose p;
        std::copy(row.begin() + 1, row.begin() + 10, p.R.val);
        p.C = cv::Vec3d(row[10], row[11], row[12]);
        poses[static_cast<int>(row[0])] = p;
    }
    return poses;
}

cv::Matx33d readCamera(const std::string& path)
{
    std::ifstream file(path);
    if (!file) fail("cannot open '" + path + "'");
    const auto rows = essential_samples::readNumberRows(file, "malformed '" + path + "'");
    cv::Matx33d K;
    if (rows.size() != 3) fail("malformed '" + path + "': expected 3 x 3");
    for (int r = 0; r < 3; ++r) {
        if (rows[r].size() != 3) fail("malformed '" + path + "': expected 3 x 3");
        for (int c = 0; c < 3; ++c)
            K(r, c) = rows[r][c];
    }
    return K;
}

// The pairs (i, i + N): per offset, up to `perOffset` first frames spread evenly over those whose
// partner exists.
std::vector<std::pair<int, int>> choosePairs(const std::map<int, Pose>& frames,
                                             const std::vector<int>& offsets, int perOffset)
{
    std::vector<std::pair<int, int>> pairs;
    for (int n : offsets) {
        std::vector<int> firsts;
        for (const auto& f : frames)
            if (frames.count(f.first + n)) firsts.push_back(f.first);
        const int c = static_cast<int>(firsts.size());
        if (c == 0) continue;
        if (c <= perOffset) {
            for (int i : firsts)
                pairs.emplace_back(i, i + n);
            continue;
        }
        for (int k = 0; k < perOffset; ++k) {
            const int idx = perOffset == 1 ? c / 2 : cvRound(double(k) * (c - 1) / (perOffset - 1));
            pairs.emplace_back(firsts[idx], firsts[idx] + n);
        }
    }
    return pairs;
}

// The indices of a variant's matches among all of a pair's matches, in random order: the best
// fraction by distance (ties in matchFeatures' order, as the front end's own selection) or a
// random subset of the same size.
std::vector<int> selectVariant(const essential_samples::Matches& all, bool best, double fraction,
                               std::uint64_t seed)
{
    const int n = static_cast<int>(all.points1.size());
    std::vector<int> order(static_cast<size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    cv::RNG rng(seed);
    if (best) {
        std::stable_sort(order.begin(), order.end(),
                         [&](int a, int b) { return all.distances[a] < all.distances[b]; });
    } else {
        for (int i = n - 1; i > 0; --i)
            std::swap(order[i], order[rng.uniform(0, i + 1)]);
    }
    const int keep = std::min(n, static_cast<int>(std::ceil(fraction * n - 1e-9)));
    order.resize(static_cast<size_t>(keep));
    for (int i = keep - 1; i > 0; --i)
        std::swap(order[i], order[rng.uniform(0, i + 1)]);
    return order;
}

double directionErrorDeg(const cv::Vec3d& t, const cv::Vec3d& truth)
{
    return essential_samples::directionAngleDeg(t, truth, 180.0);
}

int run(int argc, char** argv)
{
    const Options o = parseOptions(argc, argv);
    std::ofstream csv(o.csv);
    if (!csv) fail("cannot write '" + o.csv + "'");
    csv << "sequence,variant,frame1,frame2,offset,matches,motion_px,true_inlier_rate,solver,"
           "budget_ms,time_ms,cpu_ms,hypotheses,inliers,inlier_rate,t_err_deg,r_err_deg,correct\n";

    essential_samples::FrontEndParams frontParams;
    frontParams.keepFraction = 1.0; // every match; the variants select from them
    const auto runStart = std::chrono::steady_clock::now();
    double matchMs = 0, estimateMs = 0;
    int matched = 0, cached = 0;

    for (const std::string& sequence : o.sequences) {
        const std::string dir = o.data + "/" + sequence;
        const cv::Matx33d K = readCamera(dir + "/camera.txt");
        const std::map<int, Pose> poses = readPoses(dir + "/poses.txt");
        const auto pairs = choosePairs(poses, o.offsets, o.pairsPerOffset);
        if (pairs.empty()) fail("no frame pair with the given offsets in '" + dir + "'");
        std::map<int, essential_samples::Features> features;
        auto featuresOf = [&](int k) -> const essential_samples::Features& {
            auto it = features.find(k);
            if (it == features.end()) {
                const cv::Mat image =
                    cv::imread(essential_samples::framePath(dir, k), cv::IMREAD_GRAYSCALE);
                if (image.empty())
                    fail("cannot read '" + essential_samples::framePath(dir, k) + "'");
                it = features.emplace(k, essential_samples::detectAndDescribe(image, frontParams))
                         .first;
            }
            return it->second;
        };

        int done = 0;
        for (const auto& pair : pairs) {
            const int i = pair.first, j = pair.second;
            std::fprintf(stderr, "\ressential_paper_rail: %s pair %d / %zu (frames %d, %d)   ",
                         sequence.c_str(), ++done, pairs.size(), i, j);
            std::fflush(stderr);

            // All matches of the pair: from the cache, or matched once and cached.
            essential_samples::Matches all;
            const std::string cachePath =
                o.cache.empty()
                    ? std::string()
                    : cv::format("%s/%s_%03d_%03d.bin", o.cache.c_str(), sequence.c_str(), i, j);
            if (!cachePath.empty() && loadMatches(cachePath, all)) {
                ++cached;
            } else {
                const auto start = std::chrono::steady_clock::now();
                all = essential_samples::matchFeatures(featuresOf(i), featuresOf(j), frontParams);
                matchMs += elapsedMs(start);
                ++matched;
                if (!cachePath.empty()) saveMatches(cachePath, all);
            }

            // The truth: which matches lie within the threshold of the true E, and the pair's
            // average pixel motion (mean displacement of those matches among all matches).
            const Pose& a = poses.at(i);
            const Pose& b = poses.at(j);
            const cv::Matx33d Rtrue = essential_samples::relativeRotation(a, b);
            const cv::Vec3d tTrue = essential_samples::relativeTranslation(a, b);
            const cv::Matx33d F = essential_samples::trueFundamental(K, a, b);
            const int total = static_cast<int>(all.points1.size());
            std::vector<char> isInlier(static_cast<size_t>(total));
            double motionSum = 0;
            int inlierCount = 0;
            for (int m = 0; m < total; ++m) {
                isInlier[m] =
                    essential_samples::sampsonPx(F, all.points1[m], all.points2[m]) < o.threshold;
                if (!isInlier[m]) continue;
                motionSum += cv::norm(all.points2[m] - all.points1[m]);
                ++inlierCount;
            }
            const double motion = inlierCount ? motionSum / inlierCount : 0.0;

            for (size_t v = 0; v < o.variants.size(); ++v) {
                const auto variant = parseVariant(o.variants[v]);
                const std::uint64_t pairSeed =
                    static_cast<std::uint64_t>(o.seed) * 1000003ULL + i * 1009ULL + j * 17ULL + v;
                const std::vector<int> chosen =
                    selectVariant(all, variant.first, variant.second, pairSeed);
                std::vector<cv::Point2f> p1, p2;
                int good = 0;
                for (int m : chosen) {
                    p1.push_back(all.points1[m]);
                    p2.push_back(all.points2[m]);
                    good += isInlier[m];
                }
                const int n = static_cast<int>(p1.size());
                const double trueRate = n ? double(good) / n : 0.0;

                auto writeRow = [&](const std::string& solver, double budget, double ms,
                                    double cpuMs, int hypotheses, int inliers, bool posed,
                                    const cv::Vec3d& t, const cv::Matx33d& R) {
                    const double tErr = posed ? directionErrorDeg(t, tTrue) : NAN;
                    const double rErr = posed ? essential_samples::rotationAngleDeg(R, Rtrue) : NAN;
                    const bool correct = posed && tErr < o.thresholdDeg;
                    csv << cv::format(
                        "%s,%s,%d,%d,%d,%d,%.2f,%.4f,%s,%g,%.3f,%.3f,%d,%d,%.4f,%s,%s,%d\n",
                        sequence.c_str(), o.variants[v].c_str(), i, j, j - i, n, motion, trueRate,
                        solver.c_str(), budget, ms, cpuMs, hypotheses, inliers,
                        n ? double(inliers) / n : 0.0,
                        posed ? cv::format("%.3f", tErr).c_str() : "",
                        posed ? cv::format("%.4f", rErr).c_str() : "", correct ? 1 : 0);
                };

                for (const std::string& solver : o.solvers) {
                    for (double budget : o.budgets) {
                        cv::essential::EssentialParams params;
                        params.solver = solver;
                        params.engine = cv::essential::ENGINE_PREEMPTIVE;
                        params.timeBudgetMs = budget;
                        params.threshold = o.threshold;
                        params.seed = pairSeed;
                        cv::essential::EssentialReport report;
                        bool posed = false;
                        const double cpuStart = essential_bench::threadCpuMs();
                        const auto start = std::chrono::steady_clock::now();
                        if (n >= 5) {
                            const cv::Mat E = cv::essential::findEssentialMatIter(
                                p1, p2, K, params, cv::noArray(), &report);
                            posed = !E.empty() && report.success && report.poseRecovered;
                        }
                        const double ms = elapsedMs(start);
                        const double cpuMs = essential_bench::threadCpuMs() - cpuStart;
                        estimateMs += ms;
                        writeRow(solver, budget, ms, cpuMs, report.hypothesesGenerated,
                                 report.inliers, posed, report.t, report.R);
                    }
                }
                if (o.opencv) {
                    // OpenCV's defaults (RANSAC, prob 0.999, 1000 iterations) and its pose.
                    cv::Mat mask, R, t;
                    bool posed = false;
                    int inliers = 0;
                    const double cpuStart = essential_bench::threadCpuMs();
                    const auto start = std::chrono::steady_clock::now();
                    if (n >= 5) {
                        const cv::Mat E = cv::findEssentialMat(p1, p2, K, cv::RANSAC, 0.999,
                                                               o.threshold, 1000, mask);
                        if (E.rows == 3 && E.cols == 3) {
                            cv::recoverPose(E, p1, p2, K, R, t, mask);
                            posed = true;
                        }
                        inliers = mask.empty() ? 0 : cv::countNonZero(mask);
                    }
                    const double ms = elapsedMs(start);
                    const double cpuMs = essential_bench::threadCpuMs() - cpuStart;
                    estimateMs += ms;
                    writeRow("opencv", 0, ms, cpuMs, 0, inliers, posed,
                             posed ? cv::Vec3d(t) : cv::Vec3d(),
                             posed ? cv::Matx33d(R) : cv::Matx33d::eye());
                }
            }
            csv.flush();
        }
        std::fprintf(stderr, "\n");
    }
    csv.close();
    if (!csv) fail("cannot write '" + o.csv + "'");
    std::printf("essential_paper_rail: %d pairs matched (%.0f ms per pair), %d from the cache; "
                "estimation %.1f s; total %.1f s; wrote %s\n",
                matched, matched ? matchMs / matched : 0.0, cached, estimateMs / 1000,
                elapsedMs(runStart) / 1000, o.csv.c_str());
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    return essential_samples::runCli("essential_paper_rail", run, argc, argv);
}

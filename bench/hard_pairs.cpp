// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// Right-rates on HARD pairs: few inliers (5-25%), a dominant plane, repeated structure, clustered
// inliers, and real pairs matched without filtering. For every problem and every shuffle of its
// matches, each method runs once (all methods interleaved, so that a drift of the machine's speed
// is shared): OpenCV's cv::findEssentialMat with RANSAC and three USAC flags, the module's drop-in
// overload, and the module's own overload under named EssentialParams configurations. An estimate
// is right when its rotation is within 5 degrees and its translation direction within 10 degrees
// of the truth; a failure (empty E, exception) is wrong. Public API only.
//
//   essential_hard_pairs [--sets LIST] [--methods LIST] [--csv FILE] [--md FILE] ...  (kUsage)

#include "bench_common.hpp"
#include "bench_options.hpp"
#include "cli_common.hpp"
#include "frontend/frontend.hpp"
#include "frontend/sequence_io.hpp"
#include "hard_scenes.hpp"
#include "match_cache.hpp"
#include "methods.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/essential.hpp>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <time.h>

namespace {

using essential_samples::fail;
using essential_samples::parseDouble;
using essential_samples::parseInt;
using essential_samples::split;

const char* const kUsage =
    "usage: essential_hard_pairs [--sets LIST] [--methods LIST] [--csv FILE] [--md FILE]\n"
    "           [--ratios 0.05,0.10,0.15,0.25] [--problems 10] [--points 1000] [--shuffles 5]\n"
    "           [--offsets 20,30,40,50,60] [--pairs-per-offset 2] [--data DIR] [--cache DIR]\n"
    "           [--seed S]\n"
    "\n"
    "  --sets LIST       synth-plane, synth-repeated, synth-clustered (synthetic, --problems per\n"
    "                    inlier ratio of --ratios, --points matches), rail-random20, rail-all\n"
    "                    (DIR/rail-a horizontal and optic, pairs (i, i + N) for N in --offsets,\n"
    "                    a random 20% of all matches or all of them), aloe-orb20, aloe-orb30\n"
    "                    (DIR/pairs/aloeL.jpg, aloeR.jpg with ORB descriptors, the best 20% or\n"
    "                    30% of the matches); default all; a set whose data are missing is "
    "skipped\n"
    "                    Easy sets, to check that nothing gets slower there (not in the default):\n"
    "                    synth-protocol (the paper's synthetic protocol, 500 points, 90% and 50%\n"
    "                    inliers, --problems each) and rail-best20 (the rail pairs' best 20% of\n"
    "                    the matches by descriptor distance, the front end's default)\n"
    "  --methods LIST    cv_ransac, usac_magsac, usac_accurate, usac_prosac "
    "(cv::findEssentialMat,\n"
    "                    prob 0.999, threshold 1 px, 1000 iterations), dropin (the module's\n"
    "                    drop-in overload with cv_ransac's arguments), ours[:k=v;k=v...] (the\n"
    "                    module's own overload; keys: solver, sampler (uniform|prosac|napsac|\n"
    "                    pnapsac), maxIters, lo, loSample, sprt (0|1), threshold, budgetMs,\n"
    "                    budget, plane, front, local, refine); LABEL=METHOD\n"
    "                    names a column; default cv_ransac,usac_magsac,usac_accurate,dropin,\n"
    "                    prosac=ours:sampler=prosac. PROSAC methods get the matches sorted by\n"
    "                    descriptor distance, best first\n"
    "  --shuffles S      runs per problem, each with its own order of the matches and seed\n"
    "  --data DIR        folder with rail-a/ and pairs/ (default ../shared/data)\n"
    "  --cache DIR       match cache of the real pairs (default build/hard_match_cache)\n"
    "  --csv FILE        one row per problem x shuffle x method\n"
    "  --md FILE         the summary table (also printed on stdout)\n";

// ---------------------------------------------------------------------------------------------
// Methods

using essential_bench::Method;
using essential_bench::parseMethod;

// ---------------------------------------------------------------------------------------------
// Problems

struct Problem
{
    std::string set, name;
    double ratioOrOffset = 0; // synthetic: inlier ratio; real: frame offset (aloe: 0)
    std::vector<cv::Point2f> p1, p2;
    std::vector<float> distance;
    cv::Matx33d K;
    cv::Matx33d R; // X2 = R X1 + s t
    cv::Vec3d t;   // unit
    double trueInlierRate = 0;
};

struct Options
{
    std::vector<std::string> sets = {"synth-plane",   "synth-repeated", "synth-clustered",
                                     "rail-random20", "rail-all",       "aloe-orb20",
                                     "aloe-orb30"};
    std::vector<Method> methods;
    std::vector<double> ratios = {0.05, 0.10, 0.15, 0.25};
    std::vector<int> offsets = {20, 30, 40, 50, 60};
    int problems = 10, points = 1000, shuffles = 5, pairsPerOffset = 2;
    std::string data = "../shared/data", cache = "build/hard_match_cache", csv, md;
    std::uint64_t seed = 1;
    std::string commandLine;
};

/** Fraction of the matches within 1 px (Sampson) of the true E with camera K. */
double trueInlierRate(const Problem& p)
{
    const cv::Matx33d Kinv = p.K.inv();
    const cv::Matx33d F = Kinv.t() * essential_test::skewMatrix(p.t) * p.R * Kinv;
    int good = 0;
    for (size_t i = 0; i < p.p1.size(); ++i)
        good += essential_test::sampsonPx(F, p.p1[i], p.p2[i]) < 1.0;
    return p.p1.empty() ? 0.0 : double(good) / p.p1.size();
}

/** synth-protocol: the paper's synthetic protocol (test/synthetic_scene.hpp) at 90% and 50%
inliers, the easy end, where the hard-data levers must cost nothing. No descriptor distances. */
std::vector<Problem> protocolProblems(const Options& o)
{
    std::vector<Problem> out;
    for (double ratio : {0.9, 0.5}) {
        for (int k = 0; k < o.problems; ++k) {
            essential_test::SceneConfig cfg;
            cfg.inlierRatio = ratio;
            const essential_test::SyntheticScene s = essential_test::makeScene(
                cfg, o.seed * 1000003ULL + 700000ULL +
                         static_cast<std::uint64_t>(ratio * 100) * 1000ULL +
                         static_cast<std::uint64_t>(k));
            Problem p;
            p.set = "synth-protocol";
            p.name = cv::format("r%.2f-%d", ratio, k);
            p.ratioOrOffset = ratio;
            for (size_t i = 0; i < s.px1.size(); ++i) {
                p.p1.emplace_back(s.px1[i]);
                p.p2.emplace_back(s.px2[i]);
            }
            p.distance.assign(s.px1.size(), 0.0f);
            p.K = s.K;
            p.R = s.R;
            p.t = s.t;
            p.trueInlierRate = double(s.numInliers) / s.px1.size();
            out.push_back(std::move(p));
        }
    }
    return out;
}

std::vector<Problem> syntheticProblems(const std::string& set, const Options& o)
{
    std::vector<Problem> out;
    const int kind = set == "synth-plane" ? 0 : set == "synth-repeated" ? 1 : 2;
    for (size_t r = 0; r < o.ratios.size(); ++r) {
        for (int k = 0; k < o.problems; ++k) {
            const std::uint64_t seed = o.seed * 1000003ULL + kind * 100000ULL + r * 1000ULL + k;
            essential_test::HardScene s;
            if (kind == 0) {
                essential_test::DominantPlaneConfig cfg;
                cfg.numPoints = o.points;
                cfg.inlierRatio = o.ratios[r];
                s = essential_test::makeDominantPlane(cfg, seed);
            } else if (kind == 1) {
                essential_test::RepeatedStructureConfig cfg;
                cfg.numPoints = o.points;
                cfg.inlierRatio = o.ratios[r];
                // Look-alikes in 4 groups totalling 60% of the inliers' count: each group is a
                // strong false structure (a quarter of the truth's support, planar, compact), yet
                // the true E keeps the largest support, so the set measures the search and not an
                // impossible tie-break (with half of all outliers shifted, one group outnumbers
                // the inliers below 14% inliers).
                cfg.numGroups = 4;
                cfg.shiftedFraction =
                    std::min(0.5, 0.6 * cfg.inlierRatio / std::max(1e-9, 1.0 - cfg.inlierRatio));
                s = essential_test::makeRepeatedStructure(cfg, seed);
            } else {
                essential_test::ClusteredInliersConfig cfg;
                cfg.numPoints = o.points;
                cfg.inlierRatio = o.ratios[r];
                s = essential_test::makeClusteredInliers(cfg, seed);
            }
            Problem p;
            p.set = set;
            p.name = cv::format("r%.2f-%d", o.ratios[r], k);
            p.ratioOrOffset = o.ratios[r];
            for (size_t i = 0; i < s.px1.size(); ++i) {
                p.p1.emplace_back(s.px1[i]);
                p.p2.emplace_back(s.px2[i]);
            }
            p.distance = s.distance;
            p.K = s.K;
            p.R = s.R;
            p.t = s.t;
            p.trueInlierRate = double(s.numInliers) / s.px1.size();
            out.push_back(std::move(p));
        }
    }
    return out;
}

bool fileExists(const std::string& path)
{
    std::error_code error;
    return std::filesystem::exists(path, error);
}

/** All matches of a pair: from the cache, or matched (features computed by `features`) and
cached. */
template <class Features>
essential_samples::Matches pairMatches(const std::string& cachePath, Features features,
                                       const essential_samples::FrontEndParams& params)
{
    essential_samples::Matches all;
    if (!cachePath.empty() && essential_bench::loadMatches(cachePath, all)) return all;
    const auto f = features();
    all = essential_samples::matchFeatures(f.first, f.second, params);
    if (!cachePath.empty()) essential_bench::saveMatches(cachePath, all);
    return all;
}

/** `base` (pose, camera, name) with the first 20% of the matches of `m` in `order` (rounded up). */
Problem railSubset(const Problem& base, const char* set, const essential_samples::Matches& m,
                   std::vector<int> order)
{
    order.resize(static_cast<size_t>(std::ceil(0.2 * order.size())));
    Problem p = base;
    p.set = set;
    for (int k : order) {
        p.p1.push_back(m.points1[k]);
        p.p2.push_back(m.points2[k]);
        p.distance.push_back(m.distances[k]);
    }
    p.trueInlierRate = trueInlierRate(p);
    return p;
}

/** rail-random20 and rail-all problems (both from one matching of each pair). */
void railProblems(const Options& o, bool random20, bool all, bool best20,
                  std::vector<Problem>& outRandom, std::vector<Problem>& outAll,
                  std::vector<Problem>& outBest)
{
    essential_samples::FrontEndParams params;
    params.keepFraction = 1.0; // every match; the sets select from them
    for (const std::string sequence : {"horizontal", "optic"}) {
        const std::string dir = o.data + "/rail-a/" + sequence;
        cv::Matx33d K;
        std::vector<essential_samples::Pose> poses;
        if (!essential_samples::readSequence(dir, K, poses)) {
            std::fprintf(stderr, "hard_pairs: rail sets: skipping '%s' (no camera.txt/poses.txt)\n",
                         dir.c_str());
            continue;
        }
        const int frames = static_cast<int>(poses.size());
        std::map<int, essential_samples::Features> features;
        auto featuresOf = [&](int k) -> const essential_samples::Features& {
            auto it = features.find(k);
            if (it == features.end()) {
                const std::string path = essential_samples::framePath(dir, k);
                const cv::Mat image = cv::imread(path, cv::IMREAD_GRAYSCALE);
                if (image.empty()) fail("cannot read '" + path + "'");
                it = features.emplace(k, essential_samples::detectAndDescribe(image, params)).first;
            }
            return it->second;
        };
        for (int n : o.offsets) {
            // Up to pairsPerOffset first frames spread evenly over those whose partner exists
            // (paper_rail's rule).
            const int c = frames - n;
            std::vector<int> firsts;
            if (c <= o.pairsPerOffset) {
                for (int i = 0; i < c; ++i)
                    firsts.push_back(i);
            } else {
                for (int k = 0; k < o.pairsPerOffset; ++k)
                    firsts.push_back(o.pairsPerOffset == 1
                                         ? c / 2
                                         : cvRound(double(k) * (c - 1) / (o.pairsPerOffset - 1)));
            }
            for (int i : firsts) {
                const int j = i + n;
                const std::string cachePath =
                    o.cache.empty() ? std::string()
                                    : cv::format("%s/%s_%03d_%03d.bin", o.cache.c_str(),
                                                 sequence.c_str(), i, j);
                const essential_samples::Matches m = pairMatches(
                    cachePath, [&]() { return std::make_pair(featuresOf(i), featuresOf(j)); },
                    params);
                Problem base;
                base.name = cv::format("%s-%03d-%03d", sequence.c_str(), i, j);
                base.ratioOrOffset = n;
                base.K = K;
                base.R = essential_samples::relativeRotation(poses[i], poses[j]);
                const cv::Vec3d t = essential_samples::relativeTranslation(poses[i], poses[j]);
                base.t = t / cv::norm(t);
                if (all) {
                    Problem p = base;
                    p.set = "rail-all";
                    p.p1 = m.points1;
                    p.p2 = m.points2;
                    p.distance = m.distances;
                    p.trueInlierRate = trueInlierRate(p);
                    outAll.push_back(std::move(p));
                }
                if (best20) {
                    // The best 20% by descriptor distance (the front end's own selection rule).
                    std::vector<int> order(m.points1.size());
                    std::iota(order.begin(), order.end(), 0);
                    std::stable_sort(order.begin(), order.end(),
                                     [&](int a, int b) { return m.distances[a] < m.distances[b]; });
                    outBest.push_back(railSubset(base, "rail-best20", m, order));
                }
                if (random20) {
                    // A fixed random 20% per pair (the shuffles then reorder it).
                    std::vector<int> order(m.points1.size());
                    std::iota(order.begin(), order.end(), 0);
                    std::mt19937_64 g(o.seed * 7919ULL + i * 131ULL + j);
                    std::shuffle(order.begin(), order.end(), g);
                    outRandom.push_back(railSubset(base, "rail-random20", m, order));
                }
            }
        }
    }
}

/** aloe-orb20 / aloe-orb30: the best fraction of the ORB matches of the rectified Aloe pair.
K: fx = fy = image width, principal point at the centre (none is given; a rectified pair's pose
does not depend on it). Truth: R = I and, the right camera's centre being at +x in the left
camera's frame, X2 = X1 - C2 gives t = -x; checked on the data (a scene point's x must be smaller
in the right image: positive disparity). */
void aloeProblems(const Options& o, const std::vector<double>& fractions,
                  std::vector<std::vector<Problem>>& out)
{
    const std::string left = o.data + "/pairs/aloeL.jpg", right = o.data + "/pairs/aloeR.jpg";
    if (!fileExists(left) || !fileExists(right)) {
        std::fprintf(stderr, "hard_pairs: aloe sets: skipped, no '%s' or '%s'\n", left.c_str(),
                     right.c_str());
        return;
    }
    const cv::Mat a = cv::imread(left, cv::IMREAD_GRAYSCALE);
    const cv::Mat b = cv::imread(right, cv::IMREAD_GRAYSCALE);
    if (a.empty() || b.empty()) fail("cannot read the Aloe pair in '" + o.data + "/pairs'");
    essential_samples::FrontEndParams params;
    params.descriptor = essential_samples::Descriptor::RotatedBrief;
    params.keepFraction = 1.0;
    const std::string cachePath = o.cache.empty() ? std::string() : o.cache + "/aloe_orb.bin";
    const essential_samples::Matches m = pairMatches(
        cachePath,
        [&]() {
            return std::make_pair(essential_samples::detectAndDescribe(a, params),
                                  essential_samples::detectAndDescribe(b, params));
        },
        params);
    const double w = a.cols, h = a.rows;
    const cv::Matx33d K(w, 0, 0.5 * (w - 1), 0, w, 0.5 * (h - 1), 0, 0, 1);

    // The sign of t from the data: the median disparity of matches on the same row.
    std::vector<double> disparity;
    for (size_t i = 0; i < m.points1.size(); ++i)
        if (std::abs(m.points1[i].y - m.points2[i].y) < 1.0)
            disparity.push_back(m.points1[i].x - m.points2[i].x);
    std::nth_element(disparity.begin(), disparity.begin() + disparity.size() / 2, disparity.end());
    const double median = disparity.empty() ? 0.0 : disparity[disparity.size() / 2];
    std::fprintf(stderr,
                 "hard_pairs: aloe: %zu matches, %zu on the same row (|dy| < 1 px), median "
                 "disparity x1 - x2 = %.1f px (> 0: right camera at +x, t = -x)\n",
                 m.points1.size(), disparity.size(), median);
    if (!(median > 0))
        fail("aloe: the data do not show a right camera at +x (median disparity <= 0)");

    std::vector<int> order(m.points1.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](int x, int y) { return m.distances[x] < m.distances[y]; });
    for (double fraction : fractions) {
        Problem p;
        p.set = cv::format("aloe-orb%d", cvRound(fraction * 100));
        p.name = "aloe";
        p.K = K;
        p.R = cv::Matx33d::eye();
        p.t = cv::Vec3d(-1, 0, 0);
        const size_t keep = static_cast<size_t>(std::ceil(fraction * order.size()));
        for (size_t k = 0; k < keep; ++k) {
            p.p1.push_back(m.points1[order[k]]);
            p.p2.push_back(m.points2[order[k]]);
            p.distance.push_back(m.distances[order[k]]);
        }
        p.trueInlierRate = trueInlierRate(p);
        out.push_back({std::move(p)});
    }
}

// ---------------------------------------------------------------------------------------------
// Running

struct Outcome
{
    double cpuMs = 0, wallMs = 0;
    int inliers = 0;
    bool posed = false;
    double rErr = NAN, tErr = NAN;
    bool right = false;
};

Outcome runMethod(const Method& m, const Problem& p, const std::vector<cv::Point2f>& p1,
                  const std::vector<cv::Point2f>& p2, std::uint64_t seed)
{
    const essential_bench::MethodOutcome r =
        essential_bench::runMethod(m, p.K, p1, p2, seed, p.name);
    Outcome out;
    out.cpuMs = r.cpuMs;
    out.wallMs = r.wallMs;
    out.inliers = r.inliers;
    out.posed = r.posed;
    if (out.posed) {
        out.rErr = essential_samples::rotationAngleDeg(r.R, p.R);
        out.tErr = essential_samples::directionAngleDeg(r.t, p.t, 180.0);
        out.right = out.rErr < 5.0 && out.tErr < 10.0;
    }
    return out;
}

struct Tally
{
    int runs = 0, right = 0;
    std::vector<double> cpuMs;
};

struct Summary
{
    // key: row name; per method label.
    std::map<std::string, std::map<std::string, Tally>> cells;
    std::map<std::string, std::vector<double>> trueRates, matches;
    std::map<std::string, int> problems;
    std::vector<std::string> rowOrder;

    void addProblem(const std::string& row, const Problem& p)
    {
        if (!problems.count(row)) rowOrder.push_back(row);
        ++problems[row];
        trueRates[row].push_back(p.trueInlierRate);
        matches[row].push_back(static_cast<double>(p.p1.size()));
    }
};

double medianOf(std::vector<double> v)
{
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double meanOf(const std::vector<double>& v)
{
    return v.empty() ? NAN : std::accumulate(v.begin(), v.end(), 0.0) / v.size();
}

std::string markdownTable(const Summary& s, const std::vector<Method>& methods,
                          const std::string& firstColumn, bool allRow)
{
    std::ostringstream md;
    md << "| " << firstColumn << " | problems | matches (median) | true inlier rate (mean) |";
    for (const Method& m : methods)
        md << " " << m.label << " |";
    md << "\n|---|---:|---:|---:|";
    for (size_t i = 0; i < methods.size(); ++i)
        md << "---:|";
    md << "\n";
    std::map<std::string, Tally> total;
    std::vector<double> allRates, allMatches;
    int allProblems = 0;
    for (const std::string& row : s.rowOrder) {
        const auto& rates = s.trueRates.at(row);
        md << "| " << row << " | " << s.problems.at(row) << " | "
           << cv::format("%.0f", medianOf(s.matches.at(row))) << " | "
           << cv::format("%.3f", meanOf(rates)) << " |";
        allRates.insert(allRates.end(), rates.begin(), rates.end());
        allMatches.insert(allMatches.end(), s.matches.at(row).begin(), s.matches.at(row).end());
        allProblems += s.problems.at(row);
        for (const Method& m : methods) {
            const auto it = s.cells.at(row).find(m.label);
            if (it == s.cells.at(row).end()) {
                md << " - |";
                continue;
            }
            const Tally& c = it->second;
            md << cv::format(" %.2f (%.1f ms) |", double(c.right) / c.runs, medianOf(c.cpuMs));
            Tally& t = total[m.label];
            t.runs += c.runs;
            t.right += c.right;
            t.cpuMs.insert(t.cpuMs.end(), c.cpuMs.begin(), c.cpuMs.end());
        }
        md << "\n";
    }
    if (allRow) {
        md << "| **all hard sets** | " << allProblems << " | "
           << cv::format("%.0f", medianOf(allMatches)) << " | "
           << cv::format("%.3f", meanOf(allRates)) << " |";
        for (const Method& m : methods) {
            const Tally& t = total[m.label];
            md << (t.runs ? cv::format(" **%.2f** (%.1f ms) |", double(t.right) / t.runs,
                                       medianOf(t.cpuMs))
                          : std::string(" - |"));
        }
        md << "\n";
    }
    return md.str();
}

Options parseOptions(int argc, char** argv)
{
    Options o;
    std::string methods = "cv_ransac,usac_magsac,usac_accurate,dropin,prosac=ours:sampler=prosac";
    o.commandLine = "essential_hard_pairs";
    for (int i = 1; i < argc; ++i)
        o.commandLine += std::string(" ") + argv[i];
    essential_bench::Options opts("essential_hard_pairs", kUsage);
    long long integer = 0;
    auto positive = [&](const char* name, int& field, long long max) {
        opts.custom(name, std::to_string(field),
                    [&field, &integer, name, max](const std::string& v) {
                        if (!parseInt(v, integer) || integer < 1 || integer > max)
                            fail(std::string("--") + name + " must be an integer in [1, " +
                                     std::to_string(max) + "]",
                                 2);
                        field = static_cast<int>(integer);
                    });
    };
    opts.add("sets", o.sets);
    opts.add("methods", methods);
    opts.custom("ratios", "", [&](const std::string& value) {
        o.ratios.clear();
        for (const std::string& part : split(value, ',')) {
            double r = 0;
            if (!parseDouble(part, r) || !(r > 0) || r > 1)
                fail("--ratios: '" + part + "' is not an inlier ratio in (0, 1]", 2);
            o.ratios.push_back(r);
        }
    });
    opts.custom("offsets", "", [&](const std::string& value) {
        o.offsets.clear();
        for (const std::string& part : split(value, ',')) {
            if (!parseInt(part, integer) || integer < 1 || integer > 100000)
                fail("--offsets: '" + part + "' is not a positive frame offset", 2);
            o.offsets.push_back(static_cast<int>(integer));
        }
    });
    positive("problems", o.problems, 100000);
    positive("points", o.points, 10000000);
    positive("shuffles", o.shuffles, 100000);
    positive("pairs-per-offset", o.pairsPerOffset, 100000);
    opts.add("data", o.data);
    opts.add("cache", o.cache);
    opts.add("csv", o.csv);
    opts.add("md", o.md);
    opts.custom("seed", "1", [&](const std::string& value) {
        if (!essential_samples::parseSeed(value, o.seed)) fail("--seed must be >= 0", 2);
    });
    opts.parse(argc, argv);
    static const std::vector<std::string> known = {
        "synth-plane", "synth-repeated", "synth-clustered", "rail-random20", "rail-all",
        "aloe-orb20",  "aloe-orb30",     "synth-protocol",  "rail-best20"};
    for (const std::string& set : o.sets)
        if (std::find(known.begin(), known.end(), set) == known.end())
            fail("--sets: unknown set '" + set + "'", 2);
    for (const std::string& text : split(methods, ','))
        o.methods.push_back(parseMethod(text));
    for (size_t i = 0; i < o.methods.size(); ++i)
        for (size_t j = 0; j < i; ++j)
            if (o.methods[i].label == o.methods[j].label)
                fail("--methods: two columns named '" + o.methods[i].label + "'", 2);
    return o;
}

int run(int argc, char** argv)
{
    const Options o = parseOptions(argc, argv);
    auto wants = [&](const std::string& set) {
        return std::find(o.sets.begin(), o.sets.end(), set) != o.sets.end();
    };
    if (!o.cache.empty()) {
        std::error_code error;
        std::filesystem::create_directories(o.cache, error);
        if (error) fail("cannot create the cache folder '" + o.cache + "': " + error.message());
    }

    // The problems of every set, in --sets order.
    std::map<std::string, std::vector<Problem>> bySet;
    const auto start = std::chrono::steady_clock::now();
    for (const std::string& set : o.sets)
        if (set == "synth-protocol")
            bySet[set] = protocolProblems(o);
        else if (set.rfind("synth-", 0) == 0)
            bySet[set] = syntheticProblems(set, o);
    if (wants("rail-random20") || wants("rail-all") || wants("rail-best20")) {
        if (!fileExists(o.data + "/rail-a")) {
            std::fprintf(stderr, "hard_pairs: rail sets: skipped, no '%s/rail-a'\n",
                         o.data.c_str());
        } else {
            railProblems(o, wants("rail-random20"), wants("rail-all"), wants("rail-best20"),
                         bySet["rail-random20"], bySet["rail-all"], bySet["rail-best20"]);
        }
    }
    if (wants("aloe-orb20") || wants("aloe-orb30")) {
        std::vector<double> fractions;
        if (wants("aloe-orb20")) fractions.push_back(0.2);
        if (wants("aloe-orb30")) fractions.push_back(0.3);
        std::vector<std::vector<Problem>> aloe;
        aloeProblems(o, fractions, aloe);
        for (auto& v : aloe)
            bySet[v.front().set] = std::move(v);
    }
    std::fprintf(stderr, "hard_pairs: problems ready in %.1f s\n",
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());

    std::ofstream csv;
    if (!o.csv.empty()) {
        csv.open(o.csv);
        if (!csv) fail("cannot write '" + o.csv + "'");
        csv << "set,problem,ratio_or_offset,matches,true_inlier_rate,shuffle,method,cpu_ms,"
               "wall_ms,inliers,r_err_deg,t_err_deg,right\n";
    }
    Summary bySetSummary, byRatioSummary;
    for (const std::string& set : o.sets) {
        const auto it = bySet.find(set);
        if (it == bySet.end() || it->second.empty()) {
            std::fprintf(stderr, "hard_pairs: set %s: no problems (data missing), skipped\n",
                         set.c_str());
            continue;
        }
        const std::vector<Problem>& problems = it->second;
        for (size_t pi = 0; pi < problems.size(); ++pi) {
            const Problem& p = problems[pi];
            const std::string ratioRow =
                set + (set.rfind("synth-", 0) == 0  ? cv::format(" @%.2f", p.ratioOrOffset)
                       : set.rfind("rail-", 0) == 0 ? cv::format(" N=%g", p.ratioOrOffset)
                                                    : std::string());
            bySetSummary.addProblem(set, p);
            byRatioSummary.addProblem(ratioRow, p);
            std::map<std::string, int> rightHere;
            for (int sh = 0; sh < o.shuffles; ++sh) {
                // This shuffle's order of the matches, and the same order sorted by descriptor
                // distance (stable: ties keep the shuffle's order) for the PROSAC methods.
                const std::uint64_t seed =
                    o.seed * 0x9E3779B97F4A7C15ULL ^ (std::hash<std::string>()(set + p.name) + sh);
                std::vector<int> order(p.p1.size());
                std::iota(order.begin(), order.end(), 0);
                std::mt19937_64 g(seed);
                std::shuffle(order.begin(), order.end(), g);
                std::vector<int> sorted = order;
                std::stable_sort(sorted.begin(), sorted.end(),
                                 [&](int a, int b) { return p.distance[a] < p.distance[b]; });
                std::vector<cv::Point2f> s1, s2, b1, b2;
                for (int k : order) {
                    s1.push_back(p.p1[k]);
                    s2.push_back(p.p2[k]);
                }
                for (int k : sorted) {
                    b1.push_back(p.p1[k]);
                    b2.push_back(p.p2[k]);
                }
                for (const Method& m : o.methods) {
                    const Outcome r = m.sortedByDistance ? runMethod(m, p, b1, b2, seed)
                                                         : runMethod(m, p, s1, s2, seed);
                    for (Summary* s : {&bySetSummary, &byRatioSummary}) {
                        Tally& t = s->cells[s == &bySetSummary ? set : ratioRow][m.label];
                        ++t.runs;
                        t.right += r.right;
                        t.cpuMs.push_back(r.cpuMs);
                    }
                    rightHere[m.label] += r.right;
                    if (csv.is_open()) {
                        csv << cv::format(
                            "%s,%s,%g,%zu,%.4f,%d,%s,%.3f,%.3f,%d,%s,%s,%d\n", set.c_str(),
                            p.name.c_str(), p.ratioOrOffset, p.p1.size(), p.trueInlierRate, sh,
                            m.label.c_str(), r.cpuMs, r.wallMs, r.inliers,
                            r.posed ? cv::format("%.3f", r.rErr).c_str() : "",
                            r.posed ? cv::format("%.3f", r.tErr).c_str() : "", r.right ? 1 : 0);
                    }
                }
            }
            if (csv.is_open()) csv.flush();
            std::string line =
                cv::format("hard_pairs: %s %zu/%zu %s (%zu matches, true %.3f):", set.c_str(),
                           pi + 1, problems.size(), p.name.c_str(), p.p1.size(), p.trueInlierRate);
            for (const Method& m : o.methods)
                line += cv::format(" %s %d/%d", m.label.c_str(), rightHere[m.label], o.shuffles);
            std::fprintf(stderr, "%s\n", line.c_str());
        }
    }

    const double totalS =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::ostringstream md;
    md << "Right-rate (rotation < 5 deg and translation direction < 10 deg; failures count as "
          "wrong) and median thread CPU time per call, "
       << o.shuffles << " shuffles per problem.\n\ncommand: `" << o.commandLine << "`\n\n"
       << markdownTable(bySetSummary, o.methods, "set", true) << "\nBy inlier ratio (synthetic) "
       << "and frame offset (rail):\n\n"
       << markdownTable(byRatioSummary, o.methods, "set / ratio or offset", false)
       << cv::format("\nTotal time %.0f s.\n", totalS);
    std::fputs(md.str().c_str(), stdout);
    if (!o.md.empty()) {
        std::ofstream out(o.md);
        out << md.str();
        if (!out) fail("cannot write '" + o.md + "'");
    }
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    return essential_samples::runCli("essential_hard_pairs", run, argc, argv);
}

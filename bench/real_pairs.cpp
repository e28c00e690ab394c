// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// The real-data pose benchmark (docs/REAL_PAIRS.md): every overlapping image pair of public
// multi-view scenes with ground-truth cameras (laid out by scripts/fetch_real_pairs.sh), the rail-a
// renders at wide frame offsets, and the hard synthetic scenes of test/hard_scenes.hpp, matched by
// a standard structure-from-motion front end (OpenCV's SIFT, Lowe's ratio test) or the project's
// FAST-9 one. Every method runs once per pair on the same correspondences, in a random order per
// pair, timed by the thread CPU clock with the pose recovery included. Reported as in the
// pose-estimation benchmarks: AUC@5/10/20 of max(rotation error, translation direction error),
// failures counted as 180 degrees; the right-rate (rotation < 5 and translation < 10 degrees); the
// pairs without a pose; median and mean CPU time; overall and by true inlier ratio.
//
//   essential_real_pairs [--data DIR] [--rail DIR] [--hard N] ...  (kUsage)

#include "bench_common.hpp"
#include "cli_common.hpp"
#include "cli_parser.hpp"
#include "frontend/frontend.hpp"
#include "frontend/sequence_io.hpp"
#include "hard_scenes.hpp"
#include "match_cache.hpp"
#include "methods.hpp"
#include "pose_accuracy.hpp"
#include "real_dataset.hpp"

#include <opencv2/core.hpp>
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

namespace {

using essential_bench::Method;
using essential_bench::MethodKind;
using essential_samples::fail;

const char* const kUsage =
    "usage: essential_real_pairs [--data DIR] [--scenes LIST] [--rail DIR] [--hard N]\n"
    "           [--front-end sift|fast] [--methods LIST] [--max-angle DEG] [--max-pairs N]\n"
    "           [--rail-offsets 20,30,40,60] [--rail-step 10] [--threshold-px 1]\n"
    "           [--cache DIR] [--csv FILE] [--md FILE] [--seed S]\n"
    "\n"
    "  --data DIR          scenes laid out by scripts/fetch_real_pairs.sh "
    "(DIR/<scene>/cameras.txt\n"
    "                      and images/); default ~/.cache/opencv_essential/real when it exists\n"
    "  --scenes LIST       only these scenes of --data (default all but castle-P19, whose\n"
    "                      images are ten of castle-P30's)\n"
    "  --max-angle DEG     pairs whose optical axes differ by at most DEG (default 60)\n"
    "  --max-pairs N       at most N pairs per scene, evenly spread (default 0: all)\n"
    "  --rail DIR          rail-a (horizontal/, optic/): pairs (i, i + N) for N in\n"
    "                      --rail-offsets, i every --rail-step frames\n"
    "  --hard N            N synthetic problems per hard set (plane, repeated, clustered) and\n"
    "                      inlier ratio (0.10, 0.15, 0.25); 1000 matches, 1 px noise\n"
    "  --front-end F       sift (OpenCV's SIFT, 4000 features, ratio test 0.8, all survivors;\n"
    "                      default) or fast (the sample front end: FAST-9 pyramid, upright BRIEF,\n"
    "                      best 20%)\n"
    "  --methods LIST      estimators (bench/methods.hpp): cv_ransac, usac_magsac, usac_accurate,\n"
    "                      dropin, ours[:k=v;...], poselib[:maxIters=N], superansac; LABEL=METHOD\n"
    "                      names a column. Default dropin,cv_ransac,usac_magsac,usac_accurate "
    "and,\n"
    "                      when built in, poselib and superansac\n"
    "  --threshold-px PX   inlier threshold of every method (default 1, OpenCV's)\n"
    "  --true-px PX        a match is a true inlier when its Sampson distance to the true E is\n"
    "                      below PX (default 1); gives each pair's true inlier ratio\n"
    "  --cache DIR         match cache (default build/real_match_cache)\n"
    "  --csv FILE          one row per pair x method\n"
    "  --md FILE           the summary tables (also printed on stdout)\n";

// ---------------------------------------------------------------------------------------------
// Pairs

struct Pair
{
    std::string set, name;
    std::vector<cv::Point2f> p1, p2;
    cv::Matx33d K;
    cv::Matx33d R; // X2 = R X1 + s t
    cv::Vec3d t;   // unit
    double trueRatio = 0;
    double rotationDeg = 0; // of the true relative pose
};

struct Options
{
    std::string data, rail, cache = "build/real_match_cache", csv, md;
    std::vector<std::string> scenes;
    std::vector<Method> methods;
    std::vector<int> railOffsets = {20, 30, 40, 60};
    int railStep = 10, hard = 0, maxPairs = 0;
    double maxAngle = 60, threshold = 1.0, truePx = 1.0;
    bool sift = true;
    std::uint64_t seed = 1;
    std::string commandLine;
};

/** The pixel fundamental matrix of the pose (R, t) with the pair's camera. */
cv::Matx33d fundamentalPx(const Pair& p, const cv::Matx33d& R, const cv::Vec3d& t)
{
    const cv::Matx33d Kinv = p.K.inv();
    return Kinv.t() * essential_test::skewMatrix(t) * R * Kinv;
}

double trueRatio(const Pair& p, double px)
{
    if (p.p1.empty()) return 0;
    const cv::Matx33d F = fundamentalPx(p, p.R, p.t);
    int good = 0;
    for (size_t i = 0; i < p.p1.size(); ++i)
        good += essential_test::sampsonPx(F, p.p1[i], p.p2[i]) < px;
    return double(good) / p.p1.size();
}

/** MSAC cost of the pose (R, t) on the pair's matches: the mean over the matches of the squared
 * Sampson distance in pixels, truncated at the threshold. Tells a search that missed the true pose
 * (the true pose costs less than the returned one) from an objective that prefers a wrong one. */
double msacCostPx(const Pair& p, const cv::Matx33d& R, const cv::Vec3d& t, double px)
{
    if (p.p1.empty()) return 0;
    const cv::Matx33d F = fundamentalPx(p, R, t);
    double cost = 0;
    for (size_t i = 0; i < p.p1.size(); ++i) {
        const double d = essential_test::sampsonPx(F, p.p1[i], p.p2[i]);
        cost += std::isfinite(d) ? std::min(d * d, px * px) : px * px;
    }
    return cost / double(p.p1.size());
}

essential_samples::FrontEndParams frontEnd(const Options& o)
{
    essential_samples::FrontEndParams params;
    if (o.sift) {
        params.detector = essential_samples::Detector::Sift;
        params.siftFeatures = 4000;
        params.ratio = 0.8;
        params.keepFraction = 1.0;
    }
    return params;
}

std::string frontEndTag(const Options& o)
{
    return o.sift ? "sift4000r08" : "fast20";
}

/** Features per image, computed once per run (a scene's images take part in many pairs). */
using FeatureStore = std::map<std::string, essential_samples::Features>;

const essential_samples::Features& featuresOf(const Options& o, const std::string& image,
                                              FeatureStore& store)
{
    const auto it = store.find(image);
    if (it != store.end()) return it->second;
    const cv::Mat a = cv::imread(image, cv::IMREAD_GRAYSCALE);
    if (a.empty()) fail("cannot read '" + image + "'");
    return store[image] = essential_samples::detectAndDescribe(a, frontEnd(o));
}

/** The matches of two images, from the cache when it has them. */
essential_samples::Matches matchPair(const Options& o, const std::string& key,
                                     const std::string& image1, const std::string& image2,
                                     FeatureStore& store)
{
    essential_samples::Matches m;
    std::string path;
    if (!o.cache.empty()) {
        path = o.cache + "/" + key + "_" + frontEndTag(o) + ".bin";
        if (essential_bench::loadMatches(path, m)) return m;
    }
    const essential_samples::Features& a = featuresOf(o, image1, store);
    const essential_samples::Features& b = featuresOf(o, image2, store);
    m = essential_samples::matchFeatures(a, b, frontEnd(o));
    if (!path.empty()) essential_bench::saveMatches(path, m);
    return m;
}

double angleDeg(const cv::Matx33d& R)
{
    return essential_samples::rotationAngleDeg(R, cv::Matx33d::eye());
}

void realPairs(const Options& o, std::vector<Pair>& out)
{
    std::vector<std::string> dirs;
    if (o.scenes.empty()) {
        // castle-P19's images are ten of castle-P30's with the same poses: its pairs would count
        // twice.
        for (const std::string& dir : essential_bench::listRealScenes(o.data))
            if (std::filesystem::path(dir).filename() != "castle-P19") dirs.push_back(dir);
    } else {
        for (const std::string& name : o.scenes)
            dirs.push_back(o.data + "/" + name);
    }
    for (const std::string& dir : dirs) {
        FeatureStore store;
        const essential_bench::RealScene scene = essential_bench::loadRealScene(dir);
        const std::string& name = scene.name;
        std::vector<std::pair<int, int>> pairs =
            essential_bench::overlappingPairs(scene, o.maxAngle);
        if (o.maxPairs > 0 && static_cast<int>(pairs.size()) > o.maxPairs) {
            std::vector<std::pair<int, int>> kept;
            for (int k = 0; k < o.maxPairs; ++k)
                kept.push_back(pairs[size_t(k) * pairs.size() / size_t(o.maxPairs)]);
            pairs.swap(kept);
        }
        std::fprintf(stderr, "real_pairs: scene %s: %zu views, %zu pairs\n", name.c_str(),
                     scene.views.size(), pairs.size());
        for (size_t k = 0; k < pairs.size(); ++k) {
            const essential_bench::RealView& a = scene.views[size_t(pairs[k].first)];
            const essential_bench::RealView& b = scene.views[size_t(pairs[k].second)];
            if (!(a.K == b.K))
                std::fprintf(stderr, "real_pairs: %s %s-%s: two cameras; the first K is used\n",
                             name.c_str(), a.name.c_str(), b.name.c_str());
            Pair p;
            p.set = "real " + name;
            p.name = name + "/" + a.name + "-" + b.name;
            const essential_samples::Matches m =
                matchPair(o, name + "_" + a.name + "_" + b.name, a.image, b.image, store);
            p.p1 = m.points1;
            p.p2 = m.points2;
            p.K = a.K;
            essential_bench::relativePose(a, b, p.R, p.t);
            p.rotationDeg = angleDeg(p.R);
            p.trueRatio = trueRatio(p, o.truePx);
            out.push_back(std::move(p));
            if ((k + 1) % 20 == 0 || k + 1 == pairs.size())
                std::fprintf(stderr, "real_pairs: %s: %zu/%zu pairs matched\n", name.c_str(), k + 1,
                             pairs.size());
        }
    }
}

void railPairs(const Options& o, std::vector<Pair>& out)
{
    for (const char* sequence : {"horizontal", "optic"}) {
        const std::string dir = o.rail + "/" + sequence;
        cv::Matx33d K;
        std::vector<essential_samples::Pose> poses;
        if (!essential_samples::readSequence(dir, K, poses))
            fail("rail: cannot read the sequence in '" + dir + "' (camera.txt, poses.txt)");
        const int frames = static_cast<int>(poses.size());
        FeatureStore store;
        for (int offset : o.railOffsets)
            for (int i = 0; i + offset < frames; i += o.railStep) {
                Pair p;
                p.set = std::string("rail ") + sequence;
                p.name = cv::format("%s/%d-%d", sequence, i, i + offset);
                const essential_samples::Matches m =
                    matchPair(o, cv::format("rail_%s_%d_%d", sequence, i, i + offset),
                              essential_samples::framePath(dir, i),
                              essential_samples::framePath(dir, i + offset), store);
                p.p1 = m.points1;
                p.p2 = m.points2;
                p.K = K;
                p.R = essential_samples::relativeRotation(poses[size_t(i)],
                                                          poses[size_t(i + offset)]);
                p.t = essential_samples::relativeTranslation(poses[size_t(i)],
                                                             poses[size_t(i + offset)]);
                p.rotationDeg = angleDeg(p.R);
                p.trueRatio = trueRatio(p, o.truePx);
                out.push_back(std::move(p));
            }
    }
}

void hardPairs(const Options& o, std::vector<Pair>& out)
{
    const double ratios[] = {0.10, 0.15, 0.25};
    for (const char* kind : {"plane", "repeated", "clustered"})
        for (double ratio : ratios)
            for (int k = 0; k < o.hard; ++k) {
                const std::uint64_t seed = o.seed * 1000003ULL + k * 7919ULL +
                                           static_cast<std::uint64_t>(ratio * 1000) +
                                           std::hash<std::string>()(kind);
                essential_test::HardScene s;
                if (std::string(kind) == "plane") {
                    essential_test::DominantPlaneConfig c;
                    c.inlierRatio = ratio;
                    s = essential_test::makeDominantPlane(c, seed);
                } else if (std::string(kind) == "repeated") {
                    essential_test::RepeatedStructureConfig c;
                    c.inlierRatio = ratio;
                    s = essential_test::makeRepeatedStructure(c, seed);
                } else {
                    essential_test::ClusteredInliersConfig c;
                    c.inlierRatio = ratio;
                    s = essential_test::makeClusteredInliers(c, seed);
                }
                Pair p;
                p.set = std::string("hard ") + kind;
                p.name = cv::format("%s@%.2f/%d", kind, ratio, k);
                for (size_t i = 0; i < s.px1.size(); ++i) {
                    p.p1.emplace_back(float(s.px1[i].x), float(s.px1[i].y));
                    p.p2.emplace_back(float(s.px2[i].x), float(s.px2[i].y));
                }
                p.K = s.K;
                p.R = s.R;
                p.t = s.t;
                p.rotationDeg = angleDeg(p.R);
                p.trueRatio = trueRatio(p, o.truePx);
                out.push_back(std::move(p));
            }
}

// ---------------------------------------------------------------------------------------------
// Results

struct Run
{
    double error = 180; // max(rotation, translation direction) error, 180 for no pose
    double rErr = 180, tErr = 180;
    double ms = 0;
    bool posed = false;
};

struct Cell
{
    std::vector<Run> runs;
};

std::string bucketOf(double ratio)
{
    if (ratio < 0.15) return "< 15%";
    if (ratio < 0.30) return "15-30%";
    if (ratio < 0.50) return "30-50%";
    return ">= 50%";
}

double meanOf(const std::vector<double>& v)
{
    return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
}

/** One table: a row per method over the given runs. */
std::string methodTable(const std::vector<Method>& methods,
                        const std::map<std::string, Cell>& cells, int pairs)
{
    std::ostringstream md;
    md << "| method | AUC@5 | AUC@10 | AUC@20 | right | no pose | median / mean ms |\n"
       << "|---|---:|---:|---:|---:|---:|---:|\n";
    (void)pairs;
    for (const Method& m : methods) {
        const auto it = cells.find(m.label);
        if (it == cells.end() || it->second.runs.empty()) continue;
        std::vector<double> err, ms;
        int right = 0, none = 0;
        for (const Run& r : it->second.runs) {
            err.push_back(r.error);
            ms.push_back(r.ms);
            right += r.rErr < 5 && r.tErr < 10;
            none += !r.posed;
        }
        const double n = double(err.size());
        md << cv::format("| %s | %.3f | %.3f | %.3f | %.3f | %d | %.1f / %.1f |\n", m.label.c_str(),
                         essential_bench::poseAuc(err, 5), essential_bench::poseAuc(err, 10),
                         essential_bench::poseAuc(err, 20), right / n, none,
                         essential_bench::median(ms), meanOf(ms));
    }
    return md.str();
}

Options parseOptions(int argc, char** argv)
{
    using essential_samples::OptionSpec;
    const std::vector<OptionSpec> specs = {
        {"data", true, ""},      {"scenes", true, ""},       {"rail", true, ""},
        {"hard", true, ""},      {"front-end", true, ""},    {"methods", true, ""},
        {"max-angle", true, ""}, {"max-pairs", true, ""},    {"rail-offsets", true, ""},
        {"rail-step", true, ""}, {"threshold-px", true, ""}, {"true-px", true, ""},
        {"cache", true, ""},     {"csv", true, ""},          {"md", true, ""},
        {"seed", true, ""}};
    const essential_samples::CommandLine line =
        essential_samples::parseCommandLine("essential_real_pairs", argc, argv, specs);
    if (line.help) {
        std::fputs(kUsage, stdout);
        std::exit(0);
    }
    if (!line.positional.empty())
        fail("unexpected argument '" + line.positional.front() + "' (see --help)", 2);
    Options o;
    o.commandLine = "essential_real_pairs";
    for (int i = 1; i < argc; ++i)
        o.commandLine += std::string(" ") + argv[i];
    std::string methods;
    long long integer = 0;
    double number = 0;
    for (const essential_samples::GivenOption& g : line.options) {
        const std::string& v = g.value;
        auto intIn = [&](long long lo, long long hi) {
            if (!essential_samples::parseInt(v, integer) || integer < lo || integer > hi)
                fail(cv::format("--%s must be an integer in [%lld, %lld]", g.name.c_str(), lo, hi),
                     2);
            return static_cast<int>(integer);
        };
        auto positiveNumber = [&]() {
            if (!essential_samples::parseDouble(v, number) || !(number > 0) ||
                !std::isfinite(number))
                fail("--" + g.name + " must be a positive number", 2);
            return number;
        };
        if (g.name == "data")
            o.data = v;
        else if (g.name == "scenes")
            o.scenes = essential_samples::split(v, ',');
        else if (g.name == "rail")
            o.rail = v;
        else if (g.name == "hard")
            o.hard = intIn(0, 100000);
        else if (g.name == "front-end") {
            if (v != "sift" && v != "fast") fail("--front-end is sift or fast", 2);
            o.sift = v == "sift";
        } else if (g.name == "methods")
            methods = v;
        else if (g.name == "max-angle")
            o.maxAngle = positiveNumber();
        else if (g.name == "max-pairs")
            o.maxPairs = intIn(0, 100000000);
        else if (g.name == "rail-offsets") {
            o.railOffsets.clear();
            for (const std::string& part : essential_samples::split(v, ',')) {
                if (!essential_samples::parseInt(part, integer) || integer < 1 || integer > 100000)
                    fail("--rail-offsets: '" + part + "' is not a positive frame offset", 2);
                o.railOffsets.push_back(static_cast<int>(integer));
            }
        } else if (g.name == "rail-step")
            o.railStep = intIn(1, 100000);
        else if (g.name == "threshold-px")
            o.threshold = positiveNumber();
        else if (g.name == "true-px")
            o.truePx = positiveNumber();
        else if (g.name == "cache")
            o.cache = v;
        else if (g.name == "csv")
            o.csv = v;
        else if (g.name == "md")
            o.md = v;
        else if (g.name == "seed") {
            if (!essential_samples::parseSeed(v, o.seed)) fail("--seed must be >= 0", 2);
        }
    }
    if (o.data.empty() && std::filesystem::exists(essential_bench::defaultRealRoot()))
        o.data = essential_bench::defaultRealRoot();
    if (methods.empty()) {
        methods = "dropin,cv_ransac,usac_magsac,usac_accurate";
#ifdef ESSENTIAL_BENCH_HAVE_POSELIB
        methods += ",poselib";
#endif
#ifdef ESSENTIAL_BENCH_HAVE_SUPERANSAC
        methods += ",superansac";
#endif
    }
    for (const std::string& text : essential_samples::split(methods, ',')) {
        Method m = essential_bench::parseMethod(text);
        if (m.kind == MethodKind::Ours)
            m.params.threshold = o.threshold;
        else
            m.threshold = o.threshold;
        o.methods.push_back(m);
    }
    for (size_t i = 0; i < o.methods.size(); ++i)
        for (size_t j = 0; j < i; ++j)
            if (o.methods[i].label == o.methods[j].label)
                fail("--methods: two columns named '" + o.methods[i].label + "'", 2);
    if (o.data.empty() && o.rail.empty() && o.hard == 0)
        fail("nothing to run: give --data DIR (scripts/fetch_real_pairs.sh), --rail DIR or "
             "--hard N",
             2);
    return o;
}

int run(int argc, char** argv)
{
    const Options o = parseOptions(argc, argv);
    if (!o.cache.empty()) {
        std::error_code error;
        std::filesystem::create_directories(o.cache, error);
        if (error) fail("cannot create the cache folder '" + o.cache + "': " + error.message());
    }
    const auto start = std::chrono::steady_clock::now();
    std::vector<Pair> pairs;
    if (!o.data.empty()) realPairs(o, pairs);
    if (!o.rail.empty()) railPairs(o, pairs);
    if (o.hard > 0) hardPairs(o, pairs);
    std::fprintf(stderr, "real_pairs: %zu pairs ready in %.1f s\n", pairs.size(),
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());

    std::ofstream csv;
    if (!o.csv.empty()) {
        csv.open(o.csv);
        if (!csv) fail("cannot write '" + o.csv + "'");
        csv << "set,pair,matches,true_ratio,true_rotation_deg,method,cpu_ms,inliers,posed,"
               "r_err_deg,t_err_deg,cost_px2,true_cost_px2\n";
    }
    // group -> method -> runs; groups: "all", each set, each bucket of every set family.
    std::map<std::string, std::map<std::string, Cell>> cells;
    std::map<std::string, int> groupPairs;
    std::vector<std::string> groupOrder;
    auto addGroup = [&](const std::string& g) {
        if (!groupPairs.count(g)) groupOrder.push_back(g);
        ++groupPairs[g];
    };
    std::mt19937_64 order(o.seed);
    for (size_t pi = 0; pi < pairs.size(); ++pi) {
        const Pair& p = pairs[pi];
        const std::string family = p.set.substr(0, p.set.find(' '));
        const std::vector<std::string> groups = {family, p.set,
                                                 family + " " + bucketOf(p.trueRatio)};
        for (const std::string& g : groups)
            addGroup(g);
        std::vector<size_t> methodOrder(o.methods.size());
        std::iota(methodOrder.begin(), methodOrder.end(), size_t(0));
        std::shuffle(methodOrder.begin(), methodOrder.end(), order);
        const std::uint64_t seed =
            o.seed * 0x9E3779B97F4A7C15ULL ^ std::hash<std::string>()(p.name);
        std::string line =
            cv::format("real_pairs: %zu/%zu %s (%zu matches, true %.2f, rot %.0f):", pi + 1,
                       pairs.size(), p.name.c_str(), p.p1.size(), p.trueRatio, p.rotationDeg);
        const double trueCost = csv.is_open() ? msacCostPx(p, p.R, p.t, o.threshold) : 0.0;
        for (size_t mi : methodOrder) {
            const Method& m = o.methods[mi];
            essential_bench::RunOptions ro;
            ro.timePose = true;
            Run r;
            essential_bench::MethodOutcome out;
            if (p.p1.size() >= 5)
                out = essential_bench::runMethod(m, p.K, p.p1, p.p2, seed, p.name, ro);
            r.ms = out.cpuMs;
            r.posed = out.posed;
            if (out.posed) {
                r.rErr = essential_samples::rotationAngleDeg(out.R, p.R);
                r.tErr = essential_samples::directionAngleDeg(out.t, p.t, 180.0);
                r.error = std::max(r.rErr, r.tErr);
            }
            for (const std::string& g : groups)
                cells[g][m.label].runs.push_back(r);
            if (csv.is_open())
                csv << cv::format("%s,%s,%zu,%.4f,%.2f,%s,%.3f,%d,%d,%.3f,%.3f,%.5f,%.5f\n",
                                  p.set.c_str(), p.name.c_str(), p.p1.size(), p.trueRatio,
                                  p.rotationDeg, m.label.c_str(), r.ms, out.inliers,
                                  r.posed ? 1 : 0, r.rErr, r.tErr,
                                  out.posed ? msacCostPx(p, out.R, out.t, o.threshold)
                                            : o.threshold * o.threshold,
                                  trueCost);
        }
        for (const Method& m : o.methods)
            line +=
                cv::format(" %s %.1f", m.label.c_str(), cells[p.set][m.label].runs.back().error);
        if (csv.is_open()) csv.flush();
        std::fprintf(stderr, "%s\n", line.c_str());
    }

    std::ostringstream md;
    md << "Pose error = max(rotation error, translation direction error) in degrees, 180 for no "
          "pose; right = rotation < 5 and translation < 10 degrees; thread CPU time per call, "
          "pose recovery included. Front end: "
       << (o.sift ? "OpenCV SIFT (4000 features), Lowe ratio 0.8"
                  : "FAST-9 pyramid, upright BRIEF, best 20%")
       << "; threshold " << o.threshold << " px.\n\ncommand: `" << o.commandLine << "`\n";
    // Families first, each followed by its sets and its buckets in a fixed order.
    std::vector<std::string> families;
    for (const std::string& g : groupOrder)
        if (g.find(' ') == std::string::npos) families.push_back(g);
    for (const std::string& f : families) {
        std::vector<double> ratios;
        for (const Pair& p : pairs)
            if (p.set.rfind(f + " ", 0) == 0) ratios.push_back(p.trueRatio);
        md << cv::format("\n### %s: %d pairs, true inlier ratio median %.2f\n\n", f.c_str(),
                         groupPairs[f], essential_bench::median(ratios))
           << methodTable(o.methods, cells[f], groupPairs[f]);
        for (const std::string& g : groupOrder)
            if (g.rfind(f + " ", 0) == 0 && g.find('%') == std::string::npos)
                md << cv::format("\n%s (%d pairs):\n\n", g.c_str(), groupPairs[g])
                   << methodTable(o.methods, cells[g], groupPairs[g]);
        for (const char* b : {"< 15%", "15-30%", "30-50%", ">= 50%"}) {
            const std::string g = f + " " + b;
            if (!groupPairs.count(g)) continue;
            md << cv::format("\n%s true inliers (%d pairs):\n\n", g.c_str(), groupPairs[g])
               << methodTable(o.methods, cells[g], groupPairs[g]);
        }
    }
    md << cv::format(
        "\nTotal time %.0f s.\n",
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
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
    return essential_samples::runCli("essential_real_pairs", run, argc, argv);
}

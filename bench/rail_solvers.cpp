// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Solvers on the rail sequences (the paper's real-data experiment, reduced): for frame pairs
// (t - N, t) of a sequence with known camera poses, the sample front end's matches go through
// findEssentialMatIter with each solver; a pair is correct when the estimated translation direction
// is within 10 degrees of the true one (the paper's criterion).
//
//   essential_rail_solvers --data DIR [--sequences horizontal,optic] [--offsets 2,5,10,20,40]
//                          [--pairs 8] [--solvers gn,lm,nister,robust] [--max-iters 1000]
//                          [--repeats 3] [--budget-ms T]
//
// DIR holds one folder per sequence with NNN.jpg frames, camera.txt (3 x 3 K) and poses.txt
// (`k r00 .. r22 Cx Cy Cz`, world-to-camera rotation and camera centre), as ../shared/data/rail-a.

#include "frontend/frontend.hpp"
#include "frontend/sequence_io.hpp"

#include "bench_common.hpp"
#include "bench_options.hpp"
#include <opencv2/essential.hpp>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

using namespace essential_bench;
using essential_samples::framePath;
using essential_samples::Pose;
using essential_samples::readSequence;

namespace {

double angleDeg(const cv::Vec3d& a, const cv::Vec3d& b)
{
    const double c = a.dot(b) / (cv::norm(a) * cv::norm(b));
    return std::acos(std::max(-1.0, std::min(1.0, c))) * 180.0 / CV_PI;
}

struct Cell
{
    int correct = 0, total = 0;
    std::vector<double> ms;
    double inlierRatio = 0;
};

} // namespace

int main(int argc, char** argv)
{
    std::string data;
    std::vector<std::string> sequences = {"horizontal", "optic"};
    std::vector<int> offsets = {2, 5, 10, 20, 40};
    std::vector<std::string> solvers = {"gn", "lm", "nister", "robust"};
    int pairs = 8, maxIters = 1000, repeats = 3;
    double budgetMs = 0;
    Options opts("essential_rail_solvers");
    opts.add("data", data);
    opts.add("sequences", sequences);
    opts.add("solvers", solvers);
    opts.add("pairs", pairs);
    opts.add("max-iters", maxIters);
    opts.add("repeats", repeats);
    opts.add("budget-ms", budgetMs);
    opts.add("offsets", offsets);
    opts.parse(argc, argv);
    if (data.empty()) {
        std::fprintf(stderr,
                     "usage: essential_rail_solvers --data DIR [options] (see the source)\n");
        return 2;
    }
    std::printf(
        "| sequence | solver | correct (t within 10 deg) | median ms | mean inlier ratio |\n"
        "|---|---|---|---|---|\n");
    for (const std::string& seq : sequences) {
        const std::string dir = data + "/" + seq;
        cv::Matx33d K;
        std::vector<Pose> poses;
        // A camera.txt that ends early is accepted here (as this program always did).
        if (!readSequence(dir, K, poses, /*acceptShortCamera=*/true) || poses.size() < 2) {
            std::fprintf(stderr, "cannot read %s/{camera,poses}.txt\n", dir.c_str());
            return 1;
        }
        const int frames = static_cast<int>(poses.size());
        std::map<int, essential_samples::Features> features;
        auto featuresOf = [&](int k) -> const essential_samples::Features& {
            auto it = features.find(k);
            if (it == features.end()) {
                const cv::Mat img = cv::imread(framePath(dir, k), cv::IMREAD_GRAYSCALE);
                if (img.empty()) {
                    std::fprintf(stderr, "cannot read %s\n", framePath(dir, k).c_str());
                    std::exit(1);
                }
                it = features.emplace(k, essential_samples::detectAndDescribe(img)).first;
            }
            return it->second;
        };
        std::map<std::string, Cell> cells;
        int done = 0;
        const int todo = static_cast<int>(offsets.size()) * pairs;
        for (int offset : offsets) {
            for (int p = 0; p < pairs; ++p) {
                // pairs spread over the sequence
                const int i = (frames - 1 - offset) * p / std::max(1, pairs - 1);
                const int j = i + offset;
                if (j >= frames || i < 0) continue;
                const auto matches = essential_samples::matchFeatures(featuresOf(i), featuresOf(j));
                const cv::Vec3d tTrue = essential_samples::relativeTranslation(poses[i], poses[j]);
                for (const std::string& solver : solvers) {
                    for (int r = 0; r < repeats; ++r) {
                        cv::essential::EssentialParams params;
                        params.solver = solver;
                        params.maxIterations = maxIters;
                        params.seed = 1000 + r;
                        if (budgetMs > 0) {
                            // The budget, not the confidence or the cap, ends the search.
                            params.timeBudgetMs = budgetMs;
                            params.confidence = 1.0 - 1e-12;
                            params.maxIterations = 100000000;
                        }
                        cv::essential::EssentialReport report;
                        const auto t0 = std::chrono::steady_clock::now();
                        const cv::Mat E = cv::essential::findEssentialMatIter(
                            matches.points1, matches.points2, cv::Mat(K), params, cv::noArray(),
                            &report);
                        Cell& c = cells[solver];
                        c.ms.push_back(std::chrono::duration<double, std::milli>(
                                           std::chrono::steady_clock::now() - t0)
                                           .count());
                        ++c.total;
                        c.inlierRatio +=
                            report.numPoints ? double(report.inliers) / report.numPoints : 0;
                        if (!E.empty() && report.poseRecovered && angleDeg(report.t, tTrue) < 10.0)
                            ++c.correct;
                    }
                }
                std::fprintf(stderr, "\r%s: %d / %d pairs", seq.c_str(), ++done, todo);
            }
        }
        std::fprintf(stderr, "\n");
        for (const std::string& solver : solvers) {
            Cell& c = cells[solver];
            std::sort(c.ms.begin(), c.ms.end());
            std::printf("| %s | %s | %.3f (%d of %d) | %.2f | %.2f |\n", seq.c_str(),
                        solver.c_str(), c.correct / double(std::max(1, c.total)), c.correct,
                        c.total, c.ms.empty() ? 0.0 : c.ms[c.ms.size() / 2],
                        c.inlierRatio / std::max(1, c.total));
        }
        std::fflush(stdout);
    }
    return 0;
}

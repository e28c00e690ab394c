// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The sample front end's descriptors on the rail sequences: for frame pairs (i, i + N) with known
// poses, the fraction of the kept matches that agree with the true essential matrix (Sampson
// distance below 1 pixel), per descriptor and offset N, and the time per image and per matching.
//
//   essential_frontend_descriptors --data DIR [--sequences horizontal,optic]
//                                  [--offsets 1,5,10,20,40,60] [--pairs 4]
//                                  [--descriptors brief,orb,patch] [--threshold 1]
//
// DIR holds one folder per sequence with NNN.jpg frames, camera.txt (3 x 3 K) and poses.txt
// (`k r00 .. r22 Cx Cy Cz`, world-to-camera rotation and camera centre), as ../shared/data/rail-a.

#include "frontend/frontend.hpp"
#include "frontend/sequence_io.hpp"

#include "bench_common.hpp"
#include "bench_options.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

using essential_bench::split;
using essential_samples::framePath;
using essential_samples::Pose;
using essential_samples::readSequence;
using essential_samples::sampsonPx;
using essential_samples::trueFundamental;

namespace {

double msSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

} // namespace

int main(int argc, char** argv)
{
    std::string data;
    std::vector<std::string> sequences = {"horizontal", "optic"};
    std::vector<int> offsets = {1, 5, 10, 20, 40, 60};
    std::vector<std::string> descriptors = {"brief", "orb", "patch"};
    int pairs = 4;
    double threshold = 1.0;
    essential_bench::Options opts("essential_frontend_descriptors");
    opts.add("data", data);
    opts.add("sequences", sequences);
    opts.add("descriptors", descriptors);
    opts.add("threshold", threshold);
    opts.add("pairs", pairs);
    opts.add("offsets", offsets);
    opts.parse(argc, argv);
    pairs = std::max(1, pairs);
    if (data.empty()) {
        std::fprintf(stderr, "usage: essential_frontend_descriptors --data DIR [options] (see the "
                             "source)\n");
        return 2;
    }

    std::printf("Fraction of the kept matches within %g px (Sampson) of the true E; in brackets "
                "the mean number of such matches per pair.\n\n",
                threshold);
    std::printf("| sequence | descriptor |");
    for (int n : offsets)
        std::printf(" N = %d |", n);
    std::printf(" mean | detect+describe ms/image | matching ms/pair |\n|---|---|");
    for (size_t i = 0; i <= offsets.size() + 2; ++i)
        std::printf("---|");
    std::printf("\n");

    for (const std::string& seq : sequences) {
        const std::string dir = data + "/" + seq;
        cv::Matx33d K;
        std::vector<Pose> poses;
        if (!readSequence(dir, K, poses) || poses.size() < 2) {
            std::fprintf(stderr, "cannot read %s/{camera,poses}.txt\n", dir.c_str());
            return 1;
        }
        const int frames = static_cast<int>(poses.size());
        std::map<int, cv::Mat> images;
        for (const std::string& name : descriptors) {
            essential_samples::FrontEndParams params;
            if (!essential_samples::parseDescriptor(name, params.descriptor)) {
                std::fprintf(stderr, "unknown descriptor %s\n", name.c_str());
                return 2;
            }
            std::map<int, essential_samples::Features> features;
            double detectMs = 0, matchMs = 0;
            int detections = 0, matchings = 0;
            auto featuresOf = [&](int k) -> const essential_samples::Features& {
                auto it = features.find(k);
                if (it == features.end()) {
                    cv::Mat& image = images[k];
                    if (image.empty()) image = cv::imread(framePath(dir, k), cv::IMREAD_GRAYSCALE);
                    if (image.empty()) {
                        std::fprintf(stderr, "cannot read %s\n", framePath(dir, k).c_str());
                        std::exit(1);
                    }
                    const auto t0 = std::chrono::steady_clock::now();
                    it = features.emplace(k, essential_samples::detectAndDescribe(image, params))
                             .first;
                    detectMs += msSince(t0);
                    ++detections;
                }
                return it->second;
            };
            std::printf("| %s | %s |", seq.c_str(), name.c_str());
            double rateSum = 0;
            for (int offset : offsets) {
                double rate = 0, good = 0;
                int counted = 0;
                for (int p = 0; p < pairs; ++p) {
                    // pairs spread over the sequence
                    const int i = (frames - 1 - offset) * p / std::max(1, pairs - 1);
                    const int j = i + offset;
                    if (i < 0 || j >= frames) continue;
                    if (p > 0 && i == (frames - 1 - offset) * (p - 1) / std::max(1, pairs - 1))
                        continue; // the same pair again (few frames left)
                    const auto& f1 = featuresOf(i);
                    const auto& f2 = featuresOf(j);
                    const auto t0 = std::chrono::steady_clock::now();
                    const auto matches = essential_samples::matchFeatures(f1, f2, params);
                    matchMs += msSince(t0);
                    ++matchings;
                    const cv::Matx33d F = trueFundamental(K, poses[i], poses[j]);
                    int inliers = 0;
                    for (size_t m = 0; m < matches.points1.size(); ++m)
                        inliers += sampsonPx(F, matches.points1[m], matches.points2[m]) < threshold;
                    rate +=
                        matches.points1.empty() ? 0.0 : double(inliers) / matches.points1.size();
                    good += inliers;
                    ++counted;
                }
                rate /= std::max(1, counted);
                rateSum += rate;
                std::printf(" %.3f (%.0f) |", rate, good / std::max(1, counted));
                std::fflush(stdout);
            }
            std::printf(" %.3f | %.1f | %.1f |\n", rateSum / offsets.size(),
                        detectMs / std::max(1, detections), matchMs / std::max(1, matchings));
        }
    }
    return 0;
}

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The PoseLib comparison of docs/ACCURACY.md on real images: the rail-a sequences (camera on a
// rail, exact poses) and the Middlebury Aloe stereo pair (rectified: R = I, t along -x). Matches
// come from the sample front end (FAST-9, upright BRIEF, best 20%); both estimators get the same
// matches in the same order, run in a random order per pair, thread CPU time.
//
//   essential_compare_poselib_real [--rail DIR] [--offsets 1,2,5,10,20,40,60] [--frames-step 5]
//                                  [--aloe DIR] [--aloe-runs 50] [--threshold 1]
//                                  [--max-iters 1000] [--poselib-max-iters 10000]
//
// --rail DIR holds horizontal/ and optic/ (rail-a layout); --aloe DIR holds aloeL.jpg, aloeR.jpg.
// For Aloe the focal length is Middlebury's 3740 px (2006 datasets, full size) and the principal
// point the image centre: for a rectified pair the true pose does not depend on them. The one pair
// is estimated --aloe-runs times, the matches shuffled differently each time.

#include "bench_common.hpp"
#include "bench_options.hpp"
#include "pose_accuracy.hpp"
#include "poselib_runner.hpp"

#include "frontend/frontend.hpp"
#include "frontend/sequence_io.hpp"

#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <string>
#include <vector>

using namespace essential_bench;

namespace {

struct Args
{
    std::string rail, aloe;
    std::vector<double> offsets = {1, 2, 5, 10, 20, 40, 60};
    int framesStep = 5;
    int aloeRuns = 50;
    double threshold = 1.0;
    int maxIters = 1000;
    int poselibMaxIters = 10000;
};

Args parse(int argc, char** argv)
{
    Args a;
    Options opts("essential_compare_poselib_real");
    opts.add("rail", a.rail);
    opts.add("aloe", a.aloe);
    opts.add("offsets", a.offsets);
    opts.add("threshold", a.threshold);
    opts.add("max-iters", a.maxIters);
    opts.add("poselib-max-iters", a.poselibMaxIters);
    opts.add("frames-step", a.framesStep);
    opts.add("aloe-runs", a.aloeRuns);
    opts.parse(argc, argv);
    a.framesStep = std::max(1, a.framesStep);
    a.aloeRuns = std::max(1, a.aloeRuns);
    if (a.rail.empty() && a.aloe.empty()) {
        std::fprintf(stderr, "give --rail DIR and/or --aloe DIR\n");
        std::exit(2);
    }
    return a;
}

/** Both methods on one set of matches, in a random order; appends their outcomes. */
void runBoth(const essential_samples::Matches& m, const cv::Matx33d& K, const cv::Matx33d& trueR,
             const cv::Vec3d& trueT, const Args& args, std::mt19937_64& order,
             std::vector<PoseOutcome>& ours, std::vector<PoseOutcome>& theirs)
{
    PoseEstimate a, b;
    if (order() & 1) {
        a = runOurs(m.points1, m.points2, K, args.threshold, args.maxIters);
        b = runPoseLib(m.points1, m.points2, K, args.threshold, args.poselibMaxIters);
    } else {
        b = runPoseLib(m.points1, m.points2, K, args.threshold, args.poselibMaxIters);
        a = runOurs(m.points1, m.points2, K, args.threshold, args.maxIters);
    }
    ours.push_back(outcomeOf(a, trueR, trueT));
    theirs.push_back(outcomeOf(b, trueR, trueT));
}

void printRows(const std::string& set, const std::vector<PoseOutcome>& ours,
               const std::vector<PoseOutcome>& theirs)
{
    const AccuracySummary so = summarise(ours), sp = summarise(theirs);
    const AccuracySummary* rows[2] = {&so, &sp};
    const char* names[2] = {"findEssentialMatIter + recoverPose", "PoseLib estimate_relative_pose"};
    for (int m = 0; m < 2; ++m) {
        const AccuracySummary& r = *rows[m];
        std::printf("| %s | %zu | %s | %.3f | %.3f | %.3f | %.3f | %.3f | %.4f | %.3f | %.2fx |\n",
                    set.c_str(), ours.size(), names[m], r.auc1, r.auc5, r.auc10, r.reliableStrict,
                    r.reliableLoose, r.medianError, r.medianMs, r.medianMs / so.medianMs);
    }
    std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv)
{
    const Args args = parse(argc, argv);
    cv::setNumThreads(1);
    std::printf("threshold %.2f px, maxIters %d (ours) / %d (PoseLib), one thread, thread CPU "
                "time; %s\n\n",
                args.threshold, args.maxIters, args.poselibMaxIters, poselib_info().c_str());
    std::printf(
        "| set | estimates | method | AUC@1 | AUC@5 | AUC@10 | reliable 1/3 | reliable 2/5 | "
        "median err deg | median CPU ms | time / ours |\n|---|---|---|---|---|---|---|---|"
        "---|---|---|\n");
    std::mt19937_64 order(0x5eedULL);
    const essential_samples::FrontEndParams fe;

    if (!args.rail.empty()) {
        for (const std::string seq : {"horizontal", "optic"}) {
            const std::string dir = args.rail + "/" + seq;
            cv::Matx33d K;
            std::vector<essential_samples::Pose> poses;
            if (!essential_samples::readSequence(dir, K, poses)) {
                std::fprintf(stderr, "cannot read %s\n", dir.c_str());
                return 1;
            }
            std::map<int, essential_samples::Features> features;
            auto featuresOf = [&](int k) -> const essential_samples::Features& {
                auto it = features.find(k);
                if (it == features.end()) {
                    const cv::Mat image =
                        cv::imread(essential_samples::framePath(dir, k), cv::IMREAD_GRAYSCALE);
                    it = features.emplace(k, essential_samples::detectAndDescribe(image, fe)).first;
                }
                return it->second;
            };
            std::vector<PoseOutcome> allOurs, allTheirs;
            for (double offsetValue : args.offsets) {
                const int offset = static_cast<int>(offsetValue);
                std::vector<PoseOutcome> ours, theirs;
                for (int k = 0; k + offset < static_cast<int>(poses.size()); k += args.framesStep) {
                    const essential_samples::Matches m =
                        essential_samples::matchFeatures(featuresOf(k), featuresOf(k + offset), fe);
                    const cv::Matx33d R =
                        essential_samples::relativeRotation(poses[k], poses[k + offset]);
                    const cv::Vec3d t =
                        essential_samples::relativeTranslation(poses[k], poses[k + offset]);
                    runBoth(m, K, R, t, args, order, ours, theirs);
                }
                printRows("rail-a " + seq + ", offset " + std::to_string(offset), ours, theirs);
                allOurs.insert(allOurs.end(), ours.begin(), ours.end());
                allTheirs.insert(allTheirs.end(), theirs.begin(), theirs.end());
            }
            printRows("rail-a " + seq + ", all offsets", allOurs, allTheirs);
        }
    }

    if (!args.aloe.empty()) {
        const cv::Mat left = cv::imread(args.aloe + "/aloeL.jpg", cv::IMREAD_GRAYSCALE);
        const cv::Mat right = cv::imread(args.aloe + "/aloeR.jpg", cv::IMREAD_GRAYSCALE);
        if (left.empty() || right.empty()) {
            std::fprintf(stderr, "cannot read %s/aloeL.jpg, aloeR.jpg\n", args.aloe.c_str());
            return 1;
        }
        const double f = 3740.0;
        const cv::Matx33d K(f, 0, 0.5 * (left.cols - 1), 0, f, 0.5 * (left.rows - 1), 0, 0, 1);
        const essential_samples::Matches base =
            essential_samples::matchFeatures(essential_samples::detectAndDescribe(left, fe),
                                             essential_samples::detectAndDescribe(right, fe), fe);
        std::vector<PoseOutcome> ours, theirs;
        for (int run = 0; run < args.aloeRuns; ++run) {
            essential_samples::Matches m = base;
            std::vector<size_t> idx(m.points1.size());
            for (size_t i = 0; i < idx.size(); ++i)
                idx[i] = i;
            std::shuffle(idx.begin(), idx.end(), std::mt19937_64(1000 + run));
            for (size_t i = 0; i < idx.size(); ++i) {
                m.points1[i] = base.points1[idx[i]];
                m.points2[i] = base.points2[idx[i]];
            }
            // The right camera sits to the right of the left one: X_right = X_left - b e_x.
            runBoth(m, K, cv::Matx33d::eye(), cv::Vec3d(-1, 0, 0), args, order, ours, theirs);
        }
        printRows("Aloe (" + std::to_string(base.points1.size()) + " matches)", ours, theirs);
    }
    return 0;
}

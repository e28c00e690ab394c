// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Pose accuracy and time of the drop-in call against PoseLib's estimate_relative_pose, in one
// process, on the same problems (docs/ACCURACY.md). Built only when find_package(PoseLib CONFIG)
// finds PoseLib (scripts/build_poselib.sh builds it outside the source tree).
//
//   essential_compare_poselib [--n 500] [--ratios 0.9,0.7,0.5] [--problems 100]
//                             [--max-iters 1000] [--poselib-max-iters 10000]
//                             [--camera paper|wide] [--threshold PX] [--seed 1] [--csv FILE]
//
// Per problem the two methods (bench/poselib_runner.hpp: the drop-in pair, and PoseLib with
// min_iterations 0 and the given cap) run in a random order, so that the machine's load falls on
// both alike, each timed by the thread's CPU clock.
// Error of an estimate: max(rotation error, translation direction error) in degrees (180 for a
// failure); AUC@1/5/10 degrees of it; reliable: rotation < 2 and translation < 5 degrees (in the
// 1/3 column: < 1 and < 3).

#include "synthetic_scene.hpp"

#include "bench_common.hpp"
#include "bench_options.hpp"
#include "pose_accuracy.hpp"
#include "poselib_runner.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>
#include <vector>

using namespace essential_bench;

namespace {

struct Args
{
    int n = 500;
    std::vector<double> ratios = {0.9, 0.7, 0.5};
    int problems = 100;
    int maxIters = 1000;
    int poselibMaxIters = 10000;
    std::string camera = "paper";
    double threshold = 1.0;
    uint64_t seed = 1;
    std::string csv;
};

Args parse(int argc, char** argv)
{
    Args a;
    Options opts("essential_compare_poselib");
    opts.add("n", a.n);
    opts.add("problems", a.problems);
    opts.add("max-iters", a.maxIters);
    opts.add("poselib-max-iters", a.poselibMaxIters);
    opts.add("camera", a.camera);
    opts.add("threshold", a.threshold);
    opts.add("seed", a.seed);
    opts.add("csv", a.csv);
    opts.add("ratios", a.ratios);
    opts.parse(argc, argv);
    if (a.camera != "paper" && a.camera != "wide") {
        std::fprintf(stderr, "--camera must be paper or wide\n");
        std::exit(2);
    }
    return a;
}

} // namespace

int main(int argc, char** argv)
{
    const Args args = parse(argc, argv);
    cv::setNumThreads(1);
    const bool wide = args.camera == "wide";
    std::printf("camera %s, N = %d, %d problems per ratio, threshold %.2f px, maxIters %d (ours) / "
                "%d (PoseLib), one thread, thread CPU time; %s\n\n",
                args.camera.c_str(), args.n, args.problems, args.threshold, args.maxIters,
                args.poselibMaxIters, poselib_info().c_str());
    std::printf(
        "| inliers | method | AUC@1 | AUC@5 | AUC@10 | reliable 1/3 | reliable 2/5 | median "
        "err deg | median CPU ms | time / ours |\n|---|---|---|---|---|---|---|---|---|---|\n");
    std::ofstream csv;
    if (!args.csv.empty()) {
        csv.open(args.csv);
        csv << "camera,n,ratio,problem,baseline,method,rot_err,trans_err,ms\n";
    }
    std::mt19937_64 order(args.seed ^ 0x5eedULL);
    for (double ratio : args.ratios) {
        std::vector<PoseOutcome> ours, theirs;
        for (int p = 0; p < args.problems; ++p) {
            essential_test::SceneConfig cfg =
                wide ? essential_test::wideCameraConfig() : essential_test::SceneConfig();
            cfg.numPoints = args.n;
            cfg.inlierRatio = ratio;
            const auto s = essential_test::makeScene(cfg, args.seed * 1000003ULL + p);
            PoseEstimate ea, eb;
            if (order() & 1) {
                ea = runOurs(s.px1, s.px2, s.K, args.threshold, args.maxIters);
                eb = runPoseLib(s.px1, s.px2, s.K, args.threshold, args.poselibMaxIters);
            } else {
                eb = runPoseLib(s.px1, s.px2, s.K, args.threshold, args.poselibMaxIters);
                ea = runOurs(s.px1, s.px2, s.K, args.threshold, args.maxIters);
            }
            const PoseOutcome a = outcomeOf(ea, s.R, s.t), b = outcomeOf(eb, s.R, s.t);
            ours.push_back(a);
            theirs.push_back(b);
            if (csv.is_open()) {
                for (int m = 0; m < 2; ++m) {
                    const PoseOutcome& o = m == 0 ? a : b;
                    csv << args.camera << ',' << args.n << ',' << ratio << ',' << p << ','
                        << s.baseline << ',' << (m == 0 ? "ours" : "poselib") << ',' << o.rotErr
                        << ',' << o.transErr << ',' << o.ms << '\n';
                }
            }
        }
        const AccuracySummary so = summarise(ours), sp = summarise(theirs);
        const AccuracySummary* rows[2] = {&so, &sp};
        const char* names[2] = {"findEssentialMatIter + recoverPose",
                                "PoseLib estimate_relative_pose"};
        for (int m = 0; m < 2; ++m) {
            const AccuracySummary& r = *rows[m];
            std::printf(
                "| %.0f%% | %s | %.3f | %.3f | %.3f | %.3f | %.3f | %.4f | %.3f | %.2fx |\n",
                100 * ratio, names[m], r.auc1, r.auc5, r.auc10, r.reliableStrict, r.reliableLoose,
                r.medianError, r.medianMs, r.medianMs / so.medianMs);
        }
        std::fflush(stdout);
    }
    return 0;
}

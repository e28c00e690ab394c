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
// Per problem the two methods run in a random order (so that a shared machine's load falls on
// both alike), each timed by the thread's CPU clock:
//  - ours: cv::essential::findEssentialMatIter(points, K, RANSAC, 0.999, threshold, maxIters, mask)
//    then cv::essential::recoverPose(E, points, K, R, t, mask) (the drop-in pair, pixels in);
//  - PoseLib: poselib::estimate_relative_pose on the same pixels with a pinhole camera, RANSAC
//    min_iterations 0, max_iterations --poselib-max-iters, max_error = threshold (px), all else
//    PoseLib's defaults (success probability 0.9999, 3x the dynamic trial count, LO by 25 LM
//    iterations with a truncated loss, final LM with a Cauchy loss on the inliers).
// Error of an estimate: max(rotation error, translation direction error) in degrees (180 for a
// failure); AUC@1/5/10 degrees of it; reliable: rotation < 2 and translation < 5 degrees (in the
// 1/3 column: < 1 and < 3).

#include "synthetic_scene.hpp"

#include "bench_common.hpp"
#include "pose_accuracy.hpp"

#include <PoseLib/poselib.h>

#include <opencv2/calib3d.hpp>
#include <opencv2/essential.hpp>

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
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string k = argv[i], v = argv[i + 1];
        if (k == "--n")
            a.n = std::atoi(v.c_str());
        else if (k == "--problems")
            a.problems = std::atoi(v.c_str());
        else if (k == "--max-iters")
            a.maxIters = std::atoi(v.c_str());
        else if (k == "--poselib-max-iters")
            a.poselibMaxIters = std::atoi(v.c_str());
        else if (k == "--camera")
            a.camera = v;
        else if (k == "--threshold")
            a.threshold = std::atof(v.c_str());
        else if (k == "--seed")
            a.seed = std::strtoull(v.c_str(), nullptr, 10);
        else if (k == "--csv")
            a.csv = v;
        else if (k == "--ratios")
            a.ratios = numbers(v);
        else {
            std::fprintf(stderr, "unknown option %s\n", k.c_str());
            std::exit(2);
        }
    }
    if (a.camera != "paper" && a.camera != "wide") {
        std::fprintf(stderr, "--camera must be paper or wide\n");
        std::exit(2);
    }
    return a;
}

PoseOutcome runOurs(const essential_test::SyntheticScene& s, const Args& args)
{
    PoseOutcome o;
    const cv::Mat K(s.K);
    const double t0 = threadCpuMs();
    cv::Mat mask, R, t;
    const cv::Mat E = cv::essential::findEssentialMatIter(s.px1, s.px2, K, cv::RANSAC, 0.999,
                                                          args.threshold, args.maxIters, mask);
    int inFront = 0;
    if (E.rows == 3 && E.cols == 3)
        inFront = cv::essential::recoverPose(E, s.px1, s.px2, K, R, t, mask);
    o.ms = threadCpuMs() - t0;
    if (inFront > 0) {
        o.rotErr = essential_test::rotationErrorDeg(cv::Matx33d(R), s.R);
        o.transErr = essential_test::translationErrorDeg(cv::Vec3d(t), s.t);
    }
    return o;
}

PoseOutcome runPoseLib(const essential_test::SyntheticScene& s, const Args& args)
{
    PoseOutcome o;
    const double t0 = threadCpuMs();
    std::vector<Eigen::Vector2d> a(s.px1.size()), b(s.px2.size());
    for (size_t i = 0; i < a.size(); ++i) {
        a[i] = Eigen::Vector2d(s.px1[i].x, s.px1[i].y);
        b[i] = Eigen::Vector2d(s.px2[i].x, s.px2[i].y);
    }
    const std::vector<double> params = {s.K(0, 0), s.K(1, 1), s.K(0, 2), s.K(1, 2)};
    const poselib::Camera camera("PINHOLE", params);
    poselib::RelativePoseOptions opt;
    opt.ransac.min_iterations = 0;
    opt.ransac.max_iterations = static_cast<size_t>(args.poselibMaxIters);
    opt.max_error = args.threshold;
    poselib::CameraPose pose;
    std::vector<char> inliers;
    const poselib::RansacStats stats =
        poselib::estimate_relative_pose(a, b, camera, camera, opt, &pose, &inliers);
    o.ms = threadCpuMs() - t0;
    if (stats.num_inliers >= 5) {
        const Eigen::Matrix3d R = pose.R();
        cv::Matx33d Rm;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                Rm(i, j) = R(i, j);
        o.rotErr = essential_test::rotationErrorDeg(Rm, s.R);
        o.transErr =
            essential_test::translationErrorDeg(cv::Vec3d(pose.t.x(), pose.t.y(), pose.t.z()), s.t);
    }
    return o;
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
            PoseOutcome a, b;
            if (order() & 1) {
                a = runOurs(s, args);
                b = runPoseLib(s, args);
            } else {
                b = runPoseLib(s, args);
                a = runOurs(s, args);
            }
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

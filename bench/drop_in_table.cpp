// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The accept/reject table of point layouts (docs/ROBUSTNESS.md, "Point layouts"): each layout of
// test/drop_in_layouts.hpp through each of OpenCV 4.6's code paths, once with cv::findEssentialMat
// or cv::recoverPose and once with the module's drop-in, on 50 outlier-free correspondences.
// Prints a markdown table; a cell says "yes" (both accept), "no" (both reject), or which one
// accepts when they differ. Exit code 1 if any cell differs.
//
// Usage: essential_drop_in_table

#include "drop_in_layouts.hpp"
#include "synthetic_scene.hpp"

#include <opencv2/essential.hpp>

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace {

using essential_test::kLayouts;
using essential_test::PointArray;

struct Path
{
    const char* name;
    /** Calls OpenCV (ours = false) or the module through this code path. */
    std::function<void(bool ours, const PointArray& a, const PointArray& b)> call;
};

bool accepts(const Path& path, bool ours, const PointArray& a, const PointArray& b)
{
    try {
        path.call(ours, a, b);
        return true;
    } catch (const cv::Exception&) {
        return false;
    }
}

} // namespace

int main()
{
    cv::redirectError([](int, const char*, const char*, const char*, int, void*) { return 0; });
    essential_test::SceneConfig cfg;
    cfg.numPoints = 50;
    cfg.inlierRatio = 1.0;
    cfg.noiseSigma = 1e-7;
    cfg.maxDepth = 20.0;
    const essential_test::SyntheticScene s = essential_test::makeScene(cfg, 2024);
    const cv::Mat K(s.K), E(s.E), zeros = cv::Mat::zeros(5, 1, CV_64F);
    namespace ess = cv::essential;
    const std::vector<Path> paths = {
        {"RANSAC, LMEDS",
         [&](bool ours, const PointArray& a, const PointArray& b) {
             cv::Mat m;
             ours ? ess::findEssentialMatIter(a.arr(), b.arr(), K, cv::RANSAC, 0.999, 1.0, 100, m)
                  : cv::findEssentialMat(a.arr(), b.arr(), K, cv::RANSAC, 0.999, 1.0, 100, m);
         }},
        {"USAC flags",
         [&](bool ours, const PointArray& a, const PointArray& b) {
             cv::Mat m;
             ours ? ess::findEssentialMatIter(a.arr(), b.arr(), K, cv::USAC_DEFAULT, 0.999, 1.0,
                                              100, m)
                  : cv::findEssentialMat(a.arr(), b.arr(), K, cv::USAC_DEFAULT, 0.999, 1.0, 100, m);
         }},
        {"K1, d1, K2, d2 form",
         [&](bool ours, const PointArray& a, const PointArray& b) {
             cv::Mat m;
             ours ? ess::findEssentialMatIter(a.arr(), b.arr(), K, zeros, K, zeros, cv::RANSAC,
                                              0.999, 1.0, m)
                  : cv::findEssentialMat(a.arr(), b.arr(), K, zeros, K, zeros, cv::RANSAC, 0.999,
                                         1.0, m);
         }},
        {"UsacParams",
         [&](bool ours, const PointArray& a, const PointArray& b) {
             cv::Mat m;
             cv::UsacParams u;
             ours
                 ? ess::findEssentialMatIter(a.arr(), b.arr(), K, K, cv::noArray(), cv::noArray(),
                                             m, u)
                 : cv::findEssentialMat(a.arr(), b.arr(), K, K, cv::noArray(), cv::noArray(), m, u);
         }},
        {"UsacParams + distortion",
         [&](bool ours, const PointArray& a, const PointArray& b) {
             cv::Mat m;
             cv::UsacParams u;
             ours ? ess::findEssentialMatIter(a.arr(), b.arr(), K, K, zeros, zeros, m, u)
                  : cv::findEssentialMat(a.arr(), b.arr(), K, K, zeros, zeros, m, u);
         }},
        {"recoverPose from E",
         [&](bool ours, const PointArray& a, const PointArray& b) {
             cv::Mat R, t;
             ours ? ess::recoverPoseIter(E, a.arr(), b.arr(), K, R, t)
                  : cv::recoverPose(E, a.arr(), b.arr(), K, R, t);
         }},
        {"recoverPose, two cameras",
         [&](bool ours, const PointArray& a, const PointArray& b) {
             cv::Mat Eo, R, t;
             ours ? ess::recoverPoseIter(a.arr(), b.arr(), K, zeros, K, zeros, Eo, R, t)
                  : cv::recoverPose(a.arr(), b.arr(), K, zeros, K, zeros, Eo, R, t);
         }},
    };
    std::printf("| layout |");
    for (const Path& p : paths)
        std::printf(" %s |", p.name);
    std::printf("\n|---|");
    for (size_t i = 0; i < paths.size(); ++i)
        std::printf("---|");
    std::printf("\n");
    int differing = 0;
    for (const auto& layout : kLayouts) {
        const PointArray a = layout.make(s.px1), b = layout.make(s.px2);
        std::printf("| %s |", layout.name);
        for (const Path& p : paths) {
            const bool cv = accepts(p, false, a, b), us = accepts(p, true, a, b);
            differing += cv != us;
            std::printf(" %s |",
                        cv == us ? (cv ? "yes" : "no") : (cv ? "OpenCV only" : "ours only"));
        }
        std::printf("\n");
    }
    std::printf("\n%d of %zu cells differ\n", differing, paths.size() * std::size(kLayouts));
    return differing == 0 ? 0 : 1;
}

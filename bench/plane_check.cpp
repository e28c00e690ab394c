// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The plane-and-parallax check on its own (src/degeneracy/plane_parallax.hpp): dominant-plane
// scenes (test/hard_scenes.hpp), the winner of a search without the check (the module's own
// overload with planeParallax and refine off), then the check; counts the winners it turns right
// ("fix"), wrong ("harm") or leaves as they were. The numbers behind kSignificance and kMemberBand.
//
//   essential_plane_check [--problems 30] [--ratios 0.10,0.15,0.25] [--plane-fraction 0.8]

#include "bench_common.hpp"
#include "bench_options.hpp"
#include "degeneracy/plane_parallax.hpp"
#include "hard_scenes.hpp"
#include "input/problem.hpp"
#include "scoring/msac_score.hpp"

#include <opencv2/essential.hpp>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

bool right(const cv::Matx33d& E, const essential_test::HardScene& s)
{
    std::vector<cv::Point2d> a, b;
    for (size_t i = 0; i < s.x1.size(); ++i)
        if (s.inlier[i]) {
            a.push_back(s.x1[i]);
            b.push_back(s.x2[i]);
        }
    cv::Mat R, t;
    cv::essential::recoverPoseIter(cv::Mat(E), a, b, cv::Mat::eye(3, 3, CV_64F), R, t);
    return essential_test::rotationErrorDeg(cv::Matx33d(R), s.R) < 5.0 &&
           essential_test::translationErrorDeg(cv::Vec3d(t), s.t) < 10.0;
}

} // namespace

int main(int argc, char** argv)
{
    int problems = 30;
    std::vector<double> ratios = {0.10, 0.15, 0.25};
    double planeFraction = 0.8;
    essential_bench::Options opts("essential_plane_check");
    opts.add("problems", problems);
    opts.add("ratios", ratios);
    opts.add("plane-fraction", planeFraction);
    opts.parse(argc, argv);
    std::printf(
        "| inliers | scenes | planes found | replaced | fix (wrong -> right) | harm (right -> "
        "wrong) | right before | right after |\n|---|---|---|---|---|---|---|---|\n");
    for (double ratio : ratios) {
        int found = 0, replaced = 0, fix = 0, harm = 0, before = 0, after = 0;
        for (int k = 0; k < problems; ++k) {
            essential_test::DominantPlaneConfig cfg;
            cfg.inlierRatio = ratio;
            cfg.planeFraction = planeFraction;
            const essential_test::HardScene s = essential_test::makeDominantPlane(cfg, k + 1);
            cv::essential::EssentialParams params;
            params.planeParallax = false;
            params.refine = false;
            params.seed = static_cast<uint64>(k);
            cv::Mat mask;
            const cv::Mat E = cv::essential::findEssentialMatIter(s.px1, s.px2, s.K, params, mask);
            if (E.empty()) continue;
            const double f = 0.5 * (s.K(0, 0) + s.K(1, 1));
            const cv::essential::Problem problem = cv::essential::makeProblem(s.x1, s.x2);
            const cv::essential::InlierTest test{1.0 / f};
            const cv::Matx33d Em(E);
            const cv::essential::scoring::Score score =
                cv::essential::scoring::scoreMsac(Em, problem, test);
            cv::RNG rng(static_cast<uint64>(k));
            const cv::essential::degeneracy::PlaneParallaxResult r =
                cv::essential::degeneracy::checkPlaneAndParallax(problem, test, Em, score, rng);
            const bool r0 = right(Em, s), r1 = r.improved ? right(r.E, s) : r0;
            found += r.planeFound;
            replaced += r.improved;
            fix += !r0 && r1;
            harm += r0 && !r1;
            before += r0;
            after += r1;
        }
        std::printf("| %.2f | %d | %d | %d | %d | %d | %d | %d |\n", ratio, problems, found,
                    replaced, fix, harm, before, after);
    }
    return 0;
}

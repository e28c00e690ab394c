// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "refine/final_refinement.hpp"

#include "pose/pose_recovery.hpp"
#include "ransac/msac_score.hpp"

#include <vector>

namespace cv {
namespace essential {
namespace refine {

/** IRLS fits the five degrees of freedom of E: fewer points leave it undetermined. */
constexpr int kMinPoints = 5;

FinalRefinementResult refineFinal(const Problem& problem, const Matx33d& E0, double threshold,
                                  const FinalRefinementSettings& settings)
{
    FinalRefinementResult result;
    result.E = E0;
    const int n = problem.size();
    std::vector<uchar> use(static_cast<size_t>(n));
    int count = ransac::inlierMask(E0, problem, settings.band * threshold, use.data());
    if (settings.inFrontOnly && count >= kMinPoints) {
        pose::PoseResult pose;
        // Writes the in-front test into `use` in place; an E0 with no decomposition keeps the
        // band's points (it cannot happen for a search winner, which has one).
        std::vector<uchar> inFront(use);
        if (pose::recoverPoseNormalised(E0, problem.p1.data(), problem.p2.data(), n, use.data(),
                                        inFront.data(), pose)) {
            use.swap(inFront);
            count = pose.inFront;
        }
    }
    if (count < kMinPoints) return result;
    std::vector<Point2d> a, b;
    a.reserve(static_cast<size_t>(count));
    b.reserve(static_cast<size_t>(count));
    for (int i = 0; i < n; ++i)
        if (use[i]) {
            a.push_back(problem.p1[i]);
            b.push_back(problem.p2[i]);
        }
    const Problem selected = makeProblem(std::move(a), std::move(b), threshold);
    const IrlsResult refined =
        refineIrls(selected, E0, settings.scaleInThresholds * threshold, settings.irls);
    result.E = refined.E;
    result.iterations = refined.iterations;
    result.pointsUsed = count;
    result.improved = refined.improved;
    return result;
}

} // namespace refine
} // namespace essential
} // namespace cv

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "solvers/iterative_minimal_solver.hpp"

namespace cv {
namespace essential {
namespace solvers {

namespace {

/** Optimises `pose` on the sample; true when it converged to an exact solution that, with
requireCheirality, puts the sample in front of the cameras. */
ESSENTIAL_INLINE_INTO_CLONES bool converges(geometry::EssentialPose& pose, const Point2d* x1,
                                            const Point2d* x2, const StartPolicy& policy,
                                            const optim::LmSettings& optimiser, StartCounts& counts)
{
    const MinimalSetModel model{x1, x2};
    optim::SquareSystem system;
    const optim::LmResult result = optim::minimise(model, pose, system, optimiser);
    counts.iterations += optimiser.damping.initial == 0.0 ? result.iterations : result.trials;
    return result.status == optim::LmStatus::Converged &&
           (!policy.requireCheirality || sampleIsInFront(pose, x1, x2, 5));
}

} // namespace

ESSENTIAL_FLATTEN ESSENTIAL_SIMD_CLONES int solveFromStarts(const Point2d* x1, const Point2d* x2,
                                                            const StartPolicy& policy,
                                                            const optim::LmSettings& optimiser,
                                                            StartCounts& counts, Matx33d* solutions)
{
    counts = StartCounts();
    if (constraintsAreDependent(x1, x2)) return 0;
    counts.starts = 1;
    geometry::EssentialPose pose = bestTranslationStart(x1, x2, 5, Eigen::Matrix3d::Identity());
    if (converges(pose, x1, x2, policy, optimiser, counts)) return writeSolution(pose, solutions);
    if (policy.extraStarts <= 0) return 0;
    StartRanking ranking;
    ranking.rank(x1, x2);
    for (int k = 0, tried = 0; k < kRankedStarts && tried < policy.extraStarts; ++k) {
        const int next = ranking.takeNext();
        if (next < 0) break;
        pose = bestTranslationStart(x1, x2, 5, StartRotations::instance()[next]);
        // A start that cannot put the sample in front of the cameras rarely leads to a root that
        // can: skipping it costs one depth test instead of an optimisation.
        if (policy.requireCheirality && !sampleIsInFront(pose, x1, x2, 5)) continue;
        ++tried;
        ++counts.starts;
        if (converges(pose, x1, x2, policy, optimiser, counts))
            return writeSolution(pose, solutions);
    }
    return 0;
}

} // namespace solvers
} // namespace essential
} // namespace cv

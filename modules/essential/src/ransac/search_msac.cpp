// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "ransac/msac_score.hpp"
#include "ransac/sample_buffer.hpp"
#include "ransac/search.hpp"
#include "ransac/termination.hpp"

namespace cv {
namespace essential {
namespace ransac {

SearchResult searchMsac(const Problem& problem, EssentialSolver& solver, RNG& rng,
                        const SearchSettings& settings)
{
    SearchResult result;
    result.threshold = problem.threshold;
    const int n = problem.size();
    SampleBuffer buffer(solver);
    if (n < buffer.sampleSize) return result;

    Score best;
    const int cap = sampleCap(settings.maxIters, solver.successRate());
    int needed = cap;
    while (result.iterations < needed) {
        if ((result.iterations & 7) == 7 && settings.deadline.passed()) break;
        ++result.iterations;
        const int count = buffer.drawAndSolve(problem, solver, rng);
        ++result.hypothesesGenerated;
        result.hypothesesConverged += count;
        for (int h = 0; h < count; ++h) {
            ++result.hypothesesScored;
            const Score s = scoreMsac(buffer.solutions[h], problem, best.cost);
            if (s.cost < best.cost && s.inliers >= buffer.sampleSize) {
                best = s;
                result.E = buffer.solutions[h];
                result.found = true;
                needed = requiredIterations(settings.confidence,
                                            solver.hitProbability(double(s.inliers) / n), cap);
            }
        }
    }
    result.inliers = best.inliers;
    return result;
}

} // namespace ransac
} // namespace essential
} // namespace cv

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#ifndef OPENCV_ESSENTIAL_SAMPLING_SAMPLE_BUFFER_HPP
#define OPENCV_ESSENTIAL_SAMPLING_SAMPLE_BUFFER_HPP

#include "input/problem.hpp"
#include "opencv2/essential/solver.hpp"
#include "sampling/napsac_sampler.hpp"
#include "sampling/prosac_sampler.hpp"
#include "sampling/uniform_sampler.hpp"
#include "solvers/sample_cheirality.hpp"

#include <vector>

namespace cv {
namespace essential {
namespace sampling {

/** The storage of one search loop, allocated once before it so the loop itself allocates nothing:
sample indices, the sampled points and room for the solver's solutions. */
struct SampleBuffer
{
    int sampleSize;
    std::vector<int> indices;
    std::vector<Point2d> x1, x2;
    std::vector<Matx33d> solutions;
    /** When set, samples come from this PROSAC sampler (points sorted best first) instead of being
    uniform. Not owned. */
    ProsacSampler* prosac = nullptr;
    /** When set, every `localEvery`-th sample (1: all) is a spatially local one from this sampler,
    the others uniform or PROSAC's; a seed without enough neighbours falls back to those. Not
    owned. */
    NapsacSampler* napsac = nullptr;
    int localEvery = 1;
    int drawn = 0;
    /** Keep only the solutions that put the sample in front of both cameras: when asked
    (SearchSettings::sampleCheirality) and the sample is minimal. Only a minimal sample can be
    expected to be all inliers; the larger samples of robust solvers hold outliers by design, whose
    depth signs say nothing about the model. */
    bool requireInFront;

    SampleBuffer(const EssentialSolver& solver, bool checkCheirality)
        : sampleSize(solver.sampleSize()), indices(static_cast<size_t>(sampleSize)),
          x1(static_cast<size_t>(sampleSize)), x2(static_cast<size_t>(sampleSize)),
          solutions(static_cast<size_t>(solver.maxSolutions())),
          requireInFront(checkCheirality && checksCheirality(solver))
    {
    }

    /** Whether the searches check cheirality on this solver's samples when asked: only on minimal
    (5-point) ones. */
    static bool checksCheirality(const EssentialSolver& solver) { return solver.sampleSize() == 5; }

    /** Draws a sample (uniform, or PROSAC's) and runs the solver on it; returns the number of
    solutions that put the sample in front of both cameras (solvers::essentialSampleIsInFront),
    moved to the front of `solutions`. A sample with two coincident points in either view is
    degenerate (it constrains E less than its size says, and all-identical input would otherwise
    "fit" anything): it is not solved. */
    int drawAndSolve(const Problem& problem, EssentialSolver& solver, RNG& rng)
    {
        const bool local =
            napsac && (drawn++ % localEvery) == 0 && napsac->draw(rng, indices.data());
        if (!local) {
            if (prosac)
                prosac->draw(rng, indices.data());
            else
                drawUniformSample(rng, problem.size(), sampleSize, indices.data());
        }
        for (int i = 0; i < sampleSize; ++i) {
            x1[i] = problem.point1(indices[i]);
            x2[i] = problem.point2(indices[i]);
        }
        if (hasCoincidentPoints()) return 0;
        const int count = solver.solve(x1.data(), x2.data(), rng, solutions.data());
        return keepSolved(count);
    }

    /** The solver's count clamped to the room in `solutions`, then, with requireInFront, reduced
to the solutions in front (moved to the front of `solutions`). */
    int keepSolved(int count)
    {
        count = std::max(0, std::min(count, static_cast<int>(solutions.size())));
        return requireInFront ? solvers::keepSolutionsInFront(solutions.data(), count, x1.data(),
                                                              x2.data(), sampleSize)
                              : count;
    }

    /** Normalised points closer than 1e-9 (about 1e-6 pixel) count as the same point. */
    bool hasCoincidentPoints() const
    {
        const double eps2 = 1e-18;
        for (int i = 0; i < sampleSize; ++i)
            for (int j = 0; j < i; ++j) {
                const Point2d d1 = x1[i] - x1[j], d2 = x2[i] - x2[j];
                if (d1.dot(d1) < eps2 || d2.dot(d2) < eps2) return true;
            }
        return false;
    }
};

} // namespace sampling
} // namespace essential
} // namespace cv

#endif

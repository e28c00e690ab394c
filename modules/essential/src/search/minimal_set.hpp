// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Exactly five correspondences: every distinct essential matrix of the minimal set, stacked, as
// cv::findEssentialMat returns them.

#ifndef OPENCV_ESSENTIAL_SEARCH_MINIMAL_SET_HPP
#define OPENCV_ESSENTIAL_SEARCH_MINIMAL_SET_HPP

#include "input/problem.hpp"

#include "opencv2/essential/params.hpp"
#include "opencv2/essential/solver.hpp"

#include <opencv2/core.hpp>

namespace cv {
namespace essential {
namespace search {

/** The distinct solutions of a five-point problem as a 3k x 3 matrix (k <= 10, each of unit norm;
empty when there is none); counts the solver calls in `report`. */
Mat solveExactlyFive(const Problem& problem, EssentialSolver& solver, RNG& rng,
                     EssentialReport& report);

} // namespace search
} // namespace essential
} // namespace cv

#endif

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#ifndef OPENCV_ESSENTIAL_SOLVERS_SOLUTION_OUTPUT_HPP
#define OPENCV_ESSENTIAL_SOLVERS_SOLUTION_OUTPUT_HPP

#include "geometry/essential_parameterisation.hpp"
#include "simd_dispatch.hpp"

#include <opencv2/core.hpp>

namespace cv {
namespace essential {
namespace solvers {

/** Writes E = [t]x R of a converged pose as the solver's single solution; returns 1. */
ESSENTIAL_INLINE_INTO_CLONES int writeSolution(const geometry::EssentialPose& pose,
                                               Matx33d* solutions)
{
    const Eigen::Matrix3d E = pose.E();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            solutions[0](i, j) = E(i, j);
    return 1;
}

} // namespace solvers
} // namespace essential
} // namespace cv

#endif

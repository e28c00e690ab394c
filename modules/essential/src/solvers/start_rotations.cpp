// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "solvers/start_rotations.hpp"

namespace cv {
namespace essential {
namespace solvers {

ESSENTIAL_SIMD_CLONES void sampleCoplanarityCosts(const Point2d* x1, const Point2d* x2,
                                                  double costs[StartRotations::kCount])
{
    coplanarityCosts<5>(x1, x2, costs);
}

} // namespace solvers
} // namespace essential
} // namespace cv

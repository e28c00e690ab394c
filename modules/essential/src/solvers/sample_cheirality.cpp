// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "solvers/sample_cheirality.hpp"

namespace cv {
namespace essential {
namespace solvers {

ESSENTIAL_SIMD_CLONES int keepSolutionsInFront(Matx33d* solutions, int count, const Point2d* x1,
                                               const Point2d* x2, int n)
{
    int kept = 0;
    for (int h = 0; h < count; ++h)
        if (essentialSampleIsInFront(solutions[h], x1, x2, n)) solutions[kept++] = solutions[h];
    return kept;
}

} // namespace solvers
} // namespace essential
} // namespace cv

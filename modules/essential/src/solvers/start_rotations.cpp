// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "solvers/start_rotations.hpp"

#include <utility>

namespace cv {
namespace essential {
namespace solvers {

ESSENTIAL_AVX2_CLONES void sampleCoplanarityCosts(const Point2d* x1, const Point2d* x2,
                                                  double costs[StartRotations::kCount])
{
    coplanarityCosts<5>(x1, x2, costs);
}

void rankStartRotations(const Point2d* x1, const Point2d* x2, int count, int* best)
{
    double costs[StartRotations::kCount];
    sampleCoplanarityCosts(x1, x2, costs);
    double bestCost[8];
    for (int k = 0; k < count; ++k) {
        bestCost[k] = HUGE_VAL;
        best[k] = 0;
    }
    for (int i = 0; i < StartRotations::kCount; ++i) {
        const double cost = costs[i];
        // Most costs miss the list once it is full: one comparison with its last entry (also
        // false for a NaN, which never enters).
        if (!(cost < bestCost[count - 1])) continue;
        int k = count - 1;
        for (; k > 0 && cost < bestCost[k - 1]; --k) {
            bestCost[k] = bestCost[k - 1];
            best[k] = best[k - 1];
        }
        bestCost[k] = cost;
        best[k] = i;
    }
}

} // namespace solvers
} // namespace essential
} // namespace cv

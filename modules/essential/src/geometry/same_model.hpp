// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// When two essential matrices are one model: the pool of runners-up keeps one hypothesis per model
// (local_optimisation/candidate_pool.hpp), and the search counts draws of its best model's basin
// (termination/basin_confirmation.hpp), both with this test.

#ifndef OPENCV_ESSENTIAL_GEOMETRY_SAME_MODEL_HPP
#define OPENCV_ESSENTIAL_GEOMETRY_SAME_MODEL_HPP

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>

namespace cv {
namespace essential {
namespace geometry {

/** Matrices nearer than this (Frobenius, both scaled to unit norm, up to sign) are one model. */
constexpr double kSameModelDistance = 0.1;

/** E scaled to unit Frobenius norm (NaN entries for E = 0, which then matches no model). */
inline Matx33d unitNorm(const Matx33d& E)
{
    return E * (1.0 / std::sqrt(E.dot(E)));
}

/** Whether two unit-norm matrices are one model (kSameModelDistance, up to sign). */
inline bool sameUnitModel(const Matx33d& unitA, const Matx33d& unitB)
{
    const double minus = norm(unitA - unitB), plus = norm(unitA + unitB);
    return std::min(minus, plus) < kSameModelDistance;
}

} // namespace geometry
} // namespace essential
} // namespace cv

#endif

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The symmetric epipolar distance of a correspondence to an essential matrix: the distance of q2 to
// its epipolar line E q1 and of q1 to E^T q2, combined as sqrt(d1^2 + d2^2). It is the inlier
// distance of OpenCV 4.6's USAC for essential matrices, so that the drop-in's USAC flags admit the
// same inliers at the same threshold. Built from the Sampson terms (geometry/sampson.hpp): the
// Sampson denominator D is the sum of the two line normals' squared lengths used here.

#ifndef OPENCV_ESSENTIAL_GEOMETRY_SYMMETRIC_EPIPOLAR_HPP
#define OPENCV_ESSENTIAL_GEOMETRY_SYMMETRIC_EPIPOLAR_HPP

#include "geometry/sampson.hpp"

namespace cv {
namespace essential {
namespace geometry {

/** Squared symmetric epipolar distance r^2 / (a^2 + b^2) + r^2 / (p^2 + q^2). A point on an
epipole (a zero denominator) gives +inf, or NaN for r = 0, which never passes a `<=` test. Since
1/D1 + 1/D2 >= 4 / (D1 + D2), it is at least four times the squared Sampson distance. */
inline double symmetricEpipolarSquared(const SampsonTerms& t)
{
    const double r2 = t.r * t.r;
    return r2 / (t.a * t.a + t.b * t.b) + r2 / (t.p * t.p + t.q * t.q);
}

inline double symmetricEpipolarSquared(const EssentialEntries& e, double x1, double y1, double x2,
                                       double y2)
{
    return symmetricEpipolarSquared(sampsonTerms(e, x1, y1, x2, y2));
}

} // namespace geometry
} // namespace essential
} // namespace cv

#endif

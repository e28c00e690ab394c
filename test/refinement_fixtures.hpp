// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Inputs shared by the refinement tests (test_irls_refinement.cpp, test_final_refinement.cpp): a
// scene as a Problem (all points or the inliers only) and a start E at a set distance from the
// truth.

#ifndef OPENCV_ESSENTIAL_TEST_REFINEMENT_FIXTURES_HPP
#define OPENCV_ESSENTIAL_TEST_REFINEMENT_FIXTURES_HPP

#include "input/problem.hpp"
#include "synthetic_scene.hpp"

#include <cmath>
#include <random>
#include <vector>

namespace essential_test {

/** The scene's normalised points as a Problem, all of them or only the inliers. */
inline cv::essential::Problem problemOf(const SyntheticScene& s, bool inliersOnly = false)
{
    std::vector<cv::Point2d> a, b;
    for (size_t i = 0; i < s.x1.size(); ++i)
        if (!inliersOnly || s.inlier[i]) {
            a.push_back(s.x1[i]);
            b.push_back(s.x2[i]);
        }
    return cv::essential::makeProblem(a, b);
}

/** The true pose moved by a rotation of `rotDeg` about a random axis and a translation direction
`transDeg` off, as E = [t']x R'. */
inline cv::Matx33d perturbed(const SyntheticScene& s, double rotDeg, double transDeg, uint64_t seed)
{
    // Not the scene's own seed: makeScene draws its motion from the same generator, and the same
    // stream would make the tilt direction parallel to t.
    std::mt19937_64 g(seed * 7919 + 13);
    const cv::Matx33d dR = axisAngle(randomUnit(g), rotDeg * CV_PI / 180.0);
    // A direction orthogonal to t, to tilt t by exactly transDeg.
    cv::Vec3d side = s.t.cross(randomUnit(g));
    side /= cv::norm(side);
    const double a = transDeg * CV_PI / 180.0;
    const cv::Vec3d t = std::cos(a) * s.t + std::sin(a) * side;
    return skewMatrix(t) * (dR * s.R);
}

} // namespace essential_test

#endif

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The sample budget "what OpenCV would have spent": cv::findEssentialMat's RANSAC pays for each of
// its maxIters iterations a 5-point solve and an error evaluation of every root on every point,
// while a sample of this module costs some twenty to thirty times less (SPRT stops most hypotheses
// after a few dozen point checks; docs/TUNING.md, "The OpenCV-time budget"). On hard data (few
// inliers, the stopping rule never satisfied) OpenCV runs its maxIters iterations; this budget lets
// the module draw as many samples as fit in that time, so that it spends no more than OpenCV yet
// tries about twenty times more samples.

#ifndef OPENCV_ESSENTIAL_TERMINATION_OPENCV_TIME_BUDGET_HPP
#define OPENCV_ESSENTIAL_TERMINATION_OPENCV_TIME_BUDGET_HPP

#include <algorithm>
#include <cmath>

namespace cv {
namespace essential {
namespace termination {

/** Cost models in microseconds of thread CPU time, linear in N, fitted to runs that reach the
iteration cap (essential_opencv_time_model; the table and the fit are in docs/TUNING.md, "The
OpenCV-time budget"). Only their ratio matters, and the fit's is at the low end of the measured
ones, which keeps the budget on the safe side of OpenCV's time. */
inline double opencvIterationMicros(int n)
{
    return 125.0 + 0.058 * n;
}
inline double moduleSampleMicros(int n)
{
    return 5.0 + 0.0015 * n;
}

/** Of the time OpenCV's maxIters iterations would take, the share the budget spends on samples:
the rest absorbs what the model does not see (local optimisation on long runs, machines where the
ratio is smaller), so that a call that uses its whole budget still stays below OpenCV's time. */
constexpr double kOpenCvTimeShare = 0.75;

/** Samples that cost kOpenCvTimeShare of the time cv::findEssentialMat's RANSAC spends on maxIters
iterations with n points (about 20 maxIters at n = 500, 24 maxIters at n = 4000). */
inline int opencvTimeSamples(int maxIters, int n)
{
    const double samples =
        kOpenCvTimeShare * maxIters * opencvIterationMicros(n) / moduleSampleMicros(n);
    return samples > 1e9 ? 1000000000 : static_cast<int>(std::floor(samples));
}

} // namespace termination
} // namespace essential
} // namespace cv

#endif

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The sample budget "what OpenCV would have spent": cv::findEssentialMat's RANSAC pays for each of
// its maxIters iterations a 5-point solve (about 125 us) and an error evaluation of every root on
// every point, while a sample of this module costs a few microseconds (SPRT stops most hypotheses
// after a few dozen point checks). On hard data (few inliers, the stopping rule never satisfied)
// OpenCV runs its maxIters iterations; this budget lets the module draw as many samples as fit in
// that time, so that it spends no more than OpenCV yet tries about twenty times more samples.

#ifndef OPENCV_ESSENTIAL_TERMINATION_OPENCV_TIME_BUDGET_HPP
#define OPENCV_ESSENTIAL_TERMINATION_OPENCV_TIME_BUDGET_HPP

#include <algorithm>
#include <cmath>

namespace cv {
namespace essential {
namespace ransac {

/** Cost models in microseconds of thread CPU time, fitted to runs that reach the iteration cap
(synthetic protocol, 3% inliers, 3 problems per N; GCC -O3, one core of the development machine;
build/bench/essential_opencv_time_model):

    N                           100    250    500   1000   2000   4000   8000
    OpenCV RANSAC, us / iter    132    143    155    176    218    362    588
    module default, us / sample 4.99   5.98   6.52   7.54   8.69  11.8   16.8

(the module's per-sample figure includes its refinement and setup, spread over about 1900 samples).
Both grow linearly in N: OpenCV's about 125 + 0.058 N, the module's about 5 + 0.0015 N, a ratio of
25 to 35. A second run on a busier machine gave 163 to 702 us against 6.8 to 15.8 us, ratios 24 to
44: only the ratio matters, and the model's is at the low end, which keeps the budget on the safe
side of OpenCV's time. */
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

} // namespace ransac
} // namespace essential
} // namespace cv

#endif

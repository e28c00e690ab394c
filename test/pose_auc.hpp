// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The accuracy figure of the pose-estimation benchmarks: the error of an estimate is the larger of
// its rotation error and its translation direction error (degrees), and the AUC up to a limit is
// the area under the curve of the fraction of estimates with error <= e, for e from 0 to the
// limit, divided by the limit. Header-only so tests, perf programs and benches share it.

#ifndef OPENCV_ESSENTIAL_TEST_POSE_AUC_HPP
#define OPENCV_ESSENTIAL_TEST_POSE_AUC_HPP

#include <algorithm>
#include <vector>

namespace essential_test {

/** The AUC of the errors (degrees; a failed estimate counts as 180) up to `limitDeg`: 1 if every
error is 0, 0 if none is below the limit. The recall rises linearly between consecutive sorted
errors (the trapezoidal rule, as in SuperGlue's `pose_auc`). */
inline double poseAuc(const std::vector<double>& unsortedErrors, double limitDeg)
{
    if (unsortedErrors.empty()) return 0.0;
    std::vector<double> errors;
    errors.assign(unsortedErrors.begin(), unsortedErrors.end());
    std::sort(errors.begin(), errors.end());
    const double n = static_cast<double>(errors.size());
    double area = 0.0, prevErr = 0.0, prevRecall = 0.0;
    for (size_t i = 0; i < errors.size(); ++i) {
        if (errors[i] >= limitDeg) break;
        const double recall = static_cast<double>(i + 1) / n;
        area += 0.5 * (prevRecall + recall) * (errors[i] - prevErr);
        prevErr = errors[i];
        prevRecall = recall;
    }
    area += prevRecall * (limitDeg - prevErr); // flat from the last error below the limit
    return area / limitDeg;
}

} // namespace essential_test

#endif

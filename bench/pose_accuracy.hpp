// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Pose accuracy figures shared by the comparison programs: the error of an estimate (the larger of
// the rotation error and the translation direction error, in degrees, as in the pose-estimation
// benchmarks) and its AUC (test/pose_auc.hpp), the reliability counts, and the thread CPU clock
// the timings use.

#ifndef OPENCV_ESSENTIAL_BENCH_POSE_ACCURACY_HPP
#define OPENCV_ESSENTIAL_BENCH_POSE_ACCURACY_HPP

#include "bench_common.hpp"
#include "pose_auc.hpp"

#include <opencv2/core.hpp>

#include <algorithm>
#include <ctime>
#include <string>
#include <vector>

namespace essential_bench {

/** One estimate: rotation and translation direction errors in degrees (180 for a failure) and
its thread CPU time. */
struct PoseOutcome
{
    double rotErr = 180.0, transErr = 180.0;
    double ms = 0.0;

    double error() const { return std::max(rotErr, transErr); }
};

/** A pose estimate from one of the compared estimators, with the thread CPU time of its call(s).
 */
struct PoseEstimate
{
    bool ok = false;
    cv::Matx33d R = cv::Matx33d::eye();
    cv::Vec3d t = cv::Vec3d(0, 0, 0);
    double ms = 0.0; //!< thread CPU time of the call(s)
};

using essential_test::poseAuc;

/** Summary of a method over a set of problems. */
struct AccuracySummary
{
    double auc1 = 0, auc5 = 0, auc10 = 0;
    double reliableStrict = 0; //!< rotation < 1 deg and translation < 3 deg
    double reliableLoose = 0;  //!< rotation < 2 deg and translation < 5 deg
    double medianError = 0;    //!< median of max(rotation, translation) error, degrees
    double medianRot = 0, medianTrans = 0;
    double medianMs = 0, meanMs = 0;
};

inline AccuracySummary summarise(const std::vector<PoseOutcome>& outcomes)
{
    AccuracySummary s;
    if (outcomes.empty()) return s;
    std::vector<double> err, rot, trans, ms;
    int strict = 0, loose = 0;
    for (const PoseOutcome& o : outcomes) {
        err.push_back(o.error());
        rot.push_back(o.rotErr);
        trans.push_back(o.transErr);
        ms.push_back(o.ms);
        s.meanMs += o.ms;
        strict += o.rotErr < 1 && o.transErr < 3;
        loose += o.rotErr < 2 && o.transErr < 5;
    }
    const double n = static_cast<double>(outcomes.size());
    s.auc1 = poseAuc(err, 1.0);
    s.auc5 = poseAuc(err, 5.0);
    s.auc10 = poseAuc(err, 10.0);
    s.reliableStrict = strict / n;
    s.reliableLoose = loose / n;
    s.medianError = median(err);
    s.medianRot = median(rot);
    s.medianTrans = median(trans);
    s.medianMs = median(ms);
    s.meanMs /= n;
    return s;
}

} // namespace essential_bench

#endif

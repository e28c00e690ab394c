// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "input/check_params.hpp"

#include "input/problem.hpp"
#include "input/raw_enum.hpp"

#include <string>

namespace cv {
namespace essential {

void checkEssentialParams(const EssentialParams& params)
{
    const int score = rawEnum(params.score), engine = rawEnum(params.engine),
              sampler = rawEnum(params.sampler), budget = rawEnum(params.sampleBudget),
              distance = rawEnum(params.distance);
    switch (score) {
    case SCORE_METHOD_MSAC:
    case SCORE_METHOD_LMEDS:
        break;
    case SCORE_METHOD_RANSAC:
    case SCORE_METHOD_MAGSAC:
        CV_Error(
            Error::StsNotImplemented,
            std::string("EssentialParams::score ") +
                (score == SCORE_METHOD_RANSAC ? "SCORE_METHOD_RANSAC" : "SCORE_METHOD_MAGSAC") +
                " is not implemented; use SCORE_METHOD_MSAC or SCORE_METHOD_LMEDS");
    default:
        CV_Error(Error::StsBadArg, "EssentialParams::score must be SCORE_METHOD_MSAC or "
                                   "SCORE_METHOD_LMEDS, got " +
                                       std::to_string(score));
    }
    if (engine != ENGINE_ADAPTIVE && engine != ENGINE_OPENCV && engine != ENGINE_PREEMPTIVE)
        CV_Error(Error::StsBadArg, "EssentialParams::engine must be ENGINE_ADAPTIVE, "
                                   "ENGINE_PREEMPTIVE or ENGINE_OPENCV, got " +
                                       std::to_string(engine));
    if (engine == ENGINE_PREEMPTIVE && score != SCORE_METHOD_MSAC)
        CV_Error(Error::StsNotImplemented,
                 "ENGINE_PREEMPTIVE scores with MSAC: EssentialParams::score must be "
                 "SCORE_METHOD_MSAC");
    if (!(params.timeBudgetMs >= 0))
        CV_Error(Error::StsBadArg, "EssentialParams::timeBudgetMs must be >= 0 (0 or +inf: no "
                                   "budget), got " +
                                       std::to_string(params.timeBudgetMs));
    if (hasTimeBudget(params) && engine == ENGINE_OPENCV)
        CV_Error(Error::StsNotImplemented,
                 "EssentialParams::timeBudgetMs is not supported by ENGINE_OPENCV (OpenCV's loop "
                 "has no deadline); use ENGINE_ADAPTIVE or ENGINE_PREEMPTIVE");
    if (params.preemptiveHypotheses < 0)
        CV_Error(Error::StsBadArg, "EssentialParams::preemptiveHypotheses must be >= 0");
    if (params.preemptiveBlockSize < 1)
        CV_Error(Error::StsBadArg, "EssentialParams::preemptiveBlockSize must be >= 1");
    if (params.loIterations < 0)
        CV_Error(Error::StsBadArg, "EssentialParams::loIterations must be >= 0, got " +
                                       std::to_string(params.loIterations));
    if (params.loSampleSize < 0 || (params.loSampleSize > 0 && params.loSampleSize < 5))
        CV_Error(Error::StsBadArg,
                 "EssentialParams::loSampleSize must be 0 (all inliers) or >= 5, got " +
                     std::to_string(params.loSampleSize));
    if (sampler != SAMPLING_UNIFORM && sampler != SAMPLING_PROSAC && sampler != SAMPLING_NAPSAC &&
        sampler != SAMPLING_PROGRESSIVE_NAPSAC)
        CV_Error(Error::StsBadArg, "EssentialParams::sampler must be SAMPLING_UNIFORM, "
                                   "SAMPLING_PROSAC, SAMPLING_NAPSAC or "
                                   "SAMPLING_PROGRESSIVE_NAPSAC, got " +
                                       std::to_string(sampler));
    if (sampler == SAMPLING_PROSAC && engine != ENGINE_ADAPTIVE)
        CV_Error(Error::StsNotImplemented,
                 "EssentialParams::sampler SAMPLING_PROSAC needs ENGINE_ADAPTIVE");
    if ((sampler == SAMPLING_NAPSAC || sampler == SAMPLING_PROGRESSIVE_NAPSAC) &&
        (engine != ENGINE_ADAPTIVE || score != SCORE_METHOD_MSAC))
        CV_Error(
            Error::StsNotImplemented,
            std::string("EssentialParams::sampler ") +
                (sampler == SAMPLING_NAPSAC ? "SAMPLING_NAPSAC" : "SAMPLING_PROGRESSIVE_NAPSAC") +
                " needs ENGINE_ADAPTIVE with SCORE_METHOD_MSAC");
    if (budget != BUDGET_CONFIDENCE && budget != BUDGET_OPENCV_TIME)
        CV_Error(Error::StsBadArg,
                 "EssentialParams::sampleBudget must be BUDGET_CONFIDENCE or BUDGET_OPENCV_TIME, "
                 "got " +
                     std::to_string(budget));
    if (distance != DISTANCE_SAMPSON && distance != DISTANCE_SYMMETRIC_EPIPOLAR)
        CV_Error(Error::StsBadArg, "EssentialParams::distance must be DISTANCE_SAMPSON or "
                                   "DISTANCE_SYMMETRIC_EPIPOLAR, got " +
                                       std::to_string(distance));
    checkConfidence(params.confidence);
    checkThreshold(params.threshold);
    checkMaxIters(params.maxIterations, "EssentialParams::maxIterations");
}

void checkDistortion(InputArray d, const char* name)
{
    if (d.empty()) return;
    Mat m = d.getMat();
    const size_t total = m.total() * static_cast<size_t>(m.channels());
    // Any integer or floating depth, as cv::undistortPoints converts it (CV_16F aside).
    if (m.depth() == CV_16F) CV_Error(Error::StsBadArg, std::string(name) + " must not be CV_16F");
    if (total != 4 && total != 5 && total != 8 && total != 12 && total != 14)
        CV_Error(Error::StsBadArg, std::string(name) +
                                       " must have 4, 5, 8, 12 or 14 coefficients (got " +
                                       std::to_string(total) + ")");
    Mat d64;
    m.convertTo(d64, CV_64F);
    if (!checkRange(d64)) CV_Error(Error::StsBadArg, std::string(name) + " has a non-finite entry");
}

} // namespace essential
} // namespace cv

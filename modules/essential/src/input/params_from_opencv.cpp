// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "input/params_from_opencv.hpp"

#include "input/problem.hpp"
#include "input/raw_enum.hpp"

#include <string>
#include <type_traits>
#include <utility>

namespace cv {
namespace essential {

namespace {

/** LO iterations of the USAC flags (the table in essential.hpp and docs/ENGINE.md), in the spirit
of OpenCV's usac::setParameters: USAC_FAST fewer, USAC_ACCURATE more than the default. */
constexpr int kUsacLoIterations = 5;
constexpr int kUsacFastLoIterations = 2;
constexpr int kUsacAccurateLoIterations = 10;

/** The engine settings a USAC method flag stands for (see the table in essential.hpp). */
void applyUsacFlag(int method, EssentialParams& p)
{
    switch (method) {
    case USAC_DEFAULT:
    case USAC_PARALLEL: // runs single-threaded
    case USAC_FM_8PTS:  // an essential matrix all the same, from the configured solver
    case USAC_MAGSAC:   // MSAC scoring with the given threshold
        p.loIterations = kUsacLoIterations;
        break;
    case USAC_FAST:
        p.loIterations = kUsacFastLoIterations;
        break;
    case USAC_ACCURATE:
        p.loIterations = kUsacAccurateLoIterations;
        break;
    case USAC_PROSAC:
        p.sampler = SAMPLING_PROSAC;
        p.loIterations = kUsacLoIterations;
        break;
    default:
        break;
    }
}

} // namespace

EssentialParams dropInParams(int method, double prob, double threshold, int maxIters)
{
    checkMethod(method);
    checkConfidence(prob);
    if (method != LMEDS) checkThreshold(threshold);
    checkMaxIters(maxIters);
    EssentialParams p;
    p.score = method == LMEDS ? SCORE_METHOD_LMEDS : SCORE_METHOD_MSAC;
    p.confidence = prob;
    p.threshold = method == LMEDS ? 1.0 : threshold;
    p.maxIterations = maxIters;
    applyUsacFlag(method, p);
    // OpenCV 4.6's USAC thresholds the symmetric epipolar distance for essential matrices.
    if (method >= USAC_DEFAULT) p.distance = DISTANCE_SYMMETRIC_EPIPOLAR;
    return p;
}

namespace {

/** UsacParams has final_polisher and final_polisher_iterations from OpenCV 4.7 on (4.6 has
neither); detected from the struct itself rather than from a version number. */
template <typename U, typename = void> struct HasFinalPolisher : std::false_type
{
};
template <typename U>
struct HasFinalPolisher<U,
                        std::void_t<decltype(std::declval<const U&>().final_polisher),
                                    decltype(std::declval<const U&>().final_polisher_iterations)>>
    : std::true_type
{
};

/** Reads final_polisher where UsacParams has it. The module's polisher is its own final IRLS
refinement (EssentialParams::refine): NONE_POLISHER (0) switches it off, as does
final_polisher_iterations = 0; LSQ_POLISHER (1), MAGSAC (2) and COV_POLISHER (3, OpenCV's default)
all run it, to its own convergence test (the iteration count is not a cap there). Anything else is
refused by name. */
template <typename U> void readFinalPolisher(const U& usac, EssentialParams& p)
{
    if constexpr (HasFinalPolisher<U>::value) {
        const int polisher = rawEnum(usac.final_polisher);
        if (polisher < 0 || polisher > 3)
            CV_Error(Error::StsBadArg, "UsacParams::final_polisher " + std::to_string(polisher) +
                                           " is not a PolishingMethod");
        if (usac.final_polisher_iterations < 0)
            CV_Error(Error::StsBadArg, "UsacParams::final_polisher_iterations must be >= 0, got " +
                                           std::to_string(usac.final_polisher_iterations));
        p.refine = polisher != 0 && usac.final_polisher_iterations > 0;
    } else {
        (void)usac;
        (void)p;
    }
}

} // namespace

/** The module's settings from a UsacParams (the mapping documented in essential.hpp). */
EssentialParams usacParams(const UsacParams& usac)
{
    EssentialParams p;
    const int score = rawEnum(usac.score), sampler = rawEnum(usac.sampler),
              loMethod = rawEnum(usac.loMethod);
    switch (score) {
    case SCORE_METHOD_RANSAC:
    case SCORE_METHOD_MSAC:
    case SCORE_METHOD_MAGSAC: // MSAC with the given threshold (MAGSAC++ is not implemented)
        p.score = SCORE_METHOD_MSAC;
        break;
    case SCORE_METHOD_LMEDS:
        p.score = SCORE_METHOD_LMEDS;
        break;
    default:
        CV_Error(Error::StsBadArg,
                 "UsacParams::score " + std::to_string(score) + " is not a ScoreMethod");
    }
    switch (sampler) {
    case SAMPLING_UNIFORM:
    case SAMPLING_PROSAC:
    case SAMPLING_NAPSAC:
    case SAMPLING_PROGRESSIVE_NAPSAC:
        p.sampler = static_cast<SamplingMethod>(sampler);
        break;
    default:
        CV_Error(Error::StsBadArg,
                 "UsacParams::sampler " + std::to_string(sampler) + " is not a SamplingMethod");
    }
    switch (loMethod) {
    case LOCAL_OPTIM_NULL:
        p.loIterations = 0;
        break;
    case LOCAL_OPTIM_INNER_LO:
    case LOCAL_OPTIM_INNER_AND_ITER_LO:
    case LOCAL_OPTIM_GC:
    case LOCAL_OPTIM_SIGMA:
        if (usac.loIterations < 0)
            CV_Error(Error::StsBadArg, "UsacParams::loIterations must be >= 0, got " +
                                           std::to_string(usac.loIterations));
        if (usac.loSampleSize < 0 || (usac.loSampleSize > 0 && usac.loSampleSize < 5))
            CV_Error(Error::StsBadArg, "UsacParams::loSampleSize must be 0 (all inliers) or >= 5, "
                                       "got " +
                                           std::to_string(usac.loSampleSize));
        p.loIterations = usac.loIterations;
        p.loSampleSize = usac.loSampleSize;
        break;
    default:
        CV_Error(Error::StsBadArg,
                 "UsacParams::loMethod " + std::to_string(loMethod) + " is not a LocalOptimMethod");
    }
    // isParallel and neighborsSearch are ignored (see essential.hpp).
    checkConfidence(usac.confidence);
    // The module's LMedS search has no local sampler: with SCORE_METHOD_LMEDS the NAPSAC samplers
    // run as uniform sampling (the drop-in forms accept what OpenCV accepts; see essential.hpp).
    if ((p.sampler == SAMPLING_NAPSAC || p.sampler == SAMPLING_PROGRESSIVE_NAPSAC) &&
        p.score == SCORE_METHOD_LMEDS)
        p.sampler = SAMPLING_UNIFORM;
    if (p.score != SCORE_METHOD_LMEDS) checkThreshold(usac.threshold);
    checkMaxIters(usac.maxIterations, "UsacParams::maxIterations");
    p.confidence = usac.confidence;
    p.threshold = p.score == SCORE_METHOD_LMEDS ? 1.0 : usac.threshold;
    p.maxIterations = usac.maxIterations;
    p.seed = static_cast<uint64>(static_cast<unsigned>(usac.randomGeneratorState));
    p.distance = DISTANCE_SYMMETRIC_EPIPOLAR; // as OpenCV's USAC (LMedS ranks by Sampson)
    readFinalPolisher(usac, p);
    return p;
}

} // namespace essential
} // namespace cv

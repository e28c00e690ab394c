// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#ifndef OPENCV_ESSENTIAL_BATCH_HPP
#define OPENCV_ESSENTIAL_BATCH_HPP

#include "opencv2/essential/params.hpp"

#include <opencv2/core.hpp>

#include <functional>
#include <string>
#include <vector>

namespace cv {
namespace essential {

//! @addtogroup essential
//! @{

/** One image pair of a batch: its correspondences (any layout findEssentialMatIter() reads) and
the camera matrix of both views. */
struct CV_EXPORTS EssentialPair
{
    Mat points1, points2, cameraMatrix;
};

/** The estimate of one pair of a batch. */
struct CV_EXPORTS EssentialPairResult
{
    Mat E;                  //!< as findEssentialMatIter() returns it (empty when none was found)
    Mat mask;               //!< N x 1 CV_8U inlier mask
    EssentialReport report; //!< the module's report (pose, counts, times)
    /** Empty when the estimate ran; otherwise the message of the cv::Exception the pair raised
    (bad input): one bad pair does not stop the batch. */
    std::string error;
};

/** Called after each finished pair with the number done and the total, from one thread at a time
(not necessarily the caller's). */
typedef std::function<void(int done, int total)> BatchProgress;

/** @brief Estimates the essential matrix of many pairs in parallel.

Each pair runs findEssentialMatIter() with `params` and the seed params.seed mixed with the pair's
index, so the results are the same at any thread count and in any order of execution.
@param pairs the pairs.
@param params the settings of every estimate (its seed is the batch's).
@param threads worker threads; 0 (default): cv::getNumThreads(). Each pair runs on one thread.
@param progress optional callback after each pair.
@param firstIndex the index of pairs[0] in a larger list: pair i gets the seed of index
firstIndex + i, so a list cut into parts (for several processes or machines) and estimated part by
part gives the results of one batch of the whole list.
@return one result per pair, in the order of `pairs`.
*/
CV_EXPORTS std::vector<EssentialPairResult>
findEssentialMatBatch(const std::vector<EssentialPair>& pairs,
                      const EssentialParams& params = EssentialParams(), int threads = 0,
                      const BatchProgress& progress = BatchProgress(), int firstIndex = 0);

/** The seed findEssentialMatBatch() gives pair `index` for the batch seed `seed` (SplitMix64 of
their combination): the same estimate as one findEssentialMatIter() call with this seed. */
CV_EXPORTS uint64 batchPairSeed(uint64 seed, int index);

//! @}

} // namespace essential
} // namespace cv

#endif

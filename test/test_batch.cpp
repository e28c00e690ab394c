// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// findEssentialMatBatch: the same results at any thread count, each pair as one call with its
// derived seed, bad pairs reported without stopping the batch, progress and its exceptions.

#include "synthetic_scene.hpp"

#include <opencv2/essential.hpp>

#include "essential_test.hpp"

#include <atomic>
#include <stdexcept>
#include <vector>

namespace {

std::vector<cv::essential::EssentialPair> makePairs(int count)
{
    std::vector<cv::essential::EssentialPair> pairs;
    essential_test::SceneConfig cfg;
    cfg.numPoints = 200;
    cfg.inlierRatio = 0.6;
    for (int i = 0; i < count; ++i) {
        const essential_test::SyntheticScene s = essential_test::makeScene(cfg, 100 + i);
        cv::essential::EssentialPair p;
        // N x 1 two-channel, as cv::Mat(vector) is in OpenCV 4 (OpenCV 5 makes it 1-D).
        const int n = static_cast<int>(s.px1.size());
        p.points1 = cv::Mat(s.px1, true).reshape(2, n);
        p.points2 = cv::Mat(s.px2, true).reshape(2, n);
        p.cameraMatrix = cv::Mat(s.K);
        pairs.push_back(p);
    }
    return pairs;
}

TEST(Batch, SameResultsAtAnyThreadCountAndAsSingleCalls)
{
    const std::vector<cv::essential::EssentialPair> pairs = makePairs(8);
    cv::essential::EssentialParams params;
    const auto one = cv::essential::findEssentialMatBatch(pairs, params, 1);
    const auto three = cv::essential::findEssentialMatBatch(pairs, params, 3);
    ASSERT_EQ(one.size(), pairs.size());
    ASSERT_EQ(three.size(), pairs.size());
    for (size_t i = 0; i < pairs.size(); ++i) {
        SCOPED_TRACE(i);
        EXPECT_TRUE(one[i].error.empty());
        ASSERT_FALSE(one[i].E.empty());
        EXPECT_EQ(cv::norm(one[i].E, three[i].E, cv::NORM_INF), 0.0);
        EXPECT_EQ(cv::norm(one[i].mask, three[i].mask, cv::NORM_INF), 0.0);
        // The same as one call with the pair's seed.
        cv::essential::EssentialParams single = params;
        single.seed = cv::essential::batchPairSeed(params.seed, static_cast<int>(i));
        cv::Mat mask;
        const cv::Mat E = cv::essential::findEssentialMatIter(pairs[i].points1, pairs[i].points2,
                                                              pairs[i].cameraMatrix, single, mask);
        EXPECT_EQ(cv::norm(E, one[i].E, cv::NORM_INF), 0.0);
    }
    EXPECT_NE(cv::essential::batchPairSeed(1, 0), cv::essential::batchPairSeed(1, 1));
}

TEST(Batch, BadPairIsReportedAndTheOthersRun)
{
    std::vector<cv::essential::EssentialPair> pairs = makePairs(3);
    pairs[1].points2 = pairs[1].points2.rowRange(0, 10); // sizes differ: bad input
    std::atomic<int> calls(0);
    int lastDone = 0, lastTotal = 0;
    const auto results = cv::essential::findEssentialMatBatch(
        pairs, cv::essential::EssentialParams(), 2, [&](int done, int total) {
            ++calls;
            lastDone = std::max(lastDone, done);
            lastTotal = total;
        });
    ASSERT_EQ(results.size(), 3u);
    EXPECT_TRUE(results[0].error.empty());
    EXPECT_FALSE(results[1].error.empty());
    EXPECT_TRUE(results[1].E.empty());
    EXPECT_TRUE(results[2].error.empty());
    EXPECT_EQ(calls.load(), 3);
    EXPECT_EQ(lastDone, 3);
    EXPECT_EQ(lastTotal, 3);
}

TEST(Batch, ProgressExceptionReachesTheCallerAndBadThreadsRaise)
{
    const std::vector<cv::essential::EssentialPair> pairs = makePairs(4);
    EXPECT_THROW(
        cv::essential::findEssentialMatBatch(pairs, cv::essential::EssentialParams(), 2,
                                             [](int, int) { throw std::runtime_error("stop"); }),
        std::runtime_error);
    EXPECT_THROW(cv::essential::findEssentialMatBatch(pairs, cv::essential::EssentialParams(), -1),
                 cv::Exception);
    EXPECT_TRUE(cv::essential::findEssentialMatBatch({}, cv::essential::EssentialParams()).empty());
    EXPECT_THROW(cv::essential::findEssentialMatBatch(pairs, cv::essential::EssentialParams(), 1,
                                                      cv::essential::BatchProgress(), -1),
                 cv::Exception);
}

TEST(Batch, PartsWithTheirFirstIndexGiveTheWholeBatch)
{
    // A list cut in two parts, each estimated with the index of its first pair, gives the results
    // of one batch of the whole list (how several processes share a list of pairs).
    const std::vector<cv::essential::EssentialPair> pairs = makePairs(6);
    const cv::essential::EssentialParams params;
    const auto whole = cv::essential::findEssentialMatBatch(pairs, params, 2);
    const std::vector<cv::essential::EssentialPair> tail(pairs.begin() + 4, pairs.end());
    const auto part =
        cv::essential::findEssentialMatBatch(tail, params, 1, cv::essential::BatchProgress(), 4);
    ASSERT_EQ(part.size(), 2u);
    for (size_t k = 0; k < part.size(); ++k) {
        SCOPED_TRACE(k);
        ASSERT_FALSE(part[k].E.empty());
        EXPECT_EQ(cv::norm(part[k].E, whole[4 + k].E, cv::NORM_INF), 0.0);
        EXPECT_EQ(cv::norm(part[k].mask, whole[4 + k].mask, cv::NORM_INF), 0.0);
    }
}

} // namespace

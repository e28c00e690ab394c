// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "opencv2/essential/batch.hpp"

#include "opencv2/essential.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>

namespace cv {
namespace essential {

uint64 batchPairSeed(uint64 seed, int index)
{
    // SplitMix64 of the batch seed advanced by the index: neighbouring indices get unrelated
    // seeds, and the same (seed, index) always the same one.
    uint64 z = seed + 0x9e3779b97f4a7c15ULL * (static_cast<uint64>(index) + 1);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

std::vector<EssentialPairResult> findEssentialMatBatch(const std::vector<EssentialPair>& pairs,
                                                       const EssentialParams& params, int threads,
                                                       const BatchProgress& progress,
                                                       int firstIndex)
{
    const int total = static_cast<int>(pairs.size());
    std::vector<EssentialPairResult> results(pairs.size());
    if (threads < 0) CV_Error(Error::StsBadArg, "threads must be >= 0 (0: cv::getNumThreads())");
    if (firstIndex < 0 || firstIndex > std::numeric_limits<int>::max() - total)
        CV_Error(Error::StsBadArg,
                 "firstIndex must be >= 0 and firstIndex + pairs.size() fit an int");
    const int workers = std::max(1, std::min(total, threads > 0 ? threads : getNumThreads()));
    std::atomic<int> next(0), done(0);
    std::mutex progressMutex;
    std::exception_ptr failure;
    auto work = [&]() {
        for (;;) {
            const int i = next.fetch_add(1);
            if (i >= total) return;
            EssentialParams p = params;
            p.seed = batchPairSeed(params.seed, firstIndex + i);
            EssentialPairResult& r = results[static_cast<size_t>(i)];
            try {
                r.E = findEssentialMatIter(pairs[i].points1, pairs[i].points2,
                                           pairs[i].cameraMatrix, p, r.mask, &r.report);
            } catch (const std::exception& e) {
                r.error = e.what();
            }
            const int finished = done.fetch_add(1) + 1;
            if (progress) {
                // A callback that throws stops the batch; its exception reaches the caller.
                std::lock_guard<std::mutex> lock(progressMutex);
                if (failure) return;
                try {
                    progress(finished, total);
                } catch (...) {
                    failure = std::current_exception();
                    next.store(total);
                    return;
                }
            }
        }
    };
    if (workers == 1) {
        work();
    } else {
        std::vector<std::thread> pool;
        for (int w = 0; w < workers; ++w)
            pool.emplace_back(work);
        for (std::thread& t : pool)
            t.join();
    }
    if (failure) std::rethrow_exception(failure);
    return results;
}

} // namespace essential
} // namespace cv

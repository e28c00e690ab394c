// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Heap allocations per findEssentialMatIter call (docs/PERFORMANCE.md, "Allocations"), on the
// paper's synthetic protocol, public API only. This executable replaces the global operator new,
// so every `new` of the process (the library's std::vector, Eigen's dynamic matrices, ...) is
// counted while a call runs; cv::Mat buffers come from cv::fastMalloc and are not counted.
//
//   essential_allocations [--n 500] [--ratios 0.9,0.5,0.3] [--problems 20] [--seed 1]
//                         [--lo-iterations K]   (EssentialParams::loIterations; default its
//                         default)
//
// Per inlier ratio: allocations per call (min, median, max) beside the hypotheses scored and the
// local optimisation (LO) runs, and the least-squares slope of allocations against LO runs. A
// per-hypothesis path that allocated would make the count grow with the hypotheses (tens to tens
// of thousands per call); run with --lo-iterations 0 to see the count without LO.

#include "synthetic_scene.hpp"

#include "bench_common.hpp"
#include "bench_options.hpp"
#include <opencv2/core.hpp>
#include <opencv2/essential.hpp>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

namespace {

/** Counts every operator new of the process while `counting` is set; relaxed atomics, as the
calls run on one thread and only the totals are read. */
std::atomic<long long> allocationCount{0};
std::atomic<bool> counting{false};

[[gnu::noinline]] void* allocate(std::size_t size)
{
    if (counting.load(std::memory_order_relaxed))
        allocationCount.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}

} // namespace

[[gnu::noinline]] void* operator new(std::size_t size)
{
    return allocate(size);
}

[[gnu::noinline]] void* operator new[](std::size_t size)
{
    return allocate(size);
}

[[gnu::noinline]] void* operator new(std::size_t size, const std::nothrow_t&) noexcept
{
    try {
        return allocate(size);
    } catch (const std::bad_alloc&) {
        return nullptr;
    }
}

[[gnu::noinline]] void* operator new[](std::size_t size, const std::nothrow_t&) noexcept
{
    try {
        return allocate(size);
    } catch (const std::bad_alloc&) {
        return nullptr;
    }
}

// GCC 14 inlines these (and the operators new above) into the std::vector code of main and then,
// seeing malloc and free in one function, warns of a free at an offset (-Wfree-nonheap-object) or
// of a sized delete of malloc's memory (-Wmismatched-new-delete), both false positives; out of
// line, each operator is what the replaced global one is: a call.
[[gnu::noinline]] void operator delete(void* p) noexcept
{
    std::free(p);
}

[[gnu::noinline]] void operator delete[](void* p) noexcept
{
    std::free(p);
}

[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept
{
    std::free(p);
}

[[gnu::noinline]] void operator delete[](void* p, std::size_t) noexcept
{
    std::free(p);
}

using namespace essential_bench;

namespace {

struct Call
{
    double allocations = 0, hypotheses = 0, loRuns = 0;
};

/** Slope of y against x by least squares (0 when x does not vary). */
double slope(const std::vector<Call>& calls, double Call::*x, double Call::*y)
{
    double mx = 0, my = 0;
    for (const Call& c : calls) {
        mx += c.*x / calls.size();
        my += c.*y / calls.size();
    }
    double sxy = 0, sxx = 0;
    for (const Call& c : calls) {
        sxy += (c.*x - mx) * (c.*y - my);
        sxx += (c.*x - mx) * (c.*x - mx);
    }
    return sxx > 0 ? sxy / sxx : 0.0;
}

} // namespace

int main(int argc, char** argv)
{
    int n = 500, problems = 20;
    int loIterations = cv::essential::EssentialParams().loIterations;
    uint64_t seed = 1;
    std::vector<double> ratios = {0.9, 0.5, 0.3};
    std::vector<Call> allCalls;
    Options opts("essential_allocations");
    opts.add("n", n);
    opts.add("problems", problems);
    opts.add("seed", seed);
    opts.add("ratios", ratios);
    opts.add("lo-iterations", loIterations);
    opts.parse(argc, argv);
    cv::setNumThreads(1);
    std::printf("N = %d, %d problems per ratio, EssentialParams overload with its defaults but "
                "loIterations = %d, operator new calls during the call\n\n",
                n, problems, loIterations);
    std::printf(
        "| inlier ratio | allocations per call: min / median / max | hypotheses scored: "
        "min / max | LO runs: min / max | allocations per LO run |\n|---|---|---|---|---|\n");
    for (double ratio : ratios) {
        std::vector<Call> calls;
        for (int p = 0; p < problems; ++p) {
            essential_test::SceneConfig cfg;
            cfg.numPoints = n;
            cfg.inlierRatio = ratio;
            const auto s = essential_test::makeScene(cfg, seed * 1000003ULL + p);
            const cv::Mat K(s.K);
            cv::Mat mask;
            cv::essential::EssentialParams params;
            params.loIterations = loIterations;
            cv::essential::EssentialReport report;
            allocationCount = 0;
            counting = true;
            cv::essential::findEssentialMatIter(s.px1, s.px2, K, params, mask, &report);
            counting = false;
            calls.push_back({double(allocationCount.load()), double(report.hypothesesScored),
                             double(report.localOptimisations)});
        }
        allCalls.insert(allCalls.end(), calls.begin(), calls.end());
        std::vector<double> a, h, lo;
        for (const Call& c : calls) {
            a.push_back(c.allocations);
            h.push_back(c.hypotheses);
            lo.push_back(c.loRuns);
        }
        std::printf("| %.2f | %.0f / %.0f / %.0f | %.0f / %.0f | %.0f / %.0f | %.1f |\n", ratio,
                    percentile(a, 0), median(a), percentile(a, 1), percentile(h, 0),
                    percentile(h, 1), percentile(lo, 0), percentile(lo, 1),
                    slope(calls, &Call::loRuns, &Call::allocations));
        std::fflush(stdout);
    }
    std::printf("\nAll ratios pooled (%zu calls): %.1f allocations per LO run.\n", allCalls.size(),
                slope(allCalls, &Call::loRuns, &Call::allocations));
    return 0;
}

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Time and peak memory of findEssentialMatIter against the number of correspondences N
// (docs/ROBUSTNESS.md, "Scaling"). Each N runs in its own child process, so that the peak resident
// set (getrusage's ru_maxrss of the child) belongs to that N alone; a second child per N only
// builds the scene, and the difference of the two peaks is what the estimate itself needed.
//
//   essential_scaling [--sizes 1000,10000,100000] [--inliers 0.5] [--repeats 5]
//
// Public API only.

#include "bench_common.hpp"
#include "bench_options.hpp"
#include "synthetic_scene.hpp"

#include <opencv2/essential.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

struct ChildResult
{
    double medianMs = 0;
    double minMs = 0;
    int inliers = 0;
    long peakKb = 0;
    bool ok = false;
};

/** Runs `work` in a child process; the child writes its numbers to a pipe, the parent adds the
child's peak resident set from wait4. */
template <typename Work> ChildResult inChild(Work work)
{
    int fds[2];
    if (pipe(fds) != 0) return {};
    const pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        ChildResult r = work();
        const ssize_t written = write(fds[1], &r, sizeof r);
        _exit(written == static_cast<ssize_t>(sizeof r) ? 0 : 1);
    }
    close(fds[1]);
    ChildResult r;
    const ssize_t got = read(fds[0], &r, sizeof r);
    close(fds[0]);
    int status = 0;
    struct rusage usage;
    std::memset(&usage, 0, sizeof usage);
    wait4(pid, &status, 0, &usage);
    r.ok = got == static_cast<ssize_t>(sizeof r) && WIFEXITED(status) && WEXITSTATUS(status) == 0;
    r.peakKb = usage.ru_maxrss; // kilobytes on Linux
    return r;
}

essential_test::SyntheticScene scene(int n, double inliers)
{
    essential_test::SceneConfig cfg;
    cfg.numPoints = n;
    cfg.inlierRatio = inliers;
    return essential_test::makeScene(cfg, 4242);
}

} // namespace

int main(int argc, char** argv)
{
    std::vector<double> sizes = {1000, 10000, 100000};
    double inliers = 0.5;
    int repeats = 5;
    essential_bench::Options opts("essential_scaling");
    opts.add("sizes", sizes);
    opts.add("inliers", inliers);
    opts.add("repeats", repeats);
    opts.parse(argc, argv);
    repeats = std::max(1, repeats);
    std::printf("| N | inliers found | median time | min time | time / N | peak RSS | RSS of scene "
                "only | estimate's share | share / N |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|\n");
    for (const double size : sizes) {
        const int n = static_cast<int>(size);
        const ChildResult base = inChild([&] {
            ChildResult r;
            const auto s = scene(n, inliers);
            r.inliers = static_cast<int>(s.px1.size());
            return r;
        });
        const ChildResult run = inChild([&] {
            ChildResult r;
            const auto s = scene(n, inliers);
            const cv::Mat K(s.K);
            std::vector<double> ms;
            for (int k = 0; k < repeats; ++k) {
                cv::Mat mask;
                const auto t0 = std::chrono::steady_clock::now();
                const cv::Mat E = cv::essential::findEssentialMatIter(s.px1, s.px2, K, cv::RANSAC,
                                                                      0.999, 1.0, 1000, mask);
                ms.push_back(
                    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                        .count());
                r.inliers = E.empty() ? 0 : cv::countNonZero(mask);
            }
            // Sorted in place (a copy through essential_bench::median trips GCC 12's
            // -Wfree-nonheap-object false positive once inlined here).
            std::sort(ms.begin(), ms.end());
            r.medianMs = ms[ms.size() / 2];
            r.minMs = ms.front();
            return r;
        });
        if (!base.ok || !run.ok) {
            std::fprintf(stderr, "essential_scaling: the child for N = %d failed\n", n);
            return 1;
        }
        const long share = run.peakKb - base.peakKb;
        std::printf("| %d | %d | %.2f ms | %.2f ms | %.2f us | %.1f MB | %.1f MB | %.2f MB | %.0f "
                    "bytes |\n",
                    n, run.inliers, run.medianMs, run.minMs, 1000.0 * run.medianMs / n,
                    run.peakKb / 1024.0, base.peakKb / 1024.0, share / 1024.0, 1024.0 * share / n);
    }
    return 0;
}

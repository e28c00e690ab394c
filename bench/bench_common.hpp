// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Small helpers the experiment programs share: comma-separated option values, order statistics
// of timings and the thread CPU clock.

#ifndef OPENCV_ESSENTIAL_BENCH_COMMON_HPP
#define OPENCV_ESSENTIAL_BENCH_COMMON_HPP

#include <algorithm>
#include <cstdlib>
#include <ctime>
#include <sstream>
#include <string>
#include <vector>

namespace essential_bench {

/** "a,b,c" -> {"a", "b", "c"}. */
inline std::vector<std::string> split(const std::string& s)
{
    std::vector<std::string> out;
    std::stringstream ss(s);
    std::string item;
    while (std::getline(ss, item, ','))
        out.push_back(item);
    return out;
}

/** "0.5,0.3" -> {0.5, 0.3}. */
inline std::vector<double> numbers(const std::string& s)
{
    std::vector<double> out;
    for (const auto& x : split(s))
        out.push_back(std::atof(x.c_str()));
    return out;
}

/** The p-quantile (0 <= p <= 1, nearest rank) of the values; 0 for none. */
inline double percentile(std::vector<double> v, double p)
{
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const size_t i = std::min(v.size() - 1, static_cast<size_t>(p * (v.size() - 1) + 0.5));
    return v[i];
}

inline double median(const std::vector<double>& v)
{
    return percentile(v, 0.5);
}

/** Thread CPU time in milliseconds (CLOCK_THREAD_CPUTIME_ID): the time the thread waits for a core
is not charged to it, which wall time would add at random. */
inline double threadCpuMs()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

} // namespace essential_bench

#endif

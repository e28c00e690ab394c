// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The on-disk cache of a frame pair's matches that the real-data experiments share
// (bench/paper_rail.cpp, bench/hard_pairs.cpp): matching a pair costs far more than estimating on
// it, so each pair is matched once. A file holds the match count, then the image-1 points, the
// image-2 points (cv::Point2f) and the descriptor distances (float), in matchFeatures' order.
// Delete the cache after changing the front end.

#ifndef OPENCV_ESSENTIAL_BENCH_MATCH_CACHE_HPP
#define OPENCV_ESSENTIAL_BENCH_MATCH_CACHE_HPP

#include "cli_common.hpp"
#include "frontend/frontend.hpp"

#include <fstream>
#include <string>

namespace essential_bench {

/** Reads the matches cached at `path` into m; false when there is no (readable) cache. */
inline bool loadMatches(const std::string& path, essential_samples::Matches& m)
{
    std::ifstream in(path, std::ios::binary);
    int n = 0;
    if (!in.read(reinterpret_cast<char*>(&n), sizeof n) || n < 0 || n > 10000000) return false;
    m.points1.resize(n);
    m.points2.resize(n);
    m.distances.resize(n);
    in.read(reinterpret_cast<char*>(m.points1.data()), n * sizeof(cv::Point2f));
    in.read(reinterpret_cast<char*>(m.points2.data()), n * sizeof(cv::Point2f));
    in.read(reinterpret_cast<char*>(m.distances.data()), n * sizeof(float));
    m.candidates = n;
    return static_cast<bool>(in);
}

/** Writes m to `path`; fails (essential_samples::fail) when it cannot. */
inline void saveMatches(const std::string& path, const essential_samples::Matches& m)
{
    std::ofstream out(path, std::ios::binary);
    const int n = static_cast<int>(m.points1.size());
    out.write(reinterpret_cast<const char*>(&n), sizeof n);
    out.write(reinterpret_cast<const char*>(m.points1.data()), n * sizeof(cv::Point2f));
    out.write(reinterpret_cast<const char*>(m.points2.data()), n * sizeof(cv::Point2f));
    out.write(reinterpret_cast<const char*>(m.distances.data()), n * sizeof(float));
    if (!out) essential_samples::fail("cannot write the match cache '" + path + "'");
}

} // namespace essential_bench

#endif

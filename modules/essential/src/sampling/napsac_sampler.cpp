// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "sampling/napsac_sampler.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace cv {
namespace essential {
namespace sampling {

namespace {

/** Cells per side of the levels, finest first. 16 x 16 cells put about 8 of 2000 matches in a cell
of image 1 (uniformly spread); 2 x 2 is the coarsest that still separates regions. */
constexpr int kCellsPerSide[] = {16, 8, 4, 2};

struct Box
{
    double x0, y0, sx, sy; //!< origin and cell size per cell count 1 (divided by c at use)
};

Box boundingBox(const Coordinates& x, const Coordinates& y)
{
    double x0 = x[0], x1 = x[0], y0 = y[0], y1 = y[0];
    for (size_t i = 1; i < x.size(); ++i) {
        x0 = std::min(x0, x[i]);
        x1 = std::max(x1, x[i]);
        y0 = std::min(y0, y[i]);
        y1 = std::max(y1, y[i]);
    }
    // A degenerate extent (all on a line) still gets cells of positive size.
    return Box{x0, y0, std::max(x1 - x0, 1e-12), std::max(y1 - y0, 1e-12)};
}

int cellOf(double v, double origin, double extent, int cells)
{
    const int c = static_cast<int>((v - origin) / extent * cells);
    return std::min(std::max(c, 0), cells - 1);
}

} // namespace

NapsacSampler::NapsacSampler(const Problem& points, int m) : n_(points.size()), m_(m)
{
    const int n = n_;
    if (n <= 0) return;
    const Box b1 = boundingBox(points.x1, points.y1), b2 = boundingBox(points.x2, points.y2);
    std::vector<std::int64_t> key(static_cast<size_t>(n));
    for (int cells : kCellsPerSide) {
        Level level;
        for (int i = 0; i < n; ++i) {
            const std::int64_t c1x = cellOf(points.x1[i], b1.x0, b1.sx, cells);
            const std::int64_t c1y = cellOf(points.y1[i], b1.y0, b1.sy, cells);
            const std::int64_t c2x = cellOf(points.x2[i], b2.x0, b2.sx, cells);
            const std::int64_t c2y = cellOf(points.y2[i], b2.y0, b2.sy, cells);
            key[static_cast<size_t>(i)] = ((c1x * cells + c1y) * cells + c2x) * cells + c2y;
        }
        level.order.resize(static_cast<size_t>(n));
        std::iota(level.order.begin(), level.order.end(), 0);
        std::stable_sort(level.order.begin(), level.order.end(),
                         [&](int a, int c) { return key[a] < key[c]; });
        level.cellBegin.resize(static_cast<size_t>(n));
        level.cellEnd.resize(static_cast<size_t>(n));
        for (int s = 0; s < n;) {
            int e = s + 1;
            while (e < n && key[level.order[e]] == key[level.order[s]])
                ++e;
            for (int k = s; k < e; ++k) {
                level.cellBegin[level.order[k]] = s;
                level.cellEnd[level.order[k]] = e;
            }
            s = e;
        }
        levels_.push_back(std::move(level));
    }
}

bool NapsacSampler::draw(RNG& rng, int* indices)
{
    if (n_ < m_) return false;
    const int seed = static_cast<int>(rng.uniform(0, n_));
    // The levels whose cell around the seed holds a whole sample; one of them at random, so that
    // both tight clusters (fine cells) and larger regions (coarse cells, better conditioned
    // samples) are tried.
    int usable[sizeof(kCellsPerSide) / sizeof(kCellsPerSide[0])];
    int count = 0;
    for (int l = 0; l < static_cast<int>(levels_.size()); ++l) {
        const Level& level = levels_[static_cast<size_t>(l)];
        if (level.cellEnd[seed] - level.cellBegin[seed] >= m_) usable[count++] = l;
    }
    if (count == 0) return false;
    const Level& level = levels_[static_cast<size_t>(usable[rng.uniform(0, count)])];
    const int begin = level.cellBegin[seed], size = level.cellEnd[seed] - begin;
    indices[0] = seed;
    for (int i = 1; i < m_; ++i) {
        for (;;) {
            const int candidate = level.order[begin + static_cast<int>(rng.uniform(0, size))];
            bool repeated = false;
            for (int j = 0; j < i; ++j)
                repeated |= indices[j] == candidate;
            if (!repeated) {
                indices[i] = candidate;
                break;
            }
        }
    }
    return true;
}

} // namespace sampling
} // namespace essential
} // namespace cv

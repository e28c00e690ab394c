// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#ifndef OPENCV_ESSENTIAL_SAMPLING_UNIFORM_SAMPLER_HPP
#define OPENCV_ESSENTIAL_SAMPLING_UNIFORM_SAMPLER_HPP

#include <opencv2/core.hpp>

namespace cv {
namespace essential {
namespace sampling {

/** Draws k distinct indices uniformly from [0, n) by rejection: for k << n (5 of hundreds) a
repeat is rare, so this beats a partial shuffle that would touch an n-sized array. */
inline void drawUniformSample(RNG& rng, int n, int k, int* indices)
{
    for (int i = 0; i < k; ++i) {
        for (;;) {
            const int candidate = static_cast<int>(rng.uniform(0, n));
            bool repeated = false;
            for (int j = 0; j < i; ++j)
                repeated |= (indices[j] == candidate);
            if (!repeated) {
                indices[i] = candidate;
                break;
            }
        }
    }
}

} // namespace sampling
} // namespace essential
} // namespace cv

#endif

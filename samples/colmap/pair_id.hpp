// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// COLMAP's image pair identifier: pair_id = id1 * 2147483647 + id2 with id1 < id2 (image ids are
// below 2147483647, which COLMAP's images table checks), so that a pair has one id whatever the
// order of its images. Matches stored under a pair id index the keypoints of id1 in their first
// column and those of id2 in their second.

#ifndef ESSENTIAL_SAMPLES_COLMAP_PAIR_ID_HPP
#define ESSENTIAL_SAMPLES_COLMAP_PAIR_ID_HPP

#include <cstdint>
#include <utility>

namespace essential_colmap {

constexpr std::int64_t kMaxImageId = 2147483647;

/** The pair id of two image ids (in either order). */
inline std::int64_t pairIdOf(std::int64_t imageA, std::int64_t imageB)
{
    return imageA < imageB ? imageA * kMaxImageId + imageB : imageB * kMaxImageId + imageA;
}

/** The image ids (id1 < id2) of a pair id. */
inline std::pair<std::int64_t, std::int64_t> imagesOfPair(std::int64_t pairId)
{
    return {pairId / kMaxImageId, pairId % kMaxImageId};
}

} // namespace essential_colmap

#endif

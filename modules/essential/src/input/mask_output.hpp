// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Writing an inlier mask into the caller's OutputArray the way OpenCV 4.6 does. Its two
// estimation paths treat a caller's preallocated mask differently (measured against
// cv::findEssentialMat: test/test_drop_in_layouts.cpp):
//  - RANSAC and LMEDS keep a preallocated 1 x N CV_8U mask as it is (the mask is created with
//    transposition allowed) and reject a mask that is a view not continuous in memory;
//  - the USAC flags and the UsacParams form copy an N x 1 CV_8U mask into it: a 1 x N mask is
//    reallocated as N x 1, a view of the right size and type is written in place, and a
//    std::vector of another element type receives the values converted.

#ifndef OPENCV_ESSENTIAL_INPUT_MASK_OUTPUT_HPP
#define OPENCV_ESSENTIAL_INPUT_MASK_OUTPUT_HPP

#include <opencv2/core.hpp>

#include <vector>

namespace cv {
namespace essential {

enum class MaskWriting {
    Classic, //!< RANSAC, LMEDS: created N x 1 or kept 1 x N; must be continuous
    Usac     //!< USAC flags, UsacParams, the module's own overload: copied as N x 1
};

/** The mask writing of the drop-in overloads for a `method` flag. */
MaskWriting maskWritingForMethod(int method);

/** Writes `values` (one per point, 0 or 1) into `mask` if the caller asked for one. Throws
cv::Exception (StsBadArg, naming the mask) for a mask that cannot hold them as OpenCV would fail. */
void writeMask(OutputArray mask, const std::vector<uchar>& values, MaskWriting how);

} // namespace essential
} // namespace cv

#endif

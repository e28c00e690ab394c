// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "input/mask_output.hpp"

#include <opencv2/calib3d.hpp>

#include <algorithm>
#include <string>

namespace cv {
namespace essential {

MaskWriting maskWritingForMethod(int method)
{
    return method >= USAC_DEFAULT && method <= USAC_MAGSAC ? MaskWriting::Usac
                                                           : MaskWriting::Classic;
}

void writeMask(OutputArray mask, const std::vector<uchar>& values, MaskWriting how)
{
    if (!mask.needed()) return;
    const int n = static_cast<int>(values.size());
    // The values are copied, so `source` may point into the const vector.
    const Mat source(n, 1, CV_8U, const_cast<uchar*>(values.data()));
    try {
        if (how == MaskWriting::Usac) {
            // As OpenCV's USAC: a fresh N x 1 array copied into the output, which reallocates a
            // mask of another shape (the allocator may hand back the same block, as it does for
            // OpenCV; copying from an owned array keeps that pattern the same as OpenCV's).
            Mat fresh(n, 1, CV_8U);
            source.copyTo(fresh);
            fresh.copyTo(mask);
            return;
        }
        mask.create(n, 1, CV_8U, -1, /*allowTransposed*/ true);
    } catch (const cv::Exception& e) {
        CV_Error(Error::StsBadArg,
                 "mask cannot receive " + std::to_string(n) +
                     " CV_8U values (a std::vector mask must hold uchar): " + e.err);
    }
    Mat m = mask.getMat();
    if (!m.isContinuous())
        CV_Error(Error::StsBadArg,
                 "mask is a view that is not continuous in memory: with RANSAC or LMEDS, as for "
                 "cv::findEssentialMat, a preallocated mask must be continuous");
    std::copy(values.begin(), values.end(), m.ptr<uchar>());
}

} // namespace essential
} // namespace cv

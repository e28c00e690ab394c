// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The output contract the fuzz targets check: what the public API may return. Anything else
// aborts, so that libFuzzer (with AddressSanitizer and UndefinedBehaviorSanitizer) records the
// input. Shared by every target.

#ifndef OPENCV_ESSENTIAL_FUZZ_CONTRACT_HPP
#define OPENCV_ESSENTIAL_FUZZ_CONTRACT_HPP

#include <opencv2/core.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>

namespace essential_fuzz {

[[noreturn]] inline void broken(const char* what)
{
    std::fprintf(stderr, "fuzz: contract broken: %s\n", what);
    std::abort();
}

/** An N x 1 CV_8U mask of 0 and 1, all zero when no E was found. */
inline void checkMask(const cv::Mat& mask, int n, bool allZero)
{
    if (mask.empty() && n == 0) return;
    if (mask.rows != n || mask.cols != 1 || mask.type() != CV_8U) broken("mask shape");
    for (int i = 0; i < n; ++i) {
        const uchar v = mask.at<uchar>(i);
        if (v > 1) broken("mask value other than 0 or 1");
        if (allZero && v) broken("non-zero mask with an empty E");
    }
}

/** E empty, or 3k x 3 CV_64F and finite; the mask as above when one was requested. */
inline void checkEssential(const cv::Mat& E, const cv::Mat& mask, int n, bool maskRequested)
{
    if (!E.empty()) {
        if (E.cols != 3 || E.rows % 3 != 0 || E.rows == 0 || E.type() != CV_64F)
            broken("E shape or type");
        if (!cv::checkRange(E)) broken("non-finite E");
    }
    if (maskRequested) checkMask(mask, n, E.empty());
}

/** recoverPose's answer: a count in [0, n], R a rotation, t a unit or zero vector. */
inline void checkPose(int inFront, const cv::Mat& R, const cv::Mat& t, int n)
{
    if (inFront < 0 || inFront > n) broken("recoverPose count out of range");
    if (R.rows != 3 || R.cols != 3 || R.type() != CV_64F || !cv::checkRange(R)) broken("R shape");
    if (t.rows != 3 || t.cols != 1 || t.type() != CV_64F || !cv::checkRange(t)) broken("t shape");
    const cv::Matx33d Rm = R;
    if (cv::norm(Rm.t() * Rm - cv::Matx33d::eye()) > 1e-6) broken("R not orthonormal");
    const double tn = cv::norm(t);
    if (!(std::abs(tn - 1.0) < 1e-6 || tn == 0.0)) broken("t neither unit nor zero");
}

/** recoverPose's triangulated points: 4 x n CV_64F and finite, or empty with the no-pose answer
(E cannot be decomposed: count 0, t = 0), as essential.hpp documents. */
inline void checkTriangulated(const cv::Mat& X, int n, int inFront, const cv::Mat& t)
{
    if (X.empty() && inFront == 0 && cv::norm(t) == 0.0) return;
    if (X.rows != 4 || X.cols != n || X.type() != CV_64F || !cv::checkRange(X))
        broken("triangulated points shape");
}

/** Runs one input: a cv::Exception is the documented answer to bad input; any other exception
breaks the contract. OpenCV's printing of every CV_Error to stderr is silenced once. */
template <class Run> int runGuarded(Run run)
{
    static const bool quiet = [] {
        cv::redirectError([](int, const char*, const char*, const char*, int, void*) { return 0; });
        return true;
    }();
    (void)quiet;
    try {
        run();
    } catch (const cv::Exception&) {
        // The documented answer to bad input.
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz: not a cv::Exception: %s\n", e.what());
        std::abort();
    }
    return 0;
}

} // namespace essential_fuzz

#endif // OPENCV_ESSENTIAL_FUZZ_CONTRACT_HPP

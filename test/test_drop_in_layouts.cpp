// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Drop-in conformance of findEssentialMatIter's input and output arrays, measured against
// cv::findEssentialMat (OpenCV 4.6) itself at run time, so that it cannot drift from what OpenCV
// does: for every drop-in overload (one test instance each) x point layout x method flag x mask
// form, both throw or neither does, and when neither does E and the mask come out with the same
// shape and type (and, for a preallocated mask, both write into it in place or both reallocate).
// The data are outlier-free and noise-free, so that both searches stop after a few samples and
// the whole set runs in a few seconds.

#include "drop_in_layouts.hpp"
#include "opencv2/essential.hpp"
#include "synthetic_scene.hpp"

#include "essential_test.hpp"
#include <opencv2/calib3d.hpp>

#include <string>
#include <vector>

namespace {

using essential_test::kLayouts;
using essential_test::Layout;
using essential_test::makeScene;
using essential_test::PointArray;
using essential_test::SceneConfig;
using essential_test::SyntheticScene;

constexpr int kPoints = 50;
/** Iteration cap of the forms that take one: with outlier-free data RANSAC stops after its first
sample anyway; LMEDS draws min(maxIters, what 45% outliers need) samples, so the cap bounds it. */
constexpr int kMaxIters = 5;

const SyntheticScene& scene()
{
    static const SyntheticScene s = [] {
        SceneConfig cfg;
        cfg.numPoints = kPoints;
        cfg.inlierRatio = 1.0;
        cfg.noiseSigma = 1e-7; // 0.00005 px: noise-free for both libraries
        cfg.maxDepth = 20.0;   // parallax everywhere
        return makeScene(cfg, 2024);
    }();
    return s;
}

// ---------------------------------------------------------------------------------------------
// Mask forms.

struct MaskArray
{
    enum Kind { None, EmptyMat, Nx1, OneByN, Nx1View, VecUchar, VecInt } kind;
    cv::Mat m, wide;
    std::vector<uchar> vu;
    std::vector<int> vi;
    const uchar* before = nullptr; //!< data pointer of a preallocated Mat, to see reallocation

    explicit MaskArray(Kind k) : kind(k)
    {
        if (k == Nx1) m = cv::Mat(kPoints, 1, CV_8U, cv::Scalar(7));
        if (k == OneByN) m = cv::Mat(1, kPoints, CV_8U, cv::Scalar(7));
        if (k == Nx1View) {
            wide = cv::Mat(kPoints, 3, CV_8U, cv::Scalar(7));
            m = wide.col(1);
        }
        before = m.data;
    }

    cv::_OutputArray arr()
    {
        switch (kind) {
        case None:
            return cv::noArray();
        case VecUchar:
            return cv::_OutputArray(vu);
        case VecInt:
            return cv::_OutputArray(vi);
        default:
            return cv::_OutputArray(m);
        }
    }

    /** What the caller sees afterwards: shape, type, values. */
    cv::Mat result() const
    {
        if (kind == VecUchar) return cv::Mat(vu, true);
        if (kind == VecInt) return cv::Mat(vi, true);
        return m;
    }
    bool writtenInPlace() const { return before != nullptr && m.data == before; }
};

const MaskArray::Kind kMaskKinds[] = {MaskArray::None,   MaskArray::EmptyMat, MaskArray::Nx1,
                                      MaskArray::OneByN, MaskArray::Nx1View,  MaskArray::VecUchar,
                                      MaskArray::VecInt};

const char* maskName(MaskArray::Kind k)
{
    switch (k) {
    case MaskArray::None:
        return "no mask";
    case MaskArray::EmptyMat:
        return "empty Mat";
    case MaskArray::Nx1:
        return "preallocated N x 1 CV_8U";
    case MaskArray::OneByN:
        return "preallocated 1 x N CV_8U";
    case MaskArray::Nx1View:
        return "preallocated N x 1 CV_8U view (not continuous)";
    case MaskArray::VecUchar:
        return "vector<uchar>";
    case MaskArray::VecInt:
        return "vector<int>";
    }
    return "?";
}

// ---------------------------------------------------------------------------------------------
// Methods and overloads.

struct Method
{
    const char* name;
    int flag;
};

const Method kMethods[] = {{"RANSAC", cv::RANSAC},
                           {"LMEDS", cv::LMEDS},
                           {"USAC_DEFAULT", cv::USAC_DEFAULT},
                           {"USAC_PARALLEL", cv::USAC_PARALLEL},
                           {"USAC_FM_8PTS", cv::USAC_FM_8PTS},
                           {"USAC_FAST", cv::USAC_FAST},
                           {"USAC_ACCURATE", cv::USAC_ACCURATE},
                           {"USAC_PROSAC", cv::USAC_PROSAC},
                           {"USAC_MAGSAC", cv::USAC_MAGSAC}};

enum class Overload {
    CameraMaxIters, //!< (K, method, prob, threshold, maxIters, mask)
    Camera,         //!< (K, method, prob, threshold, mask)
    FocalMaxIters,  //!< (focal, pp, method, prob, threshold, maxIters, mask)
    Focal,          //!< (focal, pp, method, prob, threshold, mask)
    TwoCameras,     //!< (K1, d1, K2, d2, method, prob, threshold, mask)
    Usac,           //!< (K1, K2, d1, d2, mask, UsacParams), no distortion coefficients
    UsacDistortion, //!< the same with (zero) distortion coefficients: OpenCV undistorts then
};

const char* overloadName(Overload o)
{
    switch (o) {
    case Overload::CameraMaxIters:
        return "CameraMaxIters";
    case Overload::Camera:
        return "Camera";
    case Overload::FocalMaxIters:
        return "FocalMaxIters";
    case Overload::Focal:
        return "Focal";
    case Overload::TwoCameras:
        return "TwoCameras";
    case Overload::Usac:
        return "UsacParams";
    case Overload::UsacDistortion:
        return "UsacParamsWithDistortion";
    }
    return "?";
}

bool takesNoMaxIters(Overload o)
{
    return o == Overload::Camera || o == Overload::Focal || o == Overload::TwoCameras;
}

/** Calls one overload of cv::findEssentialMat (ours = false) or of findEssentialMatIter. */
cv::Mat callOverload(bool ours, Overload o, int method, const cv::_InputArray& p1,
                     const cv::_InputArray& p2, const cv::_OutputArray& mask)
{
    const cv::Mat K(scene().K);
    const double focal = scene().K(0, 0);
    const cv::Point2d pp(scene().K(0, 2), scene().K(1, 2));
    const cv::Mat zeros = cv::Mat::zeros(5, 1, CV_64F);
    cv::UsacParams usac;
    usac.maxIterations = kMaxIters;
    namespace ess = cv::essential;
    switch (o) {
    case Overload::CameraMaxIters:
        return ours ? ess::findEssentialMatIter(p1, p2, K, method, 0.999, 1.0, kMaxIters, mask)
                    : cv::findEssentialMat(p1, p2, K, method, 0.999, 1.0, kMaxIters, mask);
#if CV_VERSION_MAJOR < 5 // OpenCV 5 has no forms without maxIters (nor has the module there)
    case Overload::Camera:
        return ours ? ess::findEssentialMatIter(p1, p2, K, method, 0.999, 1.0, mask)
                    : cv::findEssentialMat(p1, p2, K, method, 0.999, 1.0, mask);
#endif
    case Overload::FocalMaxIters:
        return ours ? ess::findEssentialMatIter(p1, p2, focal, pp, method, 0.999, 1.0, kMaxIters,
                                                mask)
                    : cv::findEssentialMat(p1, p2, focal, pp, method, 0.999, 1.0, kMaxIters, mask);
#if CV_VERSION_MAJOR < 5
    case Overload::Focal:
        return ours ? ess::findEssentialMatIter(p1, p2, focal, pp, method, 0.999, 1.0, mask)
                    : cv::findEssentialMat(p1, p2, focal, pp, method, 0.999, 1.0, mask);
#endif
    default:
        break;
    case Overload::TwoCameras:
        return ours
                   ? ess::findEssentialMatIter(p1, p2, K, zeros, K, zeros, method, 0.999, 1.0, mask)
                   : cv::findEssentialMat(p1, p2, K, zeros, K, zeros, method, 0.999, 1.0, mask);
    case Overload::Usac:
        return ours ? ess::findEssentialMatIter(p1, p2, K, K, cv::noArray(), cv::noArray(), mask,
                                                usac)
                    : cv::findEssentialMat(p1, p2, K, K, cv::noArray(), cv::noArray(), mask, usac);
    case Overload::UsacDistortion:
        return ours ? ess::findEssentialMatIter(p1, p2, K, K, zeros, zeros, mask, usac)
                    : cv::findEssentialMat(p1, p2, K, K, zeros, zeros, mask, usac);
    }
    return cv::Mat();
}

/** The outcome of one call, as a caller sees it. */
struct Outcome
{
    bool threw = false;
    std::string error;
    cv::Mat E, mask;
    bool maskInPlace = false;
};

Outcome run(bool ours, Overload o, int method, const PointArray& a, const PointArray& b,
            MaskArray::Kind maskKind)
{
    Outcome out;
    MaskArray mask(maskKind);
    try {
        out.E = callOverload(ours, o, method, a.arr(), b.arr(), mask.arr());
        out.mask = mask.result();
        out.maskInPlace = mask.writtenInPlace();
    } catch (const cv::Exception& e) {
        out.threw = true;
        out.error = e.err;
    }
    return out;
}

std::string describe(const cv::Mat& m)
{
    return std::to_string(m.rows) + " x " + std::to_string(m.cols) + " " +
           cv::typeToString(m.type());
}

class DropInLayouts : public ::testing::TestWithParam<Overload>
{
};

TEST_P(DropInLayouts, AcceptRejectAndOutputsAsOpenCV)
{
    const Overload o = GetParam();
    const bool usacForm = o == Overload::Usac || o == Overload::UsacDistortion;
    int compared = 0, accepted = 0;
    for (const Layout& layout : kLayouts) {
        const PointArray a = layout.make(scene().px1), b = layout.make(scene().px2);
        for (const Method& method : kMethods) {
            // The UsacParams forms take no method flag: run them once.
            if (usacForm && method.flag != cv::RANSAC) continue;
            for (const MaskArray::Kind maskKind : kMaskKinds) {
                // OpenCV's LMEDS draws min(maxIters, 134) samples at 0.4 ms each (its five-point
                // solver), 55 ms a call in the forms without maxIters (1000): there, every layout
                // with one mask form and every mask form with the first layout.
                if (method.flag == cv::LMEDS && takesNoMaxIters(o) &&
                    maskKind != MaskArray::EmptyMat && &layout != &kLayouts[0])
                    continue;
                SCOPED_TRACE(std::string(layout.name) + ", " +
                             (usacForm ? "UsacParams" : method.name) + ", " + maskName(maskKind));
                const Outcome cv = run(false, o, method.flag, a, b, maskKind);
                const Outcome us = run(true, o, method.flag, a, b, maskKind);
                ++compared;
                ASSERT_EQ(us.threw, cv.threw) << "OpenCV: " << (cv.threw ? cv.error : "accepted")
                                              << "\nours: " << (us.threw ? us.error : "accepted");
                if (cv.threw) continue;
                ++accepted;
                EXPECT_EQ(describe(us.E), describe(cv.E));
                EXPECT_EQ(describe(us.mask), describe(cv.mask));
                EXPECT_EQ(us.maskInPlace, cv.maskInPlace);
                if (!us.mask.empty()) {
                    // Outlier-free, noise-free data: every point an inlier for both libraries.
                    // Whole-pixel int layouts carry 0.3 px rms of rounding, below the 1 px
                    // threshold, but some points fall outside, more so under the USAC flags'
                    // symmetric epipolar distance (at least twice the Sampson distance): 43 of
                    // 50 kept there (clang -O1), so int layouts are held to 4/5.
                    const std::string name = layout.name;
                    const bool rounded = name.find("(int)") != std::string::npos ||
                                         name.find("CV_32S") != std::string::npos;
                    cv::Mat m8;
                    us.mask.convertTo(m8, CV_8U);
                    EXPECT_EQ(cv::countNonZero(m8 > 1), 0) << "mask values must be 0 or 1";
                    EXPECT_GE(cv::countNonZero(m8), rounded ? kPoints * 4 / 5 : kPoints * 9 / 10);
                }
            }
        }
    }
    RecordProperty("combinations", compared);
    RecordProperty("accepted", accepted);
    EXPECT_GT(accepted, 0);
}

INSTANTIATE_TEST_SUITE_P(EveryDropInOverload, DropInLayouts,
                         ::testing::Values(Overload::CameraMaxIters,
#if CV_VERSION_MAJOR < 5
                                           Overload::Camera, Overload::Focal,
#endif
                                           Overload::FocalMaxIters, Overload::TwoCameras,
                                           Overload::Usac, Overload::UsacDistortion),
                         [](const ::testing::TestParamInfo<Overload>& paramInfo) {
                             return std::string(overloadName(paramInfo.param));
                         });

// Two arrays of different layouts: OpenCV's RANSAC and LMEDS need the same number of channels
// (a vector of points, two channels, cannot be paired with an N x 2 matrix), its USAC flags and
// its distortion forms do not.
TEST(DropInLayouts, MixedLayoutsAsOpenCV)
{
    const std::pair<int, int> pairs[] = {{0, 5}, {5, 8}, {4, 5}, {11, 5}, {1, 9}, {12, 5}, {6, 5}};
    int compared = 0;
    for (const auto& [first, second] : pairs) {
        const Layout &la = kLayouts[first], &lb = kLayouts[second];
        const PointArray a = la.make(scene().px1), b = lb.make(scene().px2);
        for (const Overload o : {Overload::CameraMaxIters, Overload::TwoCameras, Overload::Usac})
            for (const int method : {cv::RANSAC, cv::LMEDS, cv::USAC_DEFAULT}) {
                SCOPED_TRACE(std::string(la.name) + " with " + lb.name + ", " + overloadName(o) +
                             ", method " + std::to_string(method));
                const Outcome cv = run(false, o, method, a, b, MaskArray::EmptyMat);
                const Outcome us = run(true, o, method, a, b, MaskArray::EmptyMat);
                ++compared;
                ASSERT_EQ(us.threw, cv.threw) << "OpenCV: " << (cv.threw ? cv.error : "accepted")
                                              << "\nours: " << (us.threw ? us.error : "accepted");
                if (!cv.threw) {
                    EXPECT_EQ(describe(us.mask), describe(cv.mask));
                }
            }
    }
    EXPECT_EQ(compared, 7 * 9);
}

} // namespace

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Our own declaration of OpenCV 4.x's robust-estimation loop interface, so that the module's
// solvers can run inside the RANSAC and LMedS loops that libopencv_calib3d exports (the loops
// cv::findEssentialMat itself uses). Used by opencv_loop/opencv_loop.cpp and by the configure-time
// probe cmake/ProbeOpenCvLoop.cmake; nothing else should include it.
//
// Why it exists: libopencv_calib3d (4.x) exports cv::createRANSACPointSetRegistrator and
// cv::createLMeDSPointSetRegistrator, but the class they return and the kernel interface they take,
// cv::PointSetRegistrator and cv::PointSetRegistrator::Callback, are declared only in OpenCV's
// private calib3d/src/precomp.hpp, which is not installed. This file declares them again, written
// from what that header and the library's exported symbols show (OpenCV 4.6.0): the same
// namespace, class names, base class, virtual functions in the same order with the same
// signatures, and the same factory signatures, so that the vtables and mangled names agree.
//
// RISK: this is an ABI copy of a private class. OpenCV does not promise to keep it stable; if a
// release reorders, adds or changes these virtual functions or the factories, code compiled
// against this declaration would call the wrong slots (undefined behaviour, typically a crash).
// The configure-time probe (cmake/ProbeOpenCvLoop.cmake) compiles a small program against this
// exact declaration, runs both loops on a trivial kernel, checks that every virtual function is
// reached and that the results are right, and enables ENGINE_OPENCV (ESSENTIAL_HAVE_OPENCV_LOOP)
// only if it passes. Re-run CMake after upgrading OpenCV.
//
// Matches OpenCV 4.6.0 (modules/calib3d/src/precomp.hpp); the interface has been unchanged
// through the 4.x series that introduced it, but only the probe's verdict counts.

#ifndef OPENCV_ESSENTIAL_OPENCV_LOOP_OPENCV_POINT_SET_REGISTRATOR_HPP
#define OPENCV_ESSENTIAL_OPENCV_LOOP_OPENCV_POINT_SET_REGISTRATOR_HPP

#include <opencv2/core.hpp>

namespace cv {

/** A robust estimator loop (RANSAC or LMedS) over a model kernel; the object
createRANSACPointSetRegistrator() / createLMeDSPointSetRegistrator() return. Derived from
cv::Algorithm, whose virtual functions come first in the vtable. */
class CV_EXPORTS PointSetRegistrator : public Algorithm
{
public:
    /** The model kernel the loop calls. Slot order: destructor, runKernel, computeError,
    checkSubset. */
    class CV_EXPORTS Callback
    {
    public:
        virtual ~Callback() {}

        /** Fits models to the sample (m1, m2: the sampled rows of the data, same type and layout);
        writes n models stacked by rows into `model` and returns n (0 or less: no model). */
        virtual int runKernel(InputArray m1, InputArray m2, OutputArray model) const = 0;

        /** Writes one error per data point for `model` into `err` (CV_32F, one column). The
        RANSAC loop counts a point as an inlier when its error is <= threshold^2; the LMedS loop
        takes the median error. */
        virtual void computeError(InputArray m1, InputArray m2, InputArray model,
                                  OutputArray err) const = 0;

        /** Accepts or rejects a sample of `count` points before runKernel; rejected samples are
        redrawn. */
        virtual bool checkSubset(InputArray m1, InputArray m2, int count) const
        {
            (void)m1;
            (void)m2;
            (void)count;
            return true;
        }
    };

    /** Slots after cv::Algorithm's: setCallback, then run. */
    virtual void setCallback(const Ptr<PointSetRegistrator::Callback>& cb) = 0;

    /** Runs the loop on the data (m1, m2); returns true and writes the best model and the inlier
    mask (count x 1 CV_8U) when a model is found. */
    virtual bool run(InputArray m1, InputArray m2, OutputArray model, OutputArray mask) const = 0;
};

/** RANSAC loop: samples of modelPoints points, inliers have error <= threshold^2, the number of
iterations adapts to the best inlier count by OpenCV's formula (modelPoints, confidence) up to
maxIters. Exported by libopencv_calib3d 4.x. */
CV_EXPORTS Ptr<PointSetRegistrator>
createRANSACPointSetRegistrator(const Ptr<PointSetRegistrator::Callback>& cb, int modelPoints,
                                double threshold, double confidence = 0.99, int maxIters = 1000);

/** LMedS loop: a fixed number of samples for an assumed 45% of outliers (capped at maxIters),
the model of least median error wins. Exported by libopencv_calib3d 4.x. */
CV_EXPORTS Ptr<PointSetRegistrator>
createLMeDSPointSetRegistrator(const Ptr<PointSetRegistrator::Callback>& cb, int modelPoints,
                               double confidence = 0.99, int maxIters = 1000);

} // namespace cv

#endif

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The private hook of bench/python/bench_cv_essential.py: the thread CPU time of the C++ call
// alone, on the clock Python's time.thread_time reads (CLOCK_THREAD_CPUTIME_ID), so that the
// binding's overhead is one clock's difference.

#include "bindings.hpp"
#include "cv2_arrays.hpp"
#include "cv2_errors.hpp"

#include <opencv2/essential.hpp>

#include <time.h>

namespace cv_essential_py {

namespace {

double threadCpuMs()
{
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return 1e3 * static_cast<double>(ts.tv_sec) + 1e-6 * static_cast<double>(ts.tv_nsec);
}

/** findEssentialMatIter(points1, points2, cameraMatrix, params) in C++, timed around the call
only (the arrays are converted before, the results are not returned). */
double nativeCallMs(const InputMat& points1, const InputMat& points2, const InputMat& cameraMatrix,
                    const cv::essential::EssentialParams& params)
{
    double ms = 0;
    withoutGil([&] {
        cv::Mat mask;
        cv::essential::EssentialReport report;
        const double start = threadCpuMs();
        cv::essential::findEssentialMatIter(points1.mat, points2.mat, cameraMatrix.mat, params,
                                            mask, &report);
        ms = threadCpuMs() - start;
    });
    return ms;
}

} // namespace

void defineOverheadProbe(py::module_& forms)
{
    forms.def("nativeCallMs", &nativeCallMs, py::arg("points1"), py::arg("points2"),
              py::arg("cameraMatrix"), py::arg("params"));
}

} // namespace cv_essential_py

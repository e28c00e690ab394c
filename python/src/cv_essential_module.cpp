// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The Python module cv_essential (pybind11): the drop-in findEssentialMatIter with cv2's
// conventions. Work in progress: the camera-matrix form only, so far (see python/README.md).

#include <opencv2/essential.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

namespace py = pybind11;

namespace {

/** cv2.error, the exception cv2 raises for cv::Exception; the module raises the same. */
py::object cv2Error()
{
    static py::object error = py::module_::import("cv2").attr("error");
    return error;
}

/** A numpy array as a cv::Mat sharing its memory (C-contiguous float32/float64/int32/uint8,
1 to 3 dimensions; the last dimension of a 3-D array becomes the channels, as cv2 reads it). */
cv::Mat asMat(const py::array& a, const char* name)
{
    const py::buffer_info info = a.request();
    int depth = -1;
    if (info.format == py::format_descriptor<float>::format())
        depth = CV_32F;
    else if (info.format == py::format_descriptor<double>::format())
        depth = CV_64F;
    else if (info.format == py::format_descriptor<int>::format())
        depth = CV_32S;
    else if (info.format == py::format_descriptor<unsigned char>::format())
        depth = CV_8U;
    if (depth < 0 || info.ndim < 1 || info.ndim > 3)
        throw py::type_error(std::string(name) +
                             ": expected a float32, float64, int32 or uint8 array of 1 to 3 "
                             "dimensions");
    const int rows = static_cast<int>(info.shape[0]);
    const int cols = info.ndim >= 2 ? static_cast<int>(info.shape[1]) : 1;
    const int channels = info.ndim == 3 ? static_cast<int>(info.shape[2]) : 1;
    return cv::Mat(rows, cols, CV_MAKETYPE(depth, channels), info.ptr);
}

py::array toArray(const cv::Mat& m)
{
    if (m.empty()) return py::array_t<double>(std::vector<py::ssize_t>{0, 0});
    cv::Mat c = m.isContinuous() ? m : m.clone();
    if (c.depth() == CV_8U) {
        py::array_t<unsigned char> out({c.rows, c.cols});
        std::memcpy(out.mutable_data(), c.data, c.total() * c.elemSize());
        return std::move(out);
    }
    cv::Mat d;
    c.convertTo(d, CV_64F);
    py::array_t<double> out({d.rows, d.cols * d.channels()});
    std::memcpy(out.mutable_data(), d.data, d.total() * d.elemSize());
    return std::move(out);
}

py::tuple findEssentialMatIterCamera(const py::array& points1, const py::array& points2,
                                     const py::array& cameraMatrix, int method, double prob,
                                     double threshold, int maxIters)
{
    const cv::Mat p1 = asMat(points1, "points1"), p2 = asMat(points2, "points2");
    const cv::Mat K = asMat(cameraMatrix, "cameraMatrix");
    cv::Mat E, mask;
    try {
        py::gil_scoped_release release;
        E = cv::essential::findEssentialMatIter(p1, p2, K, method, prob, threshold, maxIters, mask);
    } catch (const cv::Exception& e) {
        PyErr_SetString(cv2Error().ptr(), e.what());
        throw py::error_already_set();
    }
    return py::make_tuple(toArray(E), mask.empty() ? py::object(py::none()) : toArray(mask));
}

} // namespace

PYBIND11_MODULE(cv_essential, m)
{
    m.doc() = "opencv_essential: essential-matrix estimation with iterative minimal-set solvers, "
              "a drop-in for cv2.findEssentialMat (work in progress)";
    m.def("findEssentialMatIter", &findEssentialMatIterCamera, py::arg("points1"),
          py::arg("points2"), py::arg("cameraMatrix"),
          py::arg("method") = static_cast<int>(cv::RANSAC), py::arg("prob") = 0.999,
          py::arg("threshold") = 1.0, py::arg("maxIters") = 1000,
          "findEssentialMatIter(points1, points2, cameraMatrix[, method[, prob[, threshold[, "
          "maxIters]]]]) -> retval, mask\n\nAs cv2.findEssentialMat (camera-matrix form).");
}

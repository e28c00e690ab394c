// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Arrays in and out as cv2 4.6 passes them: which Python objects an InputArray argument accepts,
// how they become a cv::Mat, and how a cv::Mat goes back to numpy.

#ifndef CV_ESSENTIAL_PY_CV2_ARRAYS_HPP
#define CV_ESSENTIAL_PY_CV2_ARRAYS_HPP

#include <opencv2/core.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

namespace cv_essential_py {

namespace py = pybind11;

/** An array argument converted as cv2 converts it: `mat` shares the memory of `owner` (the
numpy array itself, or a contiguous copy of it), which keeps it alive for the call. */
struct InputMat
{
    cv::Mat mat;
    py::object owner;
};

/** Converts `src` as cv2 4.6 converts an InputArray argument, measured against cv2 in
python/tests/test_layouts.py:
- None: an empty Mat;
- a Python number (bool, int, float): a 4 x 1 CV_64F Mat (v, 0, 0, 0), as cv2 reads a scalar;
- a tuple of numbers: an n x 1 CV_64F Mat;
- a numpy array of uint8, int8, uint16, int16, int32, float32 or float64 (and float16, as
  CV_16F, when built against OpenCV 4.8 or later, whose cv2 reads it so): a Mat of that depth
  sharing its memory (copied first when it is not C-contiguous). 1-D arrays are n x 1; 2-D are
  rows x cols; 3-D arrays with at most CV_CN_MAX in the last dimension are rows x cols with that
  many channels; other shapes are n-dimensional Mats (which the estimators then reject).
  int64 and uint64 arrays are converted to float64, exactly for |values| < 2^53 (cv2 casts them
  to int32, which wraps larger values silently).
Anything else (lists, complex / object arrays, bool and uint32 before OpenCV 5, float16 before 4.8,
strings) is refused: returns false and, when `why` is given, says what was expected. */
bool toInputMat(py::handle src, InputMat& out, std::string* why);

/** A Mat as cv2 returns it: None when empty; otherwise a new numpy array of the Mat's depth,
rows x cols, or rows x cols x channels when it has several channels. */
py::object toNumpy(const cv::Mat& m);

} // namespace cv_essential_py

namespace pybind11 {
namespace detail {

/** Lets pybind11 functions take InputMat arguments. A failed conversion makes pybind11 try the
next overload, as cv2's dispatcher does. */
template <> struct type_caster<cv_essential_py::InputMat>
{
    PYBIND11_TYPE_CASTER(cv_essential_py::InputMat, const_name("numpy.ndarray"));
    bool load(handle src, bool /*convert: cv2 converts in every pass*/)
    {
        return cv_essential_py::toInputMat(src, value, nullptr);
    }
    static handle cast(const cv_essential_py::InputMat& m, return_value_policy, handle)
    {
        return cv_essential_py::toNumpy(m.mat).release();
    }
};

} // namespace detail
} // namespace pybind11

#endif // CV_ESSENTIAL_PY_CV2_ARRAYS_HPP

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "cv2_arrays.hpp"

#include <cstring>
#include <vector>

namespace cv_essential_py {

namespace {

bool isNumber(PyObject* o)
{
    return PyBool_Check(o) || PyLong_Check(o) || PyFloat_Check(o);
}

/** cv2 maps numpy's float16 to CV_16F from OpenCV 4.8 on (opencv/opencv#23691, merged for 4.8.0)
and refuses it before; the module follows the OpenCV it is built against. */
constexpr bool kReadsFloat16 = CV_VERSION_MAJOR > 4 ||
                               (CV_VERSION_MAJOR == 4 && CV_VERSION_MINOR >= 8);

/** OpenCV's depth for a numpy dtype that cv2 of the same version passes through; -1 for the
others (int64 and uint64 are handled by the caller). */
int depthOf(const py::dtype& dt)
{
    const char kind = dt.kind();
    const auto size = dt.itemsize();
    if (kind == 'u' && size == 1) return CV_8U;
    if (kind == 'i' && size == 1) return CV_8S;
    if (kind == 'u' && size == 2) return CV_16U;
    if (kind == 'i' && size == 2) return CV_16S;
    if (kind == 'i' && size == 4) return CV_32S;
    if (kind == 'f' && size == 2 && kReadsFloat16) return CV_16F;
#if CV_VERSION_MAJOR >= 5
    // OpenCV 5 has unsigned 32-bit and boolean depths, and its cv2 reads such arrays as them.
    if (kind == 'u' && size == 4) return CV_32U;
    if (kind == 'b' && size == 1) return CV_Bool;
#endif
    if (kind == 'f' && size == 4) return CV_32F;
    if (kind == 'f' && size == 8) return CV_64F;
    return -1;
}

/** numpy's byte-order flag read from the descriptor itself ('=' native, '|' not applicable,
'<' or '>' explicit): no Python attribute lookup on the per-call path. */
bool isNativeByteOrder(const py::dtype& dt)
{
    const char order = py::detail::array_descriptor_proxy(dt.ptr())->byteorder;
    const char native = py::detail::array_descriptor_proxy(py::dtype::of<int>().ptr())->byteorder;
    return order == '=' || order == '|' || order == native ||
           (native == '=' && order == (PY_LITTLE_ENDIAN ? '<' : '>'));
}

bool refuse(std::string* why, const std::string& reason)
{
    if (why) *why = reason;
    return false;
}

std::string describe(py::handle src)
{
    if (py::isinstance<py::array>(src)) {
        const py::array a = py::reinterpret_borrow<py::array>(src);
        return "a numpy array of " + py::str(a.dtype()).cast<std::string>();
    }
    return "a " + py::str(py::type::handle_of(src).attr("__name__")).cast<std::string>();
}

const char* const kExpected =
    kReadsFloat16
        ? "expected a numpy array of uint8, int8, uint16, int16, int32, int64, uint64, float16, "
          "float32 or float64 (N x 2 or N x 1 x 2 for points), a number, a tuple of numbers or None"
        : "expected a numpy array of uint8, int8, uint16, int16, int32, int64, uint64, float32 or "
          "float64 (N x 2 or N x 1 x 2 for points), a number, a tuple of numbers or None";

} // namespace

bool toInputMat(py::handle src, InputMat& out, std::string* why)
{
    PyObject* o = src.ptr();
    out = InputMat();
    if (src.is_none()) return true;
    if (isNumber(o)) {
        const double v = PyFloat_AsDouble(o);
        if (PyErr_Occurred()) { // an int too large for a double
            PyErr_Clear();
            return refuse(why, "a number that does not fit in a double");
        }
        out.mat = cv::Mat(cv::Matx<double, 4, 1>(v, 0, 0, 0));
        return true;
    }
    if (PyTuple_Check(o)) {
        const Py_ssize_t n = PyTuple_GET_SIZE(o);
        cv::Mat m(static_cast<int>(n), 1, CV_64F);
        for (Py_ssize_t i = 0; i < n; ++i) {
            PyObject* item = PyTuple_GET_ITEM(o, i);
            if (!isNumber(item))
                return refuse(why,
                              std::string(kExpected) + "; got a tuple of " + describe(item) + "s");
            m.at<double>(static_cast<int>(i)) = PyFloat_AsDouble(item);
        }
        out.mat = m;
        return true;
    }
    if (!py::isinstance<py::array>(src))
        return refuse(why, std::string(kExpected) + "; got " + describe(src));
    py::array a = py::reinterpret_borrow<py::array>(src);
    py::dtype dt = a.dtype();
    if (!isNativeByteOrder(dt)) {
        // cv2 converts arrays of the other byte order; so does the module (a native copy).
        try {
            a = a.attr("astype")(dt.attr("newbyteorder")("="));
        } catch (py::error_already_set&) {
            return refuse(why, "could not convert " + describe(src) + " to native byte order");
        }
        dt = a.dtype();
    }
    int depth = depthOf(dt);
    if (depth < 0 && (dt.kind() == 'i' || dt.kind() == 'u') && dt.itemsize() == 8) {
        // cv2 casts 64-bit integers to int32; float64 keeps every value below 2^53 exact.
        a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
        if (!a) {
            PyErr_Clear();
            return refuse(why, "could not convert " + describe(src) + " to float64");
        }
        depth = CV_64F;
    }
    if (depth < 0) return refuse(why, std::string(kExpected) + "; got " + describe(src));
    if (!(a.flags() & py::array::c_style)) {
        a = py::array::ensure(a, py::array::c_style);
        if (!a) {
            PyErr_Clear();
            return refuse(why, "could not make a contiguous copy of " + describe(src));
        }
    }
    const auto ndim = a.ndim();
    if (ndim > 32) // cv::Mat holds up to CV_MAX_DIM (32) dimensions
        return refuse(why, "an array of more than 32 dimensions");
    void* data = const_cast<void*>(a.data());
    if (ndim == 0) {
        out.mat = cv::Mat(1, 1, CV_MAKETYPE(depth, 1), data);
    } else if (ndim == 1) {
        out.mat = cv::Mat(static_cast<int>(a.shape(0)), 1, CV_MAKETYPE(depth, 1), data);
    } else if (ndim == 2 || (ndim == 3 && a.shape(2) <= CV_CN_MAX)) {
        const int channels = ndim == 3 ? static_cast<int>(a.shape(2)) : 1;
        out.mat = cv::Mat(static_cast<int>(a.shape(0)), static_cast<int>(a.shape(1)),
                          CV_MAKETYPE(depth, channels), data);
    } else {
        std::vector<int> sizes(static_cast<size_t>(ndim));
        for (py::ssize_t i = 0; i < ndim; ++i)
            sizes[static_cast<size_t>(i)] = static_cast<int>(a.shape(i));
        out.mat = cv::Mat(static_cast<int>(ndim), sizes.data(), CV_MAKETYPE(depth, 1), data);
    }
    out.owner = a;
    return true;
}

py::object toNumpy(const cv::Mat& m)
{
    if (m.empty()) return py::none();
    py::dtype dt;
    switch (m.depth()) {
    case CV_8U:
        dt = py::dtype::of<uint8_t>();
        break;
    case CV_8S:
        dt = py::dtype::of<int8_t>();
        break;
    case CV_16U:
        dt = py::dtype::of<uint16_t>();
        break;
    case CV_16S:
        dt = py::dtype::of<int16_t>();
        break;
    case CV_32S:
        dt = py::dtype::of<int32_t>();
        break;
    case CV_32F:
        dt = py::dtype::of<float>();
        break;
    default: // CV_64F, and CV_16F converted to it
        dt = py::dtype::of<double>();
        break;
    }
    cv::Mat src = m;
    if (m.depth() == CV_16F) m.convertTo(src, CV_64F);
    if (!src.isContinuous()) src = src.clone();
    std::vector<py::ssize_t> shape;
    if (src.dims > 2) {
        for (int i = 0; i < src.dims; ++i)
            shape.push_back(src.size[i]);
    } else {
        shape = {src.rows, src.cols};
    }
    if (src.channels() > 1) shape.push_back(src.channels());
    py::array out(dt, shape);
    std::memcpy(out.mutable_data(), src.data, src.total() * src.elemSize());
    return py::object(std::move(out));
}

} // namespace cv_essential_py

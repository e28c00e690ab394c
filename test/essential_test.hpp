// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The test framework of the module's tests. The same test files are compiled by two builds:
//  - standalone (test/CMakeLists.txt): GoogleTest as installed;
//  - inside an OpenCV source build (modules/essential/cmake/in_opencv.cmake, which defines
//    ESSENTIAL_OPENCV_TS): OpenCV's ts (opencv2/ts.hpp), whose bundled GoogleTest 1.8 predates
//    the two spellings below that the tests use. Tests include this header, never gtest directly.
#ifndef ESSENTIAL_TEST_ESSENTIAL_TEST_HPP
#define ESSENTIAL_TEST_ESSENTIAL_TEST_HPP

#ifdef ESSENTIAL_OPENCV_TS

#include <opencv2/ts.hpp>

#include <sstream>

// GoogleTest 1.10's name for INSTANTIATE_TEST_CASE_P.
#ifndef INSTANTIATE_TEST_SUITE_P
#define INSTANTIATE_TEST_SUITE_P INSTANTIATE_TEST_CASE_P
#endif

#ifndef GTEST_SKIP
namespace essential_test {
// Collects the reason streamed after GTEST_SKIP() and ends the test body with ts's skip exception,
// which OpenCV's TEST / TEST_F / TEST_P wrappers (ts_ext.hpp) report as a skipped test.
class SkipReason
{
public:
    std::ostringstream& stream() { return reason_; }
    [[noreturn]] void raise() const { throw cvtest::SkipTestException(reason_.str()); }

private:
    std::ostringstream reason_;
};
} // namespace essential_test

// `GTEST_SKIP() << reason;` streams into the reason, then the loop's increment throws, so the
// statement leaves the test body as GoogleTest's GTEST_SKIP does.
#define GTEST_SKIP()                                                                               \
    for (::essential_test::SkipReason essential_skip_reason_;; essential_skip_reason_.raise())     \
    essential_skip_reason_.stream()
#endif

#else

#include <gtest/gtest.h>

#endif

#endif // ESSENTIAL_TEST_ESSENTIAL_TEST_HPP

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// main() of opencv_test_essential, the in-tree build's accuracy tests (OpenCV's ts). The tests
// themselves are the files of the repository's test/ folder, shared with the standalone build
// (modules/essential/cmake/in_opencv.cmake); none of them reads test data.

#include "essential_test.hpp"

CV_TEST_MAIN("")

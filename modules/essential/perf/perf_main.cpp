// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// main() of opencv_perf_essential, the in-tree build's perf tests (OpenCV's ts perf framework).

#include <opencv2/ts.hpp>

CV_PERF_TEST_MAIN(essential)

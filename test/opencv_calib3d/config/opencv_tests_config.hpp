// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Stands in for the opencv_tests_config.hpp that OpenCV's build generates for its test framework.
// It would name an install prefix and a test data path; none is given, as OpenCV's test data
// (opencv_extra) is not used: the essential-matrix tests generate their data.

// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Stands in for the cvconfig.h that OpenCV's build generates and does not install, which OpenCV's
// test framework (modules/ts) includes. It defines no HAVE_* feature: the framework is then built
// without its OpenCL, CUDA and IPP parts, which the essential-matrix tests do not use.
#ifndef ESSENTIAL_TEST_OPENCV_CVCONFIG_H
#define ESSENTIAL_TEST_OPENCV_CVCONFIG_H
#endif

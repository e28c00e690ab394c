# The ctest entry opencv_calib3d/cases_cover_the_sources: every GoogleTest case of the fetched
# OpenCV test files whose body calls findEssentialMat or recoverPose must be one of the cases the
# entries opencv_calib3d/* run, so that a newer OpenCV's new case is not silently left out.
#
#   cmake -DCASES="A.b;C.d" -DTEST_DIR=<opencv>/modules/calib3d/test -DFILES="test_usac;..." -P
#
# A case is the Suite.name of a TEST, TEST_F or TEST_P; its body runs to the next such line. Cases
# whose call sits in a helper class (test_fundam.cpp's Calib3d_FindEssentialMat.accuracy calls
# its CV_EssentialMatTest object) are listed by hand and not found here; that is why the check is
# one way. Licensed under the Apache License, Version 2.0.
cmake_minimum_required(VERSION 3.16)

foreach(var CASES TEST_DIR FILES)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_cases.cmake: ${var} is not set")
  endif()
endforeach()

set(found)
foreach(name ${FILES})
  set(path ${TEST_DIR}/${name}.cpp)
  if(NOT EXISTS ${path})
    message(FATAL_ERROR "check_cases.cmake: ${path} does not exist")
  endif()
  file(STRINGS ${path} lines)
  set(current)
  foreach(line IN LISTS lines)
    if(line MATCHES "^[ \t]*TEST(_P|_F)?[ \t]*\\([ \t]*([A-Za-z0-9_]+)[ \t]*,[ \t]*([A-Za-z0-9_]+)[ \t]*\\)")
      set(current "${CMAKE_MATCH_2}.${CMAKE_MATCH_3}")
    elseif(current AND line MATCHES "(^|[^A-Za-z0-9_])(findEssentialMat|recoverPose)[ \t]*\\(")
      list(APPEND found ${current})
    endif()
  endforeach()
endforeach()
list(REMOVE_DUPLICATES found)

set(missing)
foreach(case ${found})
  if(NOT case IN_LIST CASES)
    list(APPEND missing ${case})
  endif()
endforeach()
list(LENGTH found count)
message(STATUS "check_cases.cmake: ${count} cases call findEssentialMat or recoverPose: ${found}")
foreach(case ${CASES})
  if(NOT case IN_LIST found)
    message(STATUS "check_cases.cmake: listed ${case} is not found by the scan (a helper class "
                   "calls it, or this version has no such case)")
  endif()
endforeach()
if(missing)
  message(FATAL_ERROR "check_cases.cmake: not run by opencv_calib3d/*: ${missing}; add them to "
                      "OPENCV_CALIB3D_CASES in test/opencv_calib3d/CMakeLists.txt")
endif()

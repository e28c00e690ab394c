# cmake -DINPUT=<OpenCV test .cpp> -DOUTPUT=<copy> -P rename_calls.cmake
#
# Writes a copy of one of OpenCV's calib3d test files in which every call of cv::findEssentialMat
# goes to cv::essential::findEssentialMatIter and every call of cv::recoverPose to
# cv::essential::recoverPose (the module has all four overloads of OpenCV 4.6), and which includes
# opencv2/essential.hpp after the test's own precompiled header. A call is the name followed by
# '(', bare (the tests are inside
# `using namespace cv`) or as cv::name; the names inside strings and comments are left alone
# because there they are never followed by '('. Fails when the file has no such call or when a
# call is left over, so that a change in OpenCV's tests cannot make this copy test OpenCV again.
# Licensed under the Apache License, Version 2.0.
if(NOT INPUT OR NOT OUTPUT)
  message(FATAL_ERROR "usage: cmake -DINPUT=<file> -DOUTPUT=<file> -P rename_calls.cmake")
endif()
file(READ "${INPUT}" text)

set(calls 0)
# rename_call(NAME REPLACEMENT): rewrites NAME( and cv::NAME( (not other::NAME( or fooNAME().
macro(rename_call name replacement)
  # Placeholders first, so that the replacement (which contains the name) is not matched again.
  string(REPLACE "cv::${name}(" "@RENAMED_${name}@(" text "${text}")
  string(REGEX REPLACE "([^A-Za-z0-9_:])${name}\\(" "\\1@RENAMED_${name}@(" text "${text}")
  string(REGEX MATCHALL "@RENAMED_${name}@\\(" found "${text}")
  list(LENGTH found count)
  math(EXPR calls "${calls} + ${count}")
  string(REPLACE "@RENAMED_${name}@(" "${replacement}(" text "${text}")
  message(STATUS "${INPUT}: ${count} call(s) of ${name} -> ${replacement}")
endmacro()

rename_call(findEssentialMat cv::essential::findEssentialMatIter)
rename_call(recoverPose cv::essential::recoverPose)
if(calls EQUAL 0)
  message(FATAL_ERROR "${INPUT} calls neither findEssentialMat nor recoverPose")
endif()
string(REGEX MATCH "([^A-Za-z0-9_:.>])(findEssentialMat|recoverPose) *\\(" leftover "${text}")
if(leftover)
  message(FATAL_ERROR "${INPUT}: a call was not renamed: '${leftover}'")
endif()

set(precomp "#include \"test_precomp.hpp\"")
string(FIND "${text}" "${precomp}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${INPUT} does not include test_precomp.hpp")
endif()
string(REPLACE "${precomp}" "${precomp}\n#include \"opencv2/essential.hpp\"" text "${text}")

file(WRITE "${OUTPUT}.partial" "${text}")
file(RENAME "${OUTPUT}.partial" "${OUTPUT}")

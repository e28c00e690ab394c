# Runs essential_pair with --json (and --draw DRAW) and checks a plausible pose: exit status 0,
# cv::essential's inlier ratio at least MIN_INLIER_RATIO, and its translation direction within
# MAX_T_DIFF_DEG of cv::findEssentialMat + cv::recoverPose on the same matches; the drawing exists.
# Arguments: COMMAND (a ;-list ending in --json), DRAW, MIN_INLIER_RATIO, MAX_T_DIFF_DEG.
# Licensed under the Apache License, Version 2.0.
file(REMOVE "${DRAW}")
execute_process(COMMAND ${COMMAND} --draw ${DRAW} RESULT_VARIABLE code OUTPUT_VARIABLE json
                ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "essential_pair exited with ${code}: ${err}")
endif()
string(JSON found GET "${json}" essential found)
string(JSON ratio GET "${json}" essential inlier_ratio)
string(JSON cvRatio GET "${json}" opencv inlier_ratio)
string(JSON tDiff GET "${json}" difference translation_direction_deg)
string(JSON rDiff GET "${json}" difference rotation_deg)
string(JSON matches GET "${json}" frontend matches)
message(STATUS "matches ${matches}, inlier ratio ${ratio} (OpenCV ${cvRatio}), "
               "difference to OpenCV: t ${tDiff} deg, R ${rDiff} deg")
if(NOT found)
  message(FATAL_ERROR "no essential matrix found")
endif()
if(ratio LESS MIN_INLIER_RATIO)
  message(FATAL_ERROR "inlier ratio ${ratio} below ${MIN_INLIER_RATIO}")
endif()
if(tDiff GREATER MAX_T_DIFF_DEG)
  message(FATAL_ERROR "translation direction ${tDiff} deg from OpenCV's (max ${MAX_T_DIFF_DEG})")
endif()
if(NOT EXISTS "${DRAW}")
  message(FATAL_ERROR "--draw did not write ${DRAW}")
endif()
file(SIZE "${DRAW}" size)
if(size LESS 10000)
  message(FATAL_ERROR "${DRAW} is only ${size} bytes")
endif()

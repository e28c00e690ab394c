# essential_enable_warnings(target): the project's warning flags (-Wall -Wextra, and -Werror
# when ESSENTIAL_WARNINGS_AS_ERRORS is on).
function(essential_enable_warnings target)
  if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE -Wall -Wextra)
    if(ESSENTIAL_WARNINGS_AS_ERRORS)
      target_compile_options(${target} PRIVATE -Werror)
    endif()
  endif()
endfunction()

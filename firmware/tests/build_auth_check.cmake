# Compiles tests/build_auth_cases.cpp for one CUBE_KEY_CASE and checks the
# outcome: with EXPECT empty it must compile; otherwise it must fail and the
# compiler's output must contain EXPECT.
#   cmake -DCXX=... -DSOURCE=... -DINCLUDE=... -DCASE=N [-DEXPECT=text] -P this
execute_process(
  COMMAND ${CXX} -std=c++17 -fsyntax-only -Wall -Wextra -Wconversion
          -Wsign-conversion -Wshadow -Werror -I${INCLUDE}
          -DCUBE_KEY_CASE=${CASE} ${SOURCE}
  RESULT_VARIABLE rc
  OUTPUT_VARIABLE out
  ERROR_VARIABLE out)
if("${EXPECT}" STREQUAL "")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "case ${CASE} should compile, but:\n${out}")
  endif()
  message(STATUS "case ${CASE} compiles")
else()
  if(rc EQUAL 0)
    message(FATAL_ERROR "case ${CASE} compiled; it must stop the build with: ${EXPECT}")
  endif()
  string(FIND "${out}" "${EXPECT}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "case ${CASE} failed without saying \"${EXPECT}\":\n${out}")
  endif()
  message(STATUS "case ${CASE} stops the build with: ${EXPECT}")
endif()

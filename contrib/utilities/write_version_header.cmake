# Writes include/gelmpm/core/version.h in the build directory with GelMPM's version and the git
# revision of the source tree at build time, so that every log header names the code that ran
# even when the tree changed after configuring. Rewrites the file only when its text changes
# (configure_file), so an unchanged revision rebuilds nothing.
#
#   cmake -DSOURCE_DIR=<top> -DBINARY_DIR=<build> -DGELMPM_VERSION=<x.y.z> -P write_version_header.cmake
execute_process(
  COMMAND git describe --always --dirty --tags
  WORKING_DIRECTORY ${SOURCE_DIR}
  OUTPUT_VARIABLE GELMPM_GIT_REVISION
  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT GELMPM_GIT_REVISION)
  set(GELMPM_GIT_REVISION "unknown")
endif()
configure_file(${SOURCE_DIR}/include/gelmpm/core/version.h.in
               ${BINARY_DIR}/include/gelmpm/core/version.h @ONLY)

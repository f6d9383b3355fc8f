# Writes include/gelmpm/core/version.h in the build directory with GelMPM's version and the git
# revision of the source tree at build time, so that every log header names the code that ran
# even when the tree changed after configuring. Rewrites the file only when its text changes, so
# an unchanged revision rebuilds nothing.
#
# The tests build their programs concurrently (ctest -j), and each build runs this script: the text
# is written to a file of this process's own and renamed over the header, which is atomic, so that
# no build reads or removes a half-written header (configure_file's temporary file is shared).
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

file(READ ${SOURCE_DIR}/include/gelmpm/core/version.h.in _template)
string(CONFIGURE "${_template}" _text @ONLY)

set(_header ${BINARY_DIR}/include/gelmpm/core/version.h)
set(_current "")
if(EXISTS ${_header})
  file(READ ${_header} _current)
endif()
if(NOT _current STREQUAL _text)
  string(RANDOM LENGTH 12 _suffix)
  set(_temporary ${_header}.${_suffix}.tmp)
  file(WRITE ${_temporary} "${_text}")
  file(RENAME ${_temporary} ${_header})
endif()

# gelmpm_pickup_cases(LIBRARIES <library>... [VTU_READER] [COSTS <case> <seconds>...])
#
# The tests of one module directory as cases of a shared test program. Every foo.cc beside
# foo.output in the calling directory is a test named <module>/foo.release, run and compared as
# deal.II's DEAL_II_PICKUP_TESTS runs and compares it (deal.II's run_test.sh: the program's stdout
# and stderr against foo.output by numdiff, absolute 1e-6, relative 1e-8, a non-zero exit status
# fails the test). What differs is the compilation: deal.II compiles every foo.cc into a program of
# its own, which for a translation unit that includes the simulator costs 15-20 s of compile and
# link, mostly spent reading the same deal.II headers again and instantiating the same templates;
# here the cases of several modules are compiled once, as one translation unit, into one program
# that runs the case named by its first argument (<module>/foo).
#
# The modules of GELMPM_UNIT_TEST_MODULES (tests/CMakeLists.txt) share the program unit_cases, the
# others run_cases (doc/architecture.md, "Tests": their compile times).
# gelmpm_pickup_cases() only records a module's cases and defines its tests;
# gelmpm_add_case_programs(), called once after every module, writes each program's translation
# unit and defines the program; gelmpm_add_test_programs_build() the test that builds them.
#
# The translation unit is written by gelmpm_write_multi_call() (cmake/gelmpm_multi_call.cmake):
# every header that one of the cases includes, then each foo.cc inside a namespace of its own, so
# that the helpers of two cases never meet, with SOURCE_DIR defined around it as the case's own
# source directory. A foo.cc therefore stays an ordinary program with its own main() that compiles
# on its own, and its failure is reported under its own name.
#
# The programs are built by the test test_programs.build (a ctest fixture that every case
# requires, so that two cases never build a program at the same time, and a compile error fails
# that test and leaves the cases not run). ctest -R <module>/foo runs the build first.
#
# VTU_READER: the cases read .vtu files through Python's VTK (tests/vtu_reader.h).
#
# COSTS <case> <seconds>...: the measured run time of the longer cases, as ctest's COST, so that
# with -j 2 they start first (ctest uses Testing/Temporary/CTestCostData.txt once a run has written
# it; a fresh build directory has none).
function(gelmpm_pickup_cases)
  cmake_parse_arguments(ARG "VTU_READER" "" "LIBRARIES;COSTS" ${ARGN})
  get_filename_component(_module ${CMAKE_CURRENT_SOURCE_DIR} NAME)
  string(TOLOWER ${CMAKE_BUILD_TYPE} _suffix)
  if(_module IN_LIST GELMPM_UNIT_TEST_MODULES)
    set(_program unit_cases)
  else()
    set(_program run_cases)
  endif()

  file(GLOB _outputs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.output)
  set(_cases)
  foreach(_output ${_outputs})
    get_filename_component(_name ${_output} NAME_WE)
    if(NOT EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${_name}.cc)
      message(FATAL_ERROR "${_output} has no ${_name}.cc beside it")
    endif()
    list(APPEND _cases ${_name})
  endforeach()
  if(NOT _cases)
    return()
  endif()

  foreach(_case ${_cases})
    set_property(GLOBAL APPEND PROPERTY GELMPM_CASES_${_program} "${_module}/${_case}")
  endforeach()
  set_property(GLOBAL APPEND PROPERTY GELMPM_CASES_${_program}_LIBRARIES ${ARG_LIBRARIES})
  if(ARG_VTU_READER)
    set_property(GLOBAL PROPERTY GELMPM_CASES_${_program}_VTU_READER TRUE)
  endif()

  set(_scripts ${DEAL_II_PATH}/${DEAL_II_SHARE_RELDIR}/scripts)
  foreach(_case ${_cases})
    set(_test ${_module}/${_case}.${_suffix})
    set(_directory ${CMAKE_CURRENT_BINARY_DIR}/${_case}.${_suffix})
    file(MAKE_DIRECTORY ${_directory})
    # deal.II's run and diff stages, called directly (tests/cmake/run_case.sh): deal.II's
    # run_test.cmake would start CMake and make for each case to find the program up to date.
    add_test(NAME ${_test}
             COMMAND bash ${GELMPM_TESTS_CMAKE_DIR}/run_case.sh ${_test}
                     $<TARGET_FILE:${_program}> ${_module}/${_case}
                     ${CMAKE_CURRENT_SOURCE_DIR}/${_case}.output ${NUMDIFF_EXECUTABLE} ${_scripts}
                     ${PERL_EXECUTABLE}
             WORKING_DIRECTORY ${_directory})
    set_tests_properties(${_test} PROPERTIES LABELS ${_module} TIMEOUT 600
                         FIXTURES_REQUIRED test_programs)
  endforeach()
  set(_costs ${ARG_COSTS})
  while(_costs)
    list(POP_FRONT _costs _case _seconds)
    if(NOT _case IN_LIST _cases)
      message(FATAL_ERROR "COSTS names ${_case}, which is not a case of tests/${_module}")
    endif()
    set_tests_properties(${_module}/${_case}.${_suffix} PROPERTIES COST ${_seconds})
  endwhile()
endfunction()


# gelmpm_add_case_programs(): the programs unit_cases and run_cases from the cases recorded by
# gelmpm_pickup_cases(), added to GELMPM_TEST_PROGRAMS.
function(gelmpm_add_case_programs)
  foreach(_program unit_cases run_cases)
    get_property(_entries GLOBAL PROPERTY GELMPM_CASES_${_program})
    if(NOT _entries)
      continue()
    endif()
    get_property(_libraries GLOBAL PROPERTY GELMPM_CASES_${_program}_LIBRARIES)
    get_property(_vtu_reader GLOBAL PROPERTY GELMPM_CASES_${_program}_VTU_READER)
    list(REMOVE_DUPLICATES _libraries)

    set(_sources)
    set(_source_dirs)
    foreach(_entry ${_entries})
      get_filename_component(_module ${_entry} DIRECTORY)
      list(APPEND _sources ${CMAKE_CURRENT_SOURCE_DIR}/${_entry}.cc)
      list(APPEND _source_dirs ${CMAKE_CURRENT_SOURCE_DIR}/${_module})
    endforeach()
    gelmpm_write_multi_call(${CMAKE_CURRENT_BINARY_DIR}/${_program}.cc BY argv1 KEYS ${_entries}
                            SOURCES ${_sources} SOURCE_DIRS ${_source_dirs})

    add_executable(${_program} EXCLUDE_FROM_ALL ${CMAKE_CURRENT_BINARY_DIR}/${_program}.cc)
    deal_ii_setup_target(${_program})
    gelmpm_use_pch(${_program})
    target_link_libraries(${_program} ${_libraries})
    # A case's main() is an ordinary function here: one that ends without a return would be
    # undefined behaviour, so that is an error.
    target_compile_options(${_program} PRIVATE -Werror=return-type)
    set_target_properties(${_program} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
    if(_vtu_reader)
      gelmpm_use_vtu_reader(${_program})
    endif()

    set_property(GLOBAL APPEND PROPERTY GELMPM_TEST_PROGRAMS ${_program})
  endforeach()
endfunction()


# gelmpm_add_test_programs_build(): the test test_programs.build, which builds every program of
# GELMPM_TEST_PROGRAMS (the case programs, input_error_runner) in one build on both cores: a
# fixture that their tests require. One build rather than one per program, since two builds at
# once in one build directory may both rebuild what they share (and Ninja keeps one log).
function(gelmpm_add_test_programs_build)
  get_property(_programs GLOBAL PROPERTY GELMPM_TEST_PROGRAMS)
  # The same programs as one target, which contrib/test.sh builds together with the libraries and
  # gelmpm, in one Ninja graph: their two large files then fill the cores where the libraries'
  # build leaves one idle, and this test finds them built.
  add_custom_target(test_programs)
  add_dependencies(test_programs ${_programs})
  add_test(NAME test_programs.build
           COMMAND ${CMAKE_COMMAND} --build ${CMAKE_BINARY_DIR} --parallel 2 --target test_programs)
  set_tests_properties(test_programs.build PROPERTIES LABELS cases FIXTURES_SETUP test_programs
                       FIXTURES_REQUIRED gelmpm_build PROCESSORS 2 TIMEOUT 1800 COST 1000)
endfunction()

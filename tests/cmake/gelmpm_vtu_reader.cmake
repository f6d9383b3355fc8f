# The tests that read written .vtu files back do so with VTK's XML reader, the one ParaView uses,
# through Python's vtkmodules (tests/vtu_dump.py, tests/vtu_reader.h). Debian's python3-vtk9 and
# ParaView's python3-paraview both install vtkmodules, and they conflict with each other; VTK's
# C++ development package (libvtk9-dev) depends on python3-vtk9, so linking VTK instead would
# keep ParaView's Python off the machine, and installing ParaView would remove it.
#
# gelmpm_find_vtu_reader() sets GELMPM_VTU_READER_FOUND in the caller's scope: true when the
# interpreter GELMPM_VTU_PYTHON (default /usr/bin/python3, which sees Debian's packages; else the
# Python 3 that CMake finds) imports vtkmodules.vtkIOXML.
# gelmpm_use_vtu_reader(<target>) gives the target the interpreter and the script's path.
set(GELMPM_VTU_DUMP ${CMAKE_CURRENT_LIST_DIR}/../vtu_dump.py)
get_filename_component(GELMPM_VTU_DUMP ${GELMPM_VTU_DUMP} ABSOLUTE)

function(gelmpm_find_vtu_reader)
  if(NOT GELMPM_VTU_PYTHON)
    if(EXISTS /usr/bin/python3)
      set(_python /usr/bin/python3)
    else()
      find_package(Python3 QUIET COMPONENTS Interpreter)
      set(_python ${Python3_EXECUTABLE})
    endif()
    set(GELMPM_VTU_PYTHON ${_python} CACHE FILEPATH
        "Python 3 that reads .vtu files for the tests (needs vtkmodules: python3-vtk9 or python3-paraview)")
  endif()
  set(_found FALSE)
  if(GELMPM_VTU_PYTHON)
    execute_process(COMMAND ${GELMPM_VTU_PYTHON} -c "import vtkmodules.vtkIOXML"
                    RESULT_VARIABLE _status OUTPUT_QUIET ERROR_QUIET)
    if(_status EQUAL 0)
      set(_found TRUE)
    endif()
  endif()
  set(GELMPM_VTU_READER_FOUND ${_found} PARENT_SCOPE)
endfunction()

function(gelmpm_use_vtu_reader _target)
  target_compile_definitions(${_target} PRIVATE GELMPM_VTU_PYTHON="${GELMPM_VTU_PYTHON}"
                                                GELMPM_VTU_DUMP="${GELMPM_VTU_DUMP}")
endfunction()

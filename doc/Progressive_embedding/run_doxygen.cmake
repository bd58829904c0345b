# Runs doxygen and fails on any warning.
#
#   cmake -DDOXYGEN_EXECUTABLE=<doxygen> -DDOXYFILE=<Doxyfile> -DWARN_LOG=<file> -P run_doxygen.cmake
#
# Used by the `doc` target and the `doc_build` ctest test (doc/Progressive_embedding/CMakeLists.txt).
# The Doxyfile sets WARN_AS_ERROR = FAIL_ON_WARNINGS and WARN_LOGFILE = WARN_LOG; this script
# also fails if the log is not empty or if doxygen prints a warning or an error on its own
# output (configuration warnings are not written to the log file).

foreach(var DOXYGEN_EXECUTABLE DOXYFILE WARN_LOG)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_doxygen.cmake: ${var} is not set")
  endif()
endforeach()

file(REMOVE "${WARN_LOG}")
get_filename_component(doxyfile_dir "${DOXYFILE}" DIRECTORY)

execute_process(COMMAND "${DOXYGEN_EXECUTABLE}" "${DOXYFILE}"
                WORKING_DIRECTORY "${doxyfile_dir}"
                RESULT_VARIABLE doxygen_result
                OUTPUT_VARIABLE doxygen_output
                ERROR_VARIABLE doxygen_output)

set(warnings "")
if(EXISTS "${WARN_LOG}")
  file(READ "${WARN_LOG}" warnings)
  string(STRIP "${warnings}" warnings)
endif()
string(STRIP "${doxygen_output}" doxygen_output)

set(failed FALSE)
if(NOT doxygen_result EQUAL 0)
  set(failed TRUE)
endif()
if(NOT warnings STREQUAL "")
  set(failed TRUE)
endif()
if(doxygen_output MATCHES "[Ww]arning|[Ee]rror")
  set(failed TRUE)
endif()

if(failed)
  if(NOT doxygen_output STREQUAL "")
    message("${doxygen_output}")
  endif()
  if(NOT warnings STREQUAL "")
    message("${warnings}")
  endif()
  message(FATAL_ERROR "Documentation build failed (doxygen exit status: ${doxygen_result}); "
                      "warnings above, also in ${WARN_LOG}")
endif()

get_filename_component(out_dir "${WARN_LOG}" DIRECTORY)
message(STATUS "Documentation built without warnings: ${out_dir}/html/index.html")

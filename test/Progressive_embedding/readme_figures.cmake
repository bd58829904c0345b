# ---- the README's and the manual's result figures against benchmark/results --------------------
#   readme_figures   label docs: scripts/readme_figures.py --check regenerates, in memory, every result
#                    table of README.md and of the user manual from benchmark/results/*.csv and checks
#                    every figure quoted in their prose; it fails on any disagreement (file, line, the
#                    quoted and the expected text, the CSV). `python3 scripts/readme_figures.py` rewrites
#                    them. Without a Python 3 interpreter the test is still registered, and fails.
if(NOT Python3_EXECUTABLE)
  find_package(Python3 COMPONENTS Interpreter QUIET)
endif()
if(Python3_EXECUTABLE)
  add_test(NAME readme_figures
           COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/readme_figures.py --check
           WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
else()
  message(WARNING "Python 3 not found: the test readme_figures is registered to fail")
  set(_pe_no_python ${CMAKE_CURRENT_BINARY_DIR}/readme_figures_no_python.cmake)
  file(WRITE ${_pe_no_python} "message(FATAL_ERROR \"readme_figures: no Python 3 interpreter was found at configure time\")\n")
  add_test(NAME readme_figures COMMAND ${CMAKE_COMMAND} -P ${_pe_no_python})
endif()
set_tests_properties(readme_figures PROPERTIES LABELS "docs" TIMEOUT 120)

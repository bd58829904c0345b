# The Python module's tests (pytest), when the module is built (-DPROGRESSIVE_EMBEDDING_PYTHON=ON; the
# top-level CMakeLists.txt adds python/ before this directory, so the target exists here).
# Nothing is written into the source tree: no pytest cache, no bytecode.
if(TARGET progressive_embedding)
  add_test(NAME python_module
           COMMAND ${Python3_EXECUTABLE} -m pytest -q -p no:cacheprovider ${PROJECT_SOURCE_DIR}/python/tests
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(python_module PROPERTIES
    ENVIRONMENT "PYTHONPATH=$<TARGET_FILE_DIR:progressive_embedding>;PE_DATA_DIR=${PE_DATA_DIR};PYTHONDONTWRITEBYTECODE=1"
    LABELS "python"
    TIMEOUT 600)
endif()

# Examples on OpenMesh meshes (Debian: libopenmesh-dev), built as programs of their own when OpenMesh
# is found and PE_EXAMPLES_TOGETHER is off (else they join pe_examples); CMakeLists.txt registers
# their tests.
if(TARGET OpenMeshCore)
  add_executable(openmesh_example openmesh_example.cpp)
  target_link_libraries(openmesh_example PRIVATE CGAL::Progressive_embedding OpenMeshCore)
  target_compile_definitions(openmesh_example PRIVATE NOMINMAX _USE_MATH_DEFINES)
  pe_example_definitions(openmesh_example)
  list(APPEND PE_EXAMPLES openmesh_example)
else()
  message(STATUS "OpenMesh not found: openmesh_example is not built (Debian: libopenmesh-dev)")
endif()

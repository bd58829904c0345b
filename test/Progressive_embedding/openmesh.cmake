# ---- OpenMesh as a FaceGraph ------------------------------------------------------------------
#   openmesh_*   label openmesh: test_openmesh, the main functions on OpenMesh::TriMesh_ArrayKernelT
#                (Tutte, certificate, progressive embedding, optimization, constrained maps, CGAL's
#                parameterize() with this package's parameterizer); built when OpenMesh is found
find_package(OpenMesh QUIET)
if(TARGET OpenMeshCore)
  add_executable(test_openmesh test_openmesh.cpp)
  target_link_libraries(test_openmesh PRIVATE CGAL::Progressive_embedding OpenMeshCore)
  target_compile_options(test_openmesh PRIVATE -O2)
  target_compile_definitions(test_openmesh PRIVATE NOMINMAX _USE_MATH_DEFINES)
  foreach(_part tutte repair optimize constrained parameterizer)
    add_test(NAME openmesh_${_part} COMMAND test_openmesh ${PE_DATA_DIR} ${_part})
    set_tests_properties(openmesh_${_part} PROPERTIES TIMEOUT 300 LABELS "openmesh")
  endforeach()
else()
  message(STATUS "OpenMesh not found: the OpenMesh tests are skipped (Debian: libopenmesh-dev)")
endif()

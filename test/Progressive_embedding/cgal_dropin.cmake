# ---- CGAL drop-in: Certified_parameterizer_3 around CGAL's fixed-border parameterizers --------
#   cgal_dropin_*   label cgal_dropin: the wrapped parameterizers certified / repaired, valid maps kept
#                   bit for bit, charts of one mesh, Seam_mesh, Polyhedron_3, components with holes
add_executable(test_cgal_dropin test_cgal_dropin.cpp)
target_link_libraries(test_cgal_dropin PRIVATE CGAL::Progressive_embedding)
target_compile_options(test_cgal_dropin PRIVATE -O2)
foreach(_part wrapped polyhedron iterative valid charts holes seam)
  add_test(NAME cgal_dropin_${_part} COMMAND test_cgal_dropin ${PE_DATA_DIR} ${_part})
  set_tests_properties(cgal_dropin_${_part} PROPERTIES TIMEOUT 600 LABELS "cgal_dropin")
endforeach()

# CGAL's own parameterization examples (from libcgal-dev's examples.tar.gz), swapped by a script at
# test time, built as one program and run on their default data: the maps must be certified.
set(PE_CGAL_EXAMPLES_TAR /usr/share/doc/libcgal-dev/examples.tar.gz)
if(EXISTS ${PE_CGAL_EXAMPLES_TAR} AND EXISTS "${PE_DATA_DIR}/meshes")
  add_test(NAME cgal_dropin_cgal_examples
           COMMAND ${CMAKE_COMMAND} -DEXAMPLES_TAR=${PE_CGAL_EXAMPLES_TAR}
                   -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/cgal_examples
                   -DPE_INCLUDE=${PROJECT_SOURCE_DIR}/include -DPE_DATA_DIR=${PE_DATA_DIR}
                   -P ${PROJECT_SOURCE_DIR}/scripts/cgal_examples/run_cgal_examples.cmake)
  set_tests_properties(cgal_dropin_cgal_examples PROPERTIES TIMEOUT 1500 LABELS "cgal_dropin;cgal_examples")
endif()

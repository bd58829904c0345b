# Runs CGAL's own Surface_mesh_parameterization examples with Certified_parameterizer_3 swapped in.
#
#   cmake -DEXAMPLES_TAR=/usr/share/doc/libcgal-dev/examples.tar.gz -DWORK_DIR=... -DPE_INCLUDE=...
#         -DPE_DATA_DIR=... -DCXX_BUILD_TYPE=Release -P run_cgal_examples.cmake
#
# The sources are extracted from CGAL's tarball at test time and edited here (never copied into the
# package): each fixed-border parameterizer is wrapped, and a line printing the exact certificate
# (check_embedding) or the status follows the call. All the examples become one translation unit (each in
# its own namespace, main renamed) to build one executable only. Skipped: lscm.cpp (free border, LSCM
# pins two vertices: not a fixed-border method) and orbifold.cpp (orbifold Tutte embeddings of closed
# meshes with cones: not a fixed convex border).

foreach(v EXAMPLES_TAR WORK_DIR PE_INCLUDE PE_DATA_DIR)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "${v} is not set")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/src)
execute_process(COMMAND ${CMAKE_COMMAND} -E tar xzf ${EXAMPLES_TAR} examples/Surface_mesh_parameterization
                WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cannot extract the examples from ${EXAMPLES_TAR}")
endif()
set(SRC ${WORK_DIR}/examples/Surface_mesh_parameterization)
set(PE "CGAL::Progressive_embedding::Certified_parameterizer_3")
set(CERT "CGAL::Progressive_embedding::check_embedding")

# name;file;text to replace;replacement;certificate line (after the replaced statement)
set(names simple discrete_authalic square_border iterative seam_polyhedron)
set(simple_file simple_parameterization.cpp)
set(simple_old "SMP::parameterize(sm, bhd, uv_map);")
set(simple_new "SMP::parameterize(sm, ${PE}<SurfaceMesh, SMP::Mean_value_coordinates_parameterizer_3<SurfaceMesh> >(), bhd, uv_map);\n  std::cout << \"PE_CERTIFICATE simple_parameterization \" << ${CERT}(sm, uv_map).is_valid() << std::endl;")
set(discrete_authalic_file discrete_authalic.cpp)
set(discrete_authalic_old "SMP::Error_code err = SMP::parameterize(sm, Parameterizer(), bhd, uv_map);")
set(discrete_authalic_new "SMP::Error_code err = SMP::parameterize(sm, ${PE}<SurfaceMesh, Parameterizer>(), bhd, uv_map);\n  std::cout << \"PE_CERTIFICATE discrete_authalic \" << ${CERT}(sm, uv_map).is_valid() << std::endl;")
set(square_border_file square_border_parameterizer.cpp)
set(square_border_old "SMP::Error_code err = SMP::parameterize(sm, Parameterizer(border_param), bhd, uv_map);")
set(square_border_new "SMP::Error_code err = SMP::parameterize(sm, ${PE}<PolyMesh, Parameterizer>(Parameterizer(border_param)), bhd, uv_map);\n  std::cout << \"PE_CERTIFICATE square_border_parameterizer \" << ${CERT}(sm, uv_map).is_valid() << std::endl;")
set(iterative_file iterative_authalic_parameterizer.cpp)
set(iterative_old "SMP::Error_code err = parameterizer.parameterize(sm, bhd, uv_map, iterations);")
set(iterative_new "${PE}<Surface_mesh, Parameterizer> certified;\n  (void)parameterizer;\n  SMP::Error_code err = certified.parameterize(sm, bhd, uv_map, iterations);\n  std::cout << \"PE_CERTIFICATE iterative_authalic_parameterizer \" << ${CERT}(sm, uv_map).is_valid() << std::endl;")
set(seam_polyhedron_file seam_Polyhedron_3.cpp)
set(seam_polyhedron_old "SMP::parameterize(mesh, bhd, uv_pm);")
set(seam_polyhedron_new "const SMP::Error_code pe_status = SMP::parameterize(mesh, ${PE}<Mesh, SMP::Mean_value_coordinates_parameterizer_3<Mesh> >(), bhd, uv_pm);\n  std::cout << \"PE_STATUS seam_Polyhedron_3 \" << SMP::get_error_message(pe_status) << std::endl;\n  std::cout << \"PE_CERTIFICATE seam_Polyhedron_3 \" << ${CERT}(mesh, uv_pm, CGAL::Progressive_embedding::parameters::multiply_connected(true)).is_valid() << std::endl;")

set(unity "#include <CGAL/Progressive_embedding/Certified_parameterizer_3.h>\n#include <CGAL/Progressive_embedding/check_embedding.h>\n#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>\n")
set(bodies "")
set(calls "")
foreach(n ${names})
  file(READ ${SRC}/${${n}_file} text)
  string(FIND "${text}" "${${n}_old}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${${n}_file}: the parameterizer call to swap was not found (CGAL's example changed)")
  endif()
  string(REPLACE "${${n}_old}" "${${n}_new}" text "${text}")
  # includes stay global; the rest goes into a namespace, main renamed
  string(REGEX MATCHALL "#include[^\n]*\n" includes "${text}")
  string(REGEX REPLACE "#include[^\n]*\n" "" body "${text}")
  string(REPLACE "int main(" "int main_${n}(" body "${body}")
  foreach(i ${includes})
    string(APPEND unity "${i}")
  endforeach()
  string(APPEND bodies "namespace ex_${n} {\n${body}\n}\n")
  string(APPEND calls "  { char* args[] = {const_cast<char*>(\"${n}\"), nullptr}; int r = ex_${n}::main_${n}(1, args); std::cout << \"PE_EXIT ${n} \" << r << std::endl; }\n")
endforeach()
file(WRITE ${WORK_DIR}/src/cgal_examples_swapped.cpp "${unity}\n${bodies}\nint main()\n{\n${calls}  return 0;\n}\n")
file(WRITE ${WORK_DIR}/src/CMakeLists.txt "cmake_minimum_required(VERSION 3.14)\nproject(cgal_examples_swapped CXX)\nfind_package(CGAL REQUIRED)\nfind_package(Eigen3 3.1 REQUIRED)\ninclude(CGAL_Eigen3_support)\nadd_executable(cgal_examples_swapped cgal_examples_swapped.cpp)\ntarget_include_directories(cgal_examples_swapped BEFORE PRIVATE ${PE_INCLUDE})\ntarget_link_libraries(cgal_examples_swapped PRIVATE CGAL::CGAL CGAL::Eigen3_support)\ntarget_compile_features(cgal_examples_swapped PRIVATE cxx_std_17)\ntarget_compile_definitions(cgal_examples_swapped PRIVATE \"CGAL_DATA_DIR=\\\"${PE_DATA_DIR}\\\"\")\n")

# -O1: the examples run for about a second either way, and compile in two thirds of Release's -O3 time
execute_process(COMMAND ${CMAKE_COMMAND} -S ${WORK_DIR}/src -B ${WORK_DIR}/build -DCMAKE_BUILD_TYPE=Release
                        "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring the swapped examples failed:\n${out}")
endif()
execute_process(COMMAND nice -n 5 ${CMAKE_COMMAND} --build ${WORK_DIR}/build -j1
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building the swapped examples failed:\n${out}")
endif()
# run in the examples' folder: they read their selection files (seams, square corners) from data/
execute_process(COMMAND ${WORK_DIR}/build/cgal_examples_swapped WORKING_DIRECTORY ${SRC}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the swapped examples crashed or failed (${rc}):\n${err}")
endif()
# every fixed-border example: certified and exit 0
foreach(e simple_parameterization discrete_authalic square_border_parameterizer iterative_authalic_parameterizer)
  if(NOT out MATCHES "PE_CERTIFICATE ${e} 1")
    message(FATAL_ERROR "${e}: the map is not certified")
  endif()
endforeach()
foreach(n simple discrete_authalic square_border iterative)
  if(NOT out MATCHES "PE_EXIT ${n} 0")
    message(FATAL_ERROR "${n}: the example did not exit with success")
  endif()
endforeach()
# lion.off cut along lion.selection.txt keeps holes (several border cycles): a multiply connected map, certified
if(NOT out MATCHES "PE_STATUS seam_Polyhedron_3 Success" OR NOT out MATCHES "PE_CERTIFICATE seam_Polyhedron_3 1")
  message(FATAL_ERROR "seam_Polyhedron_3: expected a certified map of the chart with holes")
endif()

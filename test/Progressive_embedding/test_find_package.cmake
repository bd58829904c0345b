# The install / find_package test: installs the build tree into a fresh prefix, then
# configures, builds and runs a separate project (find_package_project/) that finds the
# package with find_package(Progressive_embedding REQUIRED) and links CGAL::Progressive_embedding.
#   -DBUILD_DIR=<main build> -DWORK_DIR=<scratch> -DPROJECT_SOURCE=<find_package_project> [-DCMAKE_BUILD_TYPE=...]

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(prefix "${WORK_DIR}/install")

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("== ${what}: ${ARGN}\n${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc})")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

run("install" ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}")
file(GLOB_RECURSE config "${prefix}/*/Progressive_embeddingConfig.cmake")
if(NOT config OR NOT EXISTS "${prefix}/include/CGAL/Progressive_embedding/tutte_embedding.h")
  message(FATAL_ERROR "the install tree lacks the package config or the headers")
endif()
if(NOT CMAKE_BUILD_TYPE)
  set(CMAKE_BUILD_TYPE Release)
endif()
# -O1: what is tested is the package's install and config, not the consumer's speed (a third less
# compile time than Release's -O3)
run("configure" ${CMAKE_COMMAND} -S "${PROJECT_SOURCE}" -B "${WORK_DIR}/build"
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE} "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG")
run("build" ${CMAKE_COMMAND} --build "${WORK_DIR}/build")
run("run" "${WORK_DIR}/build/consumer")
if(NOT last_output MATCHES "certified valid")
  message(FATAL_ERROR "the consumer did not print a certified map")
endif()
message("find_package test: the installed package was found, built against and run")

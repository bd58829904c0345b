# The package's headers in layers: a public algorithm header may include anything; a header of
# internal/ (the building blocks and the bodies of the algorithms) and a leaf (the public types:
# error codes, named parameters, traits, reports and statistics, the multigrid preconditioner) include only
# leaves and internal/.
# So a pipeline inside internal/ calls the bodies (internal::check_embedding_impl(), ...) and never climbs
# back to a public algorithm header. Fails on every include that goes up, naming it.
#   cmake -DHEADER_ROOT=.../include -P header_layers.cmake
set(pe ${HEADER_ROOT}/CGAL/Progressive_embedding)
set(leaves Error_code.h parameters.h Progressive_embedding_traits_2.h Distortion_report.h Embedding_report.h
           Immersion_report.h Polygon_triangulation_report.h Optimization_statistics.h
           Progressive_embedding_statistics.h Constrained_embedding_statistics.h
           Smoothed_aggregation_preconditioner.h)
file(GLOB_RECURSE internal_headers ${pe}/internal/*.h)
set(leaf_headers "")
foreach(l ${leaves})
  if(NOT EXISTS ${pe}/${l})
    message(FATAL_ERROR "the leaf header ${l} does not exist: update header_layers.cmake")
  endif()
  list(APPEND leaf_headers ${pe}/${l})
endforeach()
set(errors "")
set(checked 0)
foreach(h ${internal_headers} ${leaf_headers})
  file(STRINGS ${h} includes REGEX "^#include <CGAL/Progressive_embedding/")
  file(RELATIVE_PATH rel ${pe} ${h})
  math(EXPR checked "${checked} + 1")
  foreach(line ${includes})
    string(REGEX REPLACE "^#include <CGAL/Progressive_embedding/([^>]+)>.*" "\\1" target "${line}")
    list(FIND leaves ${target} is_leaf)
    if(rel MATCHES "^internal/")
      if(NOT target MATCHES "^internal/" AND is_leaf EQUAL -1)
        string(APPEND errors "  ${rel} includes the public algorithm header ${target}\n")
      endif()
    elseif(is_leaf EQUAL -1 AND NOT target MATCHES "^internal/")
      string(APPEND errors "  the leaf ${rel} includes ${target}, which is not a leaf\n")
    endif()
  endforeach()
endforeach()
if(errors)
  message(FATAL_ERROR "includes that go up a layer:\n${errors}")
endif()
message(STATUS "${checked} headers (internal and leaves): no include goes up a layer")

# Path tracing (phase 2 of constrained maps): test_trace_paths.cpp
pe_constrained_test(trace_paths_sizes "constrained;paths" 600)
pe_constrained_test(trace_paths_polyhedron "constrained;paths")
pe_constrained_test(trace_paths_adjacent_nodes "constrained;paths")
pe_constrained_test(trace_paths_degree_three "constrained;paths")
pe_constrained_test(trace_paths_mirrored "constrained;paths")
pe_constrained_test(trace_paths_errors "constrained;paths")
pe_constrained_test(trace_paths_exact "constrained;paths")
pe_constrained_test(trace_paths_holes "constrained;paths")

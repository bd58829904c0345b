# constrained_embedding() on layouts that force refinement or winding paths, and on meshes with holes
pe_constrained_test(constrained_cases_adjacent "constrained;matchmaker")
pe_constrained_test(constrained_cases_adjacent_gmpq "constrained;matchmaker")
pe_constrained_test(constrained_cases_mirrored "constrained;matchmaker")
pe_constrained_test(constrained_cases_degree_three "constrained;matchmaker")
pe_constrained_test(constrained_cases_annulus "constrained;matchmaker;holes")
pe_constrained_test(constrained_cases_sphere_holes "constrained;matchmaker;holes")
pe_constrained_test(constrained_cases_recycled_vertex "constrained;matchmaker")
pe_constrained_test(constrained_cases_rounded_corner "constrained;matchmaker")

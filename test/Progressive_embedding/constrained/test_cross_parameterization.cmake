# cross_parameterization(): a certified map between two disks with matched landmarks
pe_constrained_test(cross_identical "constrained;cross")
pe_constrained_test(cross_border_landmarks "constrained;cross")
pe_constrained_test(cross_shifted "constrained;cross")
pe_constrained_test(cross_remeshed "constrained;cross")
pe_constrained_test(cross_polyhedron "constrained;cross")
pe_constrained_test(cross_errors "constrained;cross")
pe_constrained_test(cross_compatible "constrained;cross")
pe_constrained_test(cross_exact_location "constrained;cross")

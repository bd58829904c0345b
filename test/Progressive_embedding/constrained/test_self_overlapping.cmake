# Triangulation of simple and weakly self-overlapping polygons (Shor-Van Wyk): test_self_overlapping.cpp
pe_constrained_test(self_overlapping_simple "constrained;polygon")
pe_constrained_test(self_overlapping_polyomino "constrained;polygon" 600)
pe_constrained_test(self_overlapping_spiral "constrained;polygon" 600)
pe_constrained_test(self_overlapping_collinear "constrained;polygon")
pe_constrained_test(self_overlapping_errors "constrained;polygon")
pe_constrained_test(self_overlapping_exact "constrained;polygon")
pe_constrained_test(self_overlapping_brute_force "constrained;polygon" 600)
pe_constrained_test(self_overlapping_certificate "constrained;polygon")

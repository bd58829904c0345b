# The target domain cut into convex polygons, and path vertices placed on its edges.
pe_constrained_test(domain_partition "constrained;domain" 600)
pe_constrained_test(domain_partition_degenerate "constrained;domain")
pe_constrained_test(domain_partition_errors "constrained;domain")
pe_constrained_test(domain_partition_exact "constrained;domain")
pe_constrained_test(domain_partition_non_convex "constrained;domain")
pe_constrained_test(domain_partition_non_convex_errors "constrained;domain")
pe_constrained_test(domain_partition_immersed "constrained;domain")
pe_constrained_test(domain_partition_non_convex_tracing "constrained;domain")

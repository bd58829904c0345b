# constrained_embedding()'s coarsening: added vertices removed where the certified map can do without
pe_constrained_test(coarsen_star "constrained;matchmaker;coarsen")
pe_constrained_test(coarsen_pipeline "constrained;matchmaker;coarsen")

# constrained_embedding() onto non-convex fixed borders: simple polygons (embeddings) and weakly self-overlapping ones (immersions)
pe_constrained_test(constrained_embedding_non_convex "constrained;matchmaker;immersion" 600)
pe_constrained_test(constrained_embedding_immersion "constrained;immersion" 600)
pe_constrained_test(constrained_embedding_hilbert "constrained;matchmaker;non_convex" 600)

# embed_patch(): a face range of a mesh (a disk) mapped into the weakly convex polygon of its border
pe_constrained_test(patch_embedding_real "constrained;patch")
pe_constrained_test(patch_embedding_polyhedron "constrained;patch")
pe_constrained_test(patch_embedding_repair "constrained;patch")
pe_constrained_test(patch_embedding_chords "constrained;patch")
pe_constrained_test(patch_embedding_refused "constrained;patch")
pe_constrained_test(patch_embedding_gmpq "constrained;patch")
pe_constrained_test(patch_embedding_disk_functions "constrained;patch")
pe_constrained_test(patch_embedding_sweep "constrained;patch")

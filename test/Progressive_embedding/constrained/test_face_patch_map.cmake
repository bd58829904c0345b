# constrained_embedding()'s face_patch_map: the patch of every face of the refined mesh (the picture of pe constrain --svg)
pe_constrained_test(face_patch_map_surface_mesh "constrained;matchmaker;face_patch_map")
pe_constrained_test(face_patch_map_polyhedron "constrained;matchmaker;face_patch_map")
pe_constrained_test(face_patch_map_cases "constrained;matchmaker;face_patch_map")

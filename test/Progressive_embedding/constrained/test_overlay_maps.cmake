# the overlay of two planar maps (compatible meshes of cross_parameterization()) against CGAL's arrangement overlay
pe_constrained_test(cross_overlay "constrained;cross")

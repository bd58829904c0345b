# check_immersion(): the exact certificate of locally injective maps (test_check_immersion.cpp)
pe_constrained_test(check_immersion "constrained;immersion")
pe_constrained_test(check_immersion_errors "constrained;immersion")
pe_constrained_test(optimize_immersion "constrained;immersion;distortion")

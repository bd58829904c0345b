# ---- batch runs of the `pe` tool: pe batch, pe batch-merge ------------------------------------
#   batch_*   label batch: batch_runs.py GROUP generates its inputs at test time (pe generate, pe
#             thingi on ${PE_DATA_DIR}/meshes, a broken file, a closed mesh) and checks the records,
#             the statuses (timeout, memory, input_error), shards against an unsharded run (their
#             merges the same bytes), --resume, the merge rules and the exit status of bad arguments
if(TARGET pe AND Python3_EXECUTABLE)
  foreach(_group shards limits pipelines merge arguments)
    add_test(NAME batch_${_group}
             COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/batch_runs.py $<TARGET_FILE:pe> ${PE_DATA_DIR}
                     ${CMAKE_CURRENT_BINARY_DIR}/batch_runs ${_group})
    # alone: the groups share ${CMAKE_CURRENT_BINARY_DIR}/batch_runs, and `limits` kills children at their time limit
    set_tests_properties(batch_${_group} PROPERTIES TIMEOUT 120 LABELS "batch" RUN_SERIAL TRUE)
    # instrumented builds (PE_TEST_TIMEOUT_FACTOR > 1) run slower: `limits` scales its --time-limit by the factor
    if(PE_TEST_TIMEOUT_FACTOR)
      set_tests_properties(batch_${_group} PROPERTIES ENVIRONMENT "PE_TEST_TIMEOUT_FACTOR=${PE_TEST_TIMEOUT_FACTOR}")
    endif()
  endforeach()
endif()

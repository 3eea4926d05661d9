# Issue 30: file safety and the last runaway classes, through the CLI.
# Included from tests/CMakeLists.txt (after hostile_check is defined).
set(HARDENING_DIR ${CMAKE_CURRENT_LIST_DIR})
add_test(NAME hardening.output_files COMMAND bash ${HARDENING_DIR}/output_files_test.sh $<TARGET_FILE:strun> ${HARDENING_DIR})
add_test(NAME hardening.retain_values COMMAND bash ${HARDENING_DIR}/retain_values_test.sh $<TARGET_FILE:strun> ${HARDENING_DIR})
add_test(NAME hardening.inputs COMMAND bash ${HARDENING_DIR}/inputs_test.sh $<TARGET_FILE:strun> ${HARDENING_DIR})
set_tests_properties(hardening.output_files hardening.retain_values hardening.inputs PROPERTIES TIMEOUT 180)
# Generated inputs (tests/hostile/hostile_check.cpp): linear growth of the
# name-matching checks, bounded memory for huge initialisers, --vcd and --retain.
foreach(case enum_100000_values struct_100000_members named_arguments_100000 program_instances_100000
             array_initialiser_50_million vcd_10_million_elements retain_64_mib_array)
  add_test(NAME hostile.${case} COMMAND hostile_check $<TARGET_FILE:strun> ${case})
  set_tests_properties(hostile.${case} PROPERTIES TIMEOUT 300)
endforeach()

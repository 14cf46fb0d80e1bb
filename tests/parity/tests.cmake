# The engines at parity on the core's rules (issue 17 item 2), included by tests/CMakeLists.txt
# when both CAPBRIDGE_LAMMPS_ENV and CAPBRIDGE_LIGGGHTS_ENV are given: parity.py gives both
# engines one input (two radii, a fixed volume or Protocol 2 liquid, law richefeu) and checks
# the reach, the time-step bound and Protocol 2's k-way share against the core's numbers
# (the CLI and capbridge.h's formulas).
find_package(Python3 REQUIRED COMPONENTS Interpreter)
add_test(NAME parity
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/parity.py
                 $<TARGET_FILE:capbridge_cli> ${CAPBRIDGE_LAMMPS_ENV}
                 $<TARGET_FILE:capbridgeplugin> ${CAPBRIDGE_LIGGGHTS_ENV}
                 --workdir ${CMAKE_CURRENT_BINARY_DIR}/parity)
set_tests_properties(parity PROPERTIES LABELS "lammps;liggghts" TIMEOUT 600)
# the same bridges removed by both engines (keyword remove, issue 18 item 7; and between runs,
# LAMMPS's fix_modify remove and LIGGGHTS's fix capillaryRemove): the bridged and the removed
# (id, id) pairs of one input, and the draw computed independently in removal.py
add_test(NAME parity_removal
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/removal.py
                 ${CAPBRIDGE_LAMMPS_ENV} $<TARGET_FILE:capbridgeplugin> ${CAPBRIDGE_LIGGGHTS_ENV}
                 --workdir ${CMAKE_CURRENT_BINARY_DIR}/parity_removal)
set_tests_properties(parity_removal PROPERTIES LABELS "lammps;liggghts" TIMEOUT 600)

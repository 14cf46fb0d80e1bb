# The engines at parity on the core's rules (issue 17 item 2), included by tests/CMakeLists.txt
# when CAPBRIDGE_LAMMPS_ENV is given: parity.py gives the engines one input (two radii, a
# fixed volume or Protocol 2 liquid, law richefeu) and checks the reach, the time-step bound
# and Protocol 2's k-way share against the core's numbers (CLI and capbridge.h's formulas).
# The LAMMPS half so far; the LIGGGHTS half joins it (label lammps;liggghts) once written.
find_package(Python3 REQUIRED COMPONENTS Interpreter)
add_test(NAME parity_lammps
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/parity.py
                 $<TARGET_FILE:capbridge_cli> ${CAPBRIDGE_LAMMPS_ENV}
                 $<TARGET_FILE:capbridgeplugin>
                 --workdir ${CMAKE_CURRENT_BINARY_DIR}/parity)
set_tests_properties(parity_lammps PROPERTIES LABELS "lammps" TIMEOUT 300)

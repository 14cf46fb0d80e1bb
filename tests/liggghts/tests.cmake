# The LIGGGHTS binding's tests (lammps_pair/liggghts/), included by tests/CMakeLists.txt
# when CAPBRIDGE_LIGGGHTS_ENV names the liggghts.env written by scripts/build_liggghts.sh
# (which builds LIGGGHTS 3.8.0 with `cohesion capillary` and the C core). Label: liggghts.
# Python 3 (standard library) drives LIGGGHTS and compares with the capbridge CLI.
if(NOT EXISTS "${CAPBRIDGE_LIGGGHTS_ENV}")
  message(FATAL_ERROR "CAPBRIDGE_LIGGGHTS_ENV=${CAPBRIDGE_LIGGGHTS_ENV} does not exist: "
                      "run scripts/build_liggghts.sh (it prints the path)")
endif()
find_package(Python3 REQUIRED COMPONENTS Interpreter)
set(_liggghts_dir ${CMAKE_CURRENT_LIST_DIR})
set(_liggghts_work ${CMAKE_CURRENT_BINARY_DIR}/liggghts)

# the 13 Gladkyy cases (+ 2 with contact), every step against `capbridge pulloff`
add_test(NAME liggghts_pulloff
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/pulloff.py
                 $<TARGET_FILE:capbridge_cli> ${CAPBRIDGE_LIGGGHTS_ENV}
                 --workdir ${_liggghts_work}/pulloff)
# the same with one sphere per rank (the bridge held by both ranks)
add_test(NAME liggghts_pulloff_mpi
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/pulloff.py
                 $<TARGET_FILE:capbridge_cli> ${CAPBRIDGE_LIGGGHTS_ENV} --ranks 2
                 --cases W21,W22,R1 --workdir ${_liggghts_work}/pulloff_mpi)
# Protocol 2: liquid conserved on 1 and 2 ranks, the same bridges on both
add_test(NAME liggghts_wet
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/wet.py ${CAPBRIDGE_LIGGGHTS_ENV}
                 --workdir ${_liggghts_work}/wet)
# bad input: an error naming the problem (a wall without a law too)
add_test(NAME liggghts_bad_input
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/bad_input.py ${CAPBRIDGE_LIGGGHTS_ENV}
                 --workdir ${_liggghts_work}/bad_input)
# the Coulomb limit on the contact force (Richefeu eq. 12); capillary_friction refused
add_test(NAME liggghts_friction
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/friction.py ${CAPBRIDGE_LIGGGHTS_ENV}
                 --workdir ${_liggghts_work}/friction)
# a pair held by its bridge alone slides at mu F_cap (eq. 12 with eq. 1's f_n), F_cap from the CLI
add_test(NAME liggghts_held
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/held.py
                 $<TARGET_FILE:capbridge_cli> ${CAPBRIDGE_LIGGGHTS_ENV}
                 --workdir ${_liggghts_work}/held)
# a bridge held beyond the reach (Protocol 2, more liquid than the reach was built for) is
# ruptured there, its liquid released, one warning; 1 and 2 ranks
add_test(NAME liggghts_beyond_reach
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/beyond_reach.py
                 $<TARGET_FILE:capbridge_cli> ${CAPBRIDGE_LIGGGHTS_ENV}
                 --workdir ${_liggghts_work}/beyond_reach)
# easo/capillary/viscous and ours against the exact curves; easo = our soulie at theta 0
# (the full table of the docs: easo_comparison.py with all laws, see its --output)
add_test(NAME liggghts_easo_comparison
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/easo_comparison.py
                 ${CAPBRIDGE_LIGGGHTS_ENV} --laws soulie,willett --check
                 --workdir ${_liggghts_work}/easo)
# a bridge's force after the surface tension changes between two runs
add_test(NAME liggghts_between_runs
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/between_runs.py ${CAPBRIDGE_LIGGGHTS_ENV}
                 --workdir ${_liggghts_work}/between_runs)
# a stretched bridge and its liquid through a restart file (Protocol 2, no free liquid left),
# on 1 rank and with one sphere per rank
add_test(NAME liggghts_restart
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/restart.py ${CAPBRIDGE_LIGGGHTS_ENV}
                 --workdir ${_liggghts_work}/restart)
add_test(NAME liggghts_restart_mpi
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/restart.py ${CAPBRIDGE_LIGGGHTS_ENV}
                 --ranks 2 --workdir ${_liggghts_work}/restart_mpi)
# Protocol 2's liquid lost with a second pair_style or with atoms that leave the box, warned
# with its amount (1 and 2 ranks)
add_test(NAME liggghts_liquid_account
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/liquid_account.py
                 ${CAPBRIDGE_LIGGGHTS_ENV} --workdir ${_liggghts_work}/liquid_account)
# the time-step check against the capillary stiffness (Richefeu's, analytic)
add_test(NAME liggghts_timestep
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/timestep.py ${CAPBRIDGE_LIGGGHTS_ENV}
                 --workdir ${_liggghts_work}/timestep)
# Protocols 1, 2, 3: liquid conserved at every step on 1, 2 and 3 ranks, bridges forming and
# rupturing, the same bridges on every rank count
add_test(NAME liggghts_protocols
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/protocols.py ${CAPBRIDGE_LIGGGHTS_ENV}
                 --workdir ${_liggghts_work}/protocols)
# Protocol 1's distribution against the core's cb_protocol1_distribute over the dumped
# spheres, computed without LIGGGHTS (protocol1_reference.c); 1 and 3 ranks
add_executable(liggghts_protocol1_reference ${_liggghts_dir}/protocol1_reference.c)
target_link_libraries(liggghts_protocol1_reference PRIVATE capbridge)
target_compile_options(liggghts_protocol1_reference PRIVATE ${CAPBRIDGE_WARNINGS})
add_test(NAME liggghts_protocol1_reference
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/protocol1_reference.py
                 $<TARGET_FILE:liggghts_protocol1_reference> ${CAPBRIDGE_LIGGGHTS_ENV}
                 --workdir ${_liggghts_work}/protocol1_reference)
# Protocols 1, 2, 3 across write_restart / read_restart: liquid conserved at every step of
# both runs; Protocols 2 and 3 resume with the same bridges (1 and 2 ranks)
add_test(NAME liggghts_protocols_restart
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/protocols_restart.py
                 ${CAPBRIDGE_LIGGGHTS_ENV} --workdir ${_liggghts_work}/protocols_restart)
# Protocol 3's receiver of a broken bridge's liquid (the lowest contact on the lower
# hemisphere, of equal heights the smaller partner ID; none: free liquid) against the core's
# functions over the dumped spheres, computed without LIGGGHTS (protocol3_reference.c); 1 and
# 2 ranks, the receiver a ghost of the giving sphere's rank
add_executable(liggghts_protocol3_reference ${_liggghts_dir}/protocol3_reference.c)
target_link_libraries(liggghts_protocol3_reference PRIVATE capbridge)
target_compile_options(liggghts_protocol3_reference PRIVATE ${CAPBRIDGE_WARNINGS})
add_test(NAME liggghts_protocol3_receiver
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/protocol3_receiver.py
                 $<TARGET_FILE:liggghts_protocol3_reference> ${CAPBRIDGE_LIGGGHTS_ENV}
                 --workdir ${_liggghts_work}/protocol3_receiver)
# a restart file with a corrupted bridge (active 0.5; law constant -1) refused at the first
# pass of the run, the error naming both particles; the unpatched file runs with the same force
add_test(NAME liggghts_corrupt_restart
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/corrupt_restart.py
                 ${CAPBRIDGE_LIGGGHTS_ENV} --workdir ${_liggghts_work}/corrupt_restart)
# keyword remove (Richefeu 2007 fig. 7, 12: half of the bonds removed, the water content
# kept): test_remove.sh's assertions on its scene, Protocols 2 and 3, 1 and 2 ranks
add_test(NAME liggghts_remove
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/remove.py ${CAPBRIDGE_LIGGGHTS_ENV}
                 --workdir ${_liggghts_work}/remove)
# fix capillaryRemove, the removal asked for between runs (Richefeu 2007 fig. 7: half of the
# bonds removed after the consolidation): after run 1, once per simulation, 1 and 2 ranks
add_test(NAME liggghts_remove_later
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/remove_later.py ${CAPBRIDGE_LIGGGHTS_ENV}
                 --workdir ${_liggghts_work}/remove_later)
# the bridge's viscous force (viscous on) against the core's coefficients (capbridge force),
# normal, tangential with spin, torque; 1 and 2 ranks; the time-step warning
add_test(NAME liggghts_viscous
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/viscous.py
                 $<TARGET_FILE:capbridge_cli> ${CAPBRIDGE_LIGGGHTS_ENV}
                 --workdir ${_liggghts_work}/viscous)
# the viscous force of ours and of easo/capillary/viscous on one motion, each against its
# formula (the page doc/easo_viscous.md: easo_viscous.py --output)
add_test(NAME liggghts_easo_viscous
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/easo_viscous.py ${CAPBRIDGE_LIGGGHTS_ENV}
                 --workdir ${_liggghts_work}/easo_viscous)
# a wet head-on collision: restitution against St, the lubrication impulse (as the LAMMPS
# test_viscous.sh's wet collision)
add_test(NAME liggghts_wet_collision
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/wet_collision.py ${CAPBRIDGE_LIGGGHTS_ENV}
                 --workdir ${_liggghts_work}/wet_collision)
# bridges between a grain and a wall (cohesion capillary in fix wall/gran, liquid fixed): a
# primitive wall and a mesh against the core's sphere-plane pair (capbridge force --plane),
# through a restart file; a short skin and a protocol beside the pair's fixed liquid refused
add_test(NAME liggghts_wall
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/wall.py
                 $<TARGET_FILE:capbridge_cli> ${CAPBRIDGE_LIGGGHTS_ENV}
                 --workdir ${_liggghts_work}/wall)
# wall bridges under Protocols 2 and 3: the grain's liquid shared with its other new bridges,
# back at rupture, a Protocol 3 receiver; conserved on 1, 2, 3 ranks and through a restart
add_test(NAME liggghts_wall_liquid
         COMMAND ${Python3_EXECUTABLE} ${_liggghts_dir}/wall_liquid.py
                 $<TARGET_FILE:capbridge_cli> ${CAPBRIDGE_LIGGGHTS_ENV}
                 --workdir ${_liggghts_work}/wall_liquid)
# our model headers without a warning at -Wall -Wextra (LIGGGHTS builds them with its flags)
add_test(NAME liggghts_model_warnings
         COMMAND ${_liggghts_dir}/model_warnings.sh ${CAPBRIDGE_LIGGGHTS_ENV})
set_tests_properties(liggghts_pulloff liggghts_pulloff_mpi liggghts_wet liggghts_bad_input
                     liggghts_friction liggghts_held liggghts_beyond_reach
                     liggghts_easo_comparison liggghts_between_runs
                     liggghts_restart liggghts_restart_mpi liggghts_liquid_account
                     liggghts_timestep liggghts_protocols liggghts_protocol1_reference
                     liggghts_protocols_restart liggghts_protocol3_receiver
                     liggghts_corrupt_restart liggghts_remove liggghts_remove_later
                     liggghts_viscous liggghts_easo_viscous liggghts_wet_collision
                     liggghts_wall liggghts_wall_liquid liggghts_model_warnings PROPERTIES LABELS "liggghts" TIMEOUT 600)

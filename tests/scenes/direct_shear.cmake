# Smoke tests of the direct shear scene (inputs/direct_shear/, Richefeu 2007 section 3.2),
# included by tests/CMakeLists.txt when both engine env files are set.  Each test runs the
# smoke decks on 2 ranks through scripts/scene.sh and asserts physics (direct_shear_smoke.py):
# wet stronger than dry, the servo's vertical stress, liquid conserved to 1e-12, the bonds.
# Measured: LAMMPS (4 runs) 50 s, LIGGGHTS (2 runs) 81 s on 2 moderately loaded cores
# (2026-12-03, the cell of the paper's heights); 305 s and 126 s with the earlier cell when
# other jobs loaded the 2 cores 4-5 times over.
find_package(Python3 REQUIRED COMPONENTS Interpreter)
set(_ds_env CAPBRIDGE_SKIP_CONFIGURE=1
            CAPBRIDGE_PLUGIN=$<TARGET_FILE:capbridgeplugin>
            # ranks waiting in MPI give the core to the other rank (the machine may be shared)
            OMPI_MCA_mpi_yield_when_idle=1)
foreach(_ds_engine lammps liggghts)
  add_test(NAME direct_shear_${_ds_engine}
           COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/direct_shear_smoke.py
                   ${_ds_engine} ${PROJECT_SOURCE_DIR}/scripts/scene.sh
                   ${CMAKE_CURRENT_BINARY_DIR}/scenes/direct_shear/${_ds_engine})
  set_tests_properties(direct_shear_${_ds_engine} PROPERTIES
                       LABELS "scenes" TIMEOUT 600 PROCESSORS 2 ENVIRONMENT "${_ds_env}")
endforeach()
# the bound of w names its unit, percent (every deck takes w in percent since December 2026;
# direct shear's range starts at 0, dry, and its study runs w = 0.1 %, the paper's w_m: no
# lower bound)
foreach(_ds_engine lammps liggghts)
  add_test(NAME direct_shear_${_ds_engine}_refuses_w
           COMMAND ${PROJECT_SOURCE_DIR}/scripts/scene.sh ${_ds_engine} direct_shear -np 1 -size smoke
                   -out ${CMAKE_CURRENT_BINARY_DIR}/scenes/direct_shear/refusals_${_ds_engine} -var w 20)
  set_tests_properties(direct_shear_${_ds_engine}_refuses_w PROPERTIES
    LABELS "scenes" TIMEOUT 120 ENVIRONMENT "${_ds_env}"
    PASS_REGULAR_EXPRESSION "ERROR: need sigma > 0 Pa and 0 <= w < 20, w in percent of the grain mass \\(1 = 1 %, not a fraction\\), got sigma 200, w 20")
endforeach()
# the shear speed must be positive (-var vshear, the rate sweep's knob)
foreach(_ds_engine lammps liggghts)
  add_test(NAME direct_shear_${_ds_engine}_refuses_vshear
           COMMAND ${PROJECT_SOURCE_DIR}/scripts/scene.sh ${_ds_engine} direct_shear -np 1 -size smoke
                   -out ${CMAKE_CURRENT_BINARY_DIR}/scenes/direct_shear/refusals_vshear_${_ds_engine} -var vshear 0)
  set_tests_properties(direct_shear_${_ds_engine}_refuses_vshear PROPERTIES
    LABELS "scenes" TIMEOUT 120 ENVIRONMENT "${_ds_env}"
    PASS_REGULAR_EXPRESSION "vshear \\(the speed of the upper ring\\) must be > 0")
endforeach()

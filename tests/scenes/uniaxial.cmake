# Smoke tests of the uniaxial compression scene (inputs/uniaxial/, Richefeu 2007 section 4.2),
# included by tests/CMakeLists.txt when both engines are configured. Each test runs the smoke
# deck wet and dry on 2 ranks through scripts/scene.sh, then asserts the physics
# (tests/scenes/uniaxial_smoke.py): the wet sample stands and resists, the dry one does not,
# the liquid is conserved, half of the bridges removed halves the bridge coordination.
foreach(engine lammps liggghts)
  add_test(NAME scene_uniaxial_${engine}
           COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/scenes/uniaxial_smoke.py
                   ${engine} ${CMAKE_CURRENT_BINARY_DIR}/scenes/uniaxial_${engine})
  set_tests_properties(scene_uniaxial_${engine} PROPERTIES
    LABELS "scenes" TIMEOUT 600 PROCESSORS 2
    ENVIRONMENT "CAPBRIDGE_SKIP_CONFIGURE=1;CAPBRIDGE_PLUGIN=$<TARGET_FILE:capbridgeplugin>")
endforeach()

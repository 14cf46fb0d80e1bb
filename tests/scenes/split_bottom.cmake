# Smoke tests of the split-bottom ring shear cell (inputs/split_bottom/, Gladkyy 2014 §4.1),
# included by tests/CMakeLists.txt when both engines are configured.  Per engine: two runs of
# the smoke deck on 2 ranks through scripts/scene.sh, dry and wet (74.2 nl bridges, law
# willett), then split_bottom_check.py asserts the physics on them (shear band at the split,
# omega from 0 to Omega, bridges, liquid = bridges x V, wet torque above dry).
# About 40 s per run on an idle machine.
foreach(_engine lammps liggghts)
  set(_work ${CMAKE_CURRENT_BINARY_DIR}/scenes/split_bottom/${_engine})
  foreach(_case dry wet)
    if(_case STREQUAL dry)
      set(_volume 0)
    else()
      set(_volume 74.2)
    endif()
    add_test(NAME scene_split_bottom_${_engine}_${_case}
             COMMAND ${PROJECT_SOURCE_DIR}/scripts/scene.sh ${_engine} split_bottom -np 2
                     -size smoke -out ${_work}/${_case} -var volume ${_volume} -var law willett)
    set_tests_properties(scene_split_bottom_${_engine}_${_case} PROPERTIES
      LABELS "scenes" TIMEOUT 600 PROCESSORS 2
      FIXTURES_SETUP split_bottom_${_engine}
      ENVIRONMENT "CAPBRIDGE_SKIP_CONFIGURE=1;CAPBRIDGE_PLUGIN=$<TARGET_FILE:capbridgeplugin>")
  endforeach()
  add_test(NAME scene_split_bottom_${_engine}_check
           COMMAND /usr/bin/python3 ${CMAKE_CURRENT_LIST_DIR}/split_bottom_check.py ${_work})
  set_tests_properties(scene_split_bottom_${_engine}_check PROPERTIES
    LABELS "scenes" TIMEOUT 600 FIXTURES_REQUIRED split_bottom_${_engine})
endforeach()
# the rotation period must be positive (-var period, the rate sweep's knob)
foreach(_engine lammps liggghts)
  add_test(NAME scene_split_bottom_${_engine}_refuses_period
           COMMAND ${PROJECT_SOURCE_DIR}/scripts/scene.sh ${_engine} split_bottom -np 1 -size smoke
                   -out ${CMAKE_CURRENT_BINARY_DIR}/scenes/split_bottom/refusals_${_engine} -var period 0)
  set_tests_properties(scene_split_bottom_${_engine}_refuses_period PROPERTIES
    LABELS "scenes" TIMEOUT 120
    ENVIRONMENT "CAPBRIDGE_SKIP_CONFIGURE=1;CAPBRIDGE_PLUGIN=$<TARGET_FILE:capbridgeplugin>"
    PASS_REGULAR_EXPRESSION "period \\(one turn of the rotating outer part\\) must be > 0 s, not 0")
endforeach()

# Smoke tests of the split-bottom ring shear cell (inputs/split_bottom/, Gladkyy 2014 §4.1),
# included by tests/CMakeLists.txt when both engines are configured.  Per engine one test runs
# the smoke deck dry and wet (74.2 nl bridges) on 2 ranks through scripts/scene.sh and asserts
# the physics with split_bottom_check.py (shear band at the split, bridges, liquid = bridges x
# V, wet torque above dry).  About 1.5 min per engine.
foreach(_engine lammps liggghts)
  add_test(NAME scene_split_bottom_${_engine}
           COMMAND /usr/bin/python3 ${CMAKE_CURRENT_LIST_DIR}/split_bottom_check.py ${_engine}
                   ${CMAKE_CURRENT_BINARY_DIR}/scenes/split_bottom/${_engine})
  set_tests_properties(scene_split_bottom_${_engine} PROPERTIES
    LABELS "scenes" TIMEOUT 600 PROCESSORS 2
    ENVIRONMENT "CAPBRIDGE_SKIP_CONFIGURE=1;CAPBRIDGE_PLUGIN=$<TARGET_FILE:capbridgeplugin>")
endforeach()

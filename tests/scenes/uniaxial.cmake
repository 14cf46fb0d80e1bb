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
# w is in percent of the grains' mass (Richefeu 2007 writes w = 2 %); the decks took a mass
# fraction until December 2026, so a w below 0.2 (the paper's range is 0.5-12 %) is refused
# as that old reading, naming the value to give; the range and the packing seed are checked
# by name. Each run stops at the deck's checks, before any atom exists. After the message:
# a further variable and its value, if any.
function(uniaxial_refusal engine name var value message)
  set(more)
  if(ARGC EQUAL 7)
    set(more -var ${ARGV5} ${ARGV6})
  endif()
  add_test(NAME scene_uniaxial_${engine}_refuses_${name}
           COMMAND ${PROJECT_SOURCE_DIR}/scripts/scene.sh ${engine} uniaxial -np 1 -size smoke
                   -out ${CMAKE_CURRENT_BINARY_DIR}/scenes/uniaxial_refusals/${engine}_${name} -var ${var} ${value}
                   ${more})
  set_tests_properties(scene_uniaxial_${engine}_refuses_${name} PROPERTIES
    LABELS "scenes" TIMEOUT 120 PASS_REGULAR_EXPRESSION "${message}"
    ENVIRONMENT "CAPBRIDGE_SKIP_CONFIGURE=1;CAPBRIDGE_PLUGIN=$<TARGET_FILE:capbridgeplugin>")
endfunction()
foreach(engine lammps liggghts)
  uniaxial_refusal(${engine} w_fraction w 0.02
    "uniaxial: w = 0.02 %: the uniaxial decks take percent since December 2026 \\(0.02 was a mass fraction, 2 %\\). give -var w 2")
  uniaxial_refusal(${engine} w_fraction_small w 0.005
    "uniaxial: w = 0.005 %: the uniaxial decks take percent since December 2026 \\(0.005 was a mass fraction, 0.5 %\\). give -var w 0.5")
  uniaxial_refusal(${engine} w_range w 20
    "uniaxial: w = 20 %: w is the water content in percent of the grain mass, allowed 0.2 <= w < 20")
  uniaxial_refusal(${engine} seed seed 2.5 "uniaxial: seed must be a .*, not 2.5")
endforeach()
# start free is Protocols 2 and 3's (Protocol 1 distributes the liquid anyway)
uniaxial_refusal(lammps start_protocol1 start free
  "uniaxial: start free needs protocol2 or protocol3, not protocol1")
# LIGGGHTS's wet plate needs a protocol (a fixed volume would make and destroy the liquid the
# grains hold)
uniaxial_refusal(liggghts plate_fixed plate wet
  "plate wet \\(dry; wet with protocol1, protocol2 or protocol3, not dry yes\\): a Label-not-found error right after this line means a value not allowed[\r\n]+ERROR: Label wasn't found"
  protocol fixed)

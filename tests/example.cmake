# Included by tests/CMakeLists.txt: the WSAD example in a real X server (Xvfb) with real key events (xdotool).
if(NOT TARGET wsad)
  message(STATUS "motus: example tests skipped (no raylib, or MOTUS_BUILD_EXAMPLES=OFF)")
  return()
endif()
# motus_vec2 and motus_vec3 against the real raylib.h (tests/unit.c checks a copy of the declaration everywhere).
motus_test_program(motus_raylib_layout raylib_layout.c)
target_link_libraries(motus_raylib_layout PRIVATE motus::raylib)
add_test(NAME unit.raylib_vector_layout COMMAND motus_raylib_layout)
set_tests_properties(unit.raylib_vector_layout PROPERTIES LABELS unit)

# Each key held for a second must move the particle its way; the script reads the printed final state.
foreach(key w a s d)
  add_test(NAME example.wsad_key_${key}
    COMMAND "${CMAKE_CURRENT_SOURCE_DIR}/example_wsad.sh" $<TARGET_FILE:wsad> ${key}
            "${CMAKE_CURRENT_BINARY_DIR}/example")
  set_tests_properties(example.wsad_key_${key} PROPERTIES LABELS example RESOURCE_LOCK x_server TIMEOUT 120)
endforeach()
# The orbits example: a headless run of 600 frames checked on its printed errors and on its screenshot's
# colours (tests/example_orbits.sh decodes the PNG with python3, so it needs no stb), and two real keys.
if(TARGET orbits)
  foreach(mode headless key_space key_up)
    add_test(NAME example.orbits_${mode}
      COMMAND "${CMAKE_CURRENT_SOURCE_DIR}/example_orbits.sh" $<TARGET_FILE:orbits> ${mode}
              "${CMAKE_CURRENT_BINARY_DIR}/example")
    set_tests_properties(example.orbits_${mode} PROPERTIES LABELS example RESOURCE_LOCK x_server TIMEOUT 120)
  endforeach()
endif()
# The sandbox example: headless runs with gravity and wind on and off, checked on their printed means and on
# the screenshot's colours, and under each method; with collisions on, a pile on the floor checked on its
# printed overlaps (< 1% of a radius), speeds and extent; and G, W, K, D, M, R, C, T held as real keys, each
# checked to change its switch (and the printed scene), the method or reset (C: and the pile it makes; T: the
# swarm gathered at the pointer).
if(TARGET sandbox)
  foreach(mode headless collisions methods key_g key_w key_k key_d key_m key_r key_c key_t)
    add_test(NAME example.sandbox_${mode}
      COMMAND "${CMAKE_CURRENT_SOURCE_DIR}/example_sandbox.sh" $<TARGET_FILE:sandbox> ${mode}
              "${CMAKE_CURRENT_BINARY_DIR}/example")
    set_tests_properties(example.sandbox_${mode} PROPERTIES LABELS example RESOURCE_LOCK x_server TIMEOUT 120)
  endforeach()
endif()

# The headless run the demo makes: a fixed number of frames, scripted input, a screenshot, checked on pixels.
find_path(MOTUS_STB_INCLUDE_DIR stb/stb_image.h)
if(NOT MOTUS_STB_INCLUDE_DIR)
  message(WARNING "motus: example.wsad_screenshot needs stb_image (Debian libstb-dev); skipped")
  return()
endif()
add_executable(motus_screenshot_probe screenshot_probe.c)
target_include_directories(motus_screenshot_probe PRIVATE "${MOTUS_STB_INCLUDE_DIR}")
target_link_libraries(motus_screenshot_probe PRIVATE m)
add_test(NAME example.wsad_screenshot
  COMMAND "${CMAKE_CURRENT_SOURCE_DIR}/example_screenshot.sh" $<TARGET_FILE:wsad>
          $<TARGET_FILE:motus_screenshot_probe> "${CMAKE_CURRENT_BINARY_DIR}/example/wsad_autopilot.png")
set_tests_properties(example.wsad_screenshot PROPERTIES LABELS example RESOURCE_LOCK x_server TIMEOUT 120)

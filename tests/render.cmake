# Included by tests/CMakeLists.txt: the OSMesa canvas and the closed-form render tests.
find_package(PkgConfig)
if(PkgConfig_FOUND)
  pkg_check_modules(OSMESA IMPORTED_TARGET osmesa)
endif()
find_path(MOTUS_STB_INCLUDE_DIR stb/stb_image_write.h)
if(NOT OSMESA_FOUND OR NOT MOTUS_STB_INCLUDE_DIR)
  message(WARNING "motus: render tests need OSMesa and stb_image_write (Debian: libosmesa6-dev libstb-dev; "
                  "scripts/deps.sh installs them). They are registered as failing until then.")
  add_test(NAME render.missing_dependencies COMMAND "${CMAKE_COMMAND}" -E false)
  set_tests_properties(render.missing_dependencies PROPERTIES LABELS render)
  return()
endif()

add_library(motus_canvas STATIC support/motus_canvas.c)
target_include_directories(motus_canvas PUBLIC "${CMAKE_CURRENT_SOURCE_DIR}/support" PRIVATE "${MOTUS_STB_INCLUDE_DIR}")
target_link_libraries(motus_canvas PUBLIC PkgConfig::OSMESA m)
set_target_properties(motus_canvas PROPERTIES C_STANDARD 99 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF)

set(MOTUS_RENDER_DIR "${CMAKE_CURRENT_BINARY_DIR}/render")
file(MAKE_DIRECTORY "${MOTUS_RENDER_DIR}")

motus_test_program(motus_canvas_selftest support/canvas_selftest.c)
target_link_libraries(motus_canvas_selftest PRIVATE motus_canvas)
add_test(NAME render.canvas_centroid_accuracy COMMAND motus_canvas_selftest WORKING_DIRECTORY "${MOTUS_RENDER_DIR}")
set_tests_properties(render.canvas_centroid_accuracy PROPERTIES LABELS render)

# Float (render.*) and double (render.double.*) builds; the double build writes its pictures under double/.
file(MAKE_DIRECTORY "${MOTUS_RENDER_DIR}/double")
motus_test_program(motus_render render.c)
motus_test_program(motus_render_double render.c)
target_link_libraries(motus_render PRIVATE motus_canvas)
target_link_libraries(motus_render_double PRIVATE motus_canvas)
target_compile_definitions(motus_render PRIVATE MOTUS_RENDER_DIR="${MOTUS_RENDER_DIR}")
target_compile_definitions(motus_render_double PRIVATE MOTUS_DOUBLE MOTUS_RENDER_DIR="${MOTUS_RENDER_DIR}/double")
motus_register_tests(motus_render "${CMAKE_CURRENT_SOURCE_DIR}/render.c" render render)
motus_register_tests(motus_render_double "${CMAKE_CURRENT_SOURCE_DIR}/render.c" render.double render)

# Contacts (issue 12): two equal balls colliding head-on (restitution 1 and 0.5), their drawn centroids
# against the closed form before and after the contact; float and double as above.
motus_test_program(motus_render_contacts render_contacts.c)
motus_test_program(motus_render_contacts_double render_contacts.c)
target_link_libraries(motus_render_contacts PRIVATE motus_canvas)
target_link_libraries(motus_render_contacts_double PRIVATE motus_canvas)
target_compile_definitions(motus_render_contacts PRIVATE MOTUS_RENDER_DIR="${MOTUS_RENDER_DIR}")
target_compile_definitions(motus_render_contacts_double PRIVATE MOTUS_DOUBLE MOTUS_RENDER_DIR="${MOTUS_RENDER_DIR}/double")
motus_register_tests(motus_render_contacts "${CMAKE_CURRENT_SOURCE_DIR}/render_contacts.c" render render)
motus_register_tests(motus_render_contacts_double "${CMAKE_CURRENT_SOURCE_DIR}/render_contacts.c" render.double render)

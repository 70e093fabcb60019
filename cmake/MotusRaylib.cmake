# MotusRaylib.cmake -- locate raylib for the optional motus raylib example.
#
#   include(cmake/MotusRaylib.cmake)   # after project(... LANGUAGES C)
#   motus_find_raylib()
#   if(MOTUS_RAYLIB_FOUND)
#     target_link_libraries(my_example PRIVATE motus::raylib)
#   endif()
#
# motus_find_raylib() never fails the configure step.  On success it creates
# the IMPORTED INTERFACE target motus::raylib (include dirs + every library
# needed to link) and sets, in the caller's scope:
#   MOTUS_RAYLIB_FOUND   TRUE / FALSE
#   MOTUS_RAYLIB_SOURCE  how it was found: "config" | "pkg-config" | "prefix"
#                        | "fetch" | "" (not found)
# On failure it prints one STATUS line explaining how to get raylib.
#
# Search order (the first that yields a raylib we can link with wins):
#   a) find_package(raylib CONFIG)   -- raylib's own CMake package (target raylib)
#   b) pkg-config module "raylib"    -- via FindPkgConfig (its resolved
#      libraries, Libs.private when static, plus the system libraries)
#   c) the prefix MOTUS_RAYLIB_PREFIX (default <project>/.deps/raylib, which
#      scripts/bootstrap-raylib.sh fills): include/raylib.h + lib/libraylib.a,
#      plus GLFW only if this libraylib.a does not bundle it (lib/libglfw3.a,
#      find_package(glfw3) or pkg-config glfw3), plus the system libraries
#      (X11, math, threads, dl).
#   d) only when MOTUS_FETCH_RAYLIB=ON: FetchContent from raylib's upstream
#      git repository (MOTUS_RAYLIB_GIT_REPOSITORY @ MOTUS_RAYLIB_GIT_TAG).
#
# a)-c) are verified with a configure-time link test of a program that calls
# InitWindow(); a candidate that does not link is skipped.  The test needs the
# C language to be enabled; without it the candidates are taken on trust.
#
# Call motus_find_raylib() from the directory that owns the consumers (or a
# parent of it): imported targets are visible in that directory and below.

include_guard(GLOBAL)

set(_MOTUS_RAYLIB_MODULE_DIR "${CMAKE_CURRENT_LIST_DIR}")

# System libraries a static raylib (desktop/GLFW platform) needs.  Appends to
# the list named by <out>.
function(_motus_raylib_system_libs out)
  set(libs)
  if(WIN32)
    list(APPEND libs opengl32 gdi32 winmm)
  elseif(APPLE)
    list(APPEND libs "-framework Cocoa" "-framework IOKit" "-framework CoreVideo"
                     "-framework CoreAudio" "-framework OpenGL")
  elseif(UNIX)
    find_package(X11 QUIET)
    if(TARGET X11::X11)
      list(APPEND libs X11::X11)
    elseif(X11_X11_LIB)
      list(APPEND libs "${X11_X11_LIB}")
    endif()
    find_package(Threads QUIET)
    if(TARGET Threads::Threads)
      list(APPEND libs Threads::Threads)
    endif()
    if(CMAKE_DL_LIBS)
      list(APPEND libs ${CMAKE_DL_LIBS})
    endif()
    list(APPEND libs m)
  endif()
  set(${out} ${${out}} ${libs} PARENT_SCOPE)
endfunction()

# Configure-time link test: does a program calling InitWindow() link against
# <libs> with <incdirs>?  Result in <out> (TRUE/FALSE); cached per input set.
function(_motus_raylib_links out incdirs libs)
  get_property(_langs GLOBAL PROPERTY ENABLED_LANGUAGES)
  if(NOT "C" IN_LIST _langs)
    set(${out} TRUE PARENT_SCOPE)   # cannot test; take it on trust
    return()
  endif()
  include(CheckCSourceCompiles)
  string(MD5 _key "${incdirs}|${libs}|${CMAKE_C_COMPILER}|${CMAKE_C_FLAGS}")
  set(_var "MOTUS_RAYLIB_LINKS_${_key}")
  set(CMAKE_REQUIRED_INCLUDES ${incdirs})
  set(CMAKE_REQUIRED_LIBRARIES ${libs})
  set(CMAKE_REQUIRED_DEFINITIONS)
  set(CMAKE_REQUIRED_LINK_OPTIONS)
  set(CMAKE_REQUIRED_QUIET ON)
  # InitWindow sits behind a run-time condition: the whole platform layer
  # (GLFW, X11) is linked in, but nothing would open a window if it ran.
  check_c_source_compiles("
#include <raylib.h>
int main(int argc, char **argv) {
    (void)argv;
    if (argc > 99) InitWindow(8, 8, \"motus\");
    return 0;
}" ${_var})
  if(${_var})
    set(${out} TRUE PARENT_SCOPE)
  else()
    set(${out} FALSE PARENT_SCOPE)
    unset(${_var} CACHE)   # do not remember failures: retry next configure
  endif()
endfunction()

# Turn a link candidate into motus::raylib.
function(_motus_raylib_make_target incdirs libs)
  add_library(motus::raylib INTERFACE IMPORTED)
  if(incdirs)
    set_property(TARGET motus::raylib PROPERTY INTERFACE_INCLUDE_DIRECTORIES ${incdirs})
  endif()
  set_property(TARGET motus::raylib PROPERTY INTERFACE_LINK_LIBRARIES ${libs})
endfunction()

# c) helper: GLFW from a prefix, an installed CMake package or pkg-config.
# Sets <out> to a link item, or empty.
function(_motus_raylib_find_glfw out prefix)
  set(${out} "" PARENT_SCOPE)
  # Plain existence checks (no find_library cache entry that would go stale
  # when MOTUS_RAYLIB_PREFIX changes).
  foreach(_cand "${prefix}/lib/libglfw3.a" "${prefix}/lib64/libglfw3.a"
                "${prefix}/lib/libglfw.so" "${prefix}/lib64/libglfw.so")
    if(EXISTS "${_cand}")
      set(${out} "${_cand}" PARENT_SCOPE)
      return()
    endif()
  endforeach()
  find_package(glfw3 CONFIG QUIET)
  if(TARGET glfw)
    set(${out} glfw PARENT_SCOPE)
    return()
  endif()
  find_package(PkgConfig QUIET)
  if(PKG_CONFIG_FOUND)
    pkg_check_modules(MOTUS_PC_GLFW3 QUIET IMPORTED_TARGET glfw3)
    if(TARGET PkgConfig::MOTUS_PC_GLFW3)
      set(${out} PkgConfig::MOTUS_PC_GLFW3 PARENT_SCOPE)
    endif()
  endif()
endfunction()

function(motus_find_raylib)
  # Default prefix: <project>/.deps/raylib (what scripts/bootstrap-raylib.sh
  # fills).  Fall back to the directory above this module if called before
  # project().
  if(PROJECT_SOURCE_DIR)
    set(_default_prefix "${PROJECT_SOURCE_DIR}/.deps/raylib")
  else()
    get_filename_component(_default_prefix "${_MOTUS_RAYLIB_MODULE_DIR}/../.deps/raylib" ABSOLUTE)
  endif()
  set(MOTUS_RAYLIB_PREFIX "${_default_prefix}" CACHE PATH
      "Prefix holding include/raylib.h and lib/libraylib.a (see scripts/bootstrap-raylib.sh)")
  option(MOTUS_FETCH_RAYLIB "Download and build raylib with FetchContent if it is not found otherwise" OFF)
  set(MOTUS_RAYLIB_GIT_REPOSITORY "https://github.com/raysan5/raylib.git" CACHE STRING
      "raylib git repository used when MOTUS_FETCH_RAYLIB=ON")
  set(MOTUS_RAYLIB_GIT_TAG "5.5" CACHE STRING
      "raylib git tag/commit used when MOTUS_FETCH_RAYLIB=ON")
  mark_as_advanced(MOTUS_RAYLIB_GIT_REPOSITORY MOTUS_RAYLIB_GIT_TAG)

  # Already resolved by an earlier call (in this or a parent directory).
  if(TARGET motus::raylib)
    get_property(_src GLOBAL PROPERTY MOTUS_RAYLIB_SOURCE)
    set(MOTUS_RAYLIB_FOUND TRUE PARENT_SCOPE)
    set(MOTUS_RAYLIB_SOURCE "${_src}" PARENT_SCOPE)
    return()
  endif()

  set(_found FALSE)
  set(_source "")
  set(_detail "")
  set(_why "")
  set(_glfw "")
  set(_sys)
  _motus_raylib_system_libs(_sys)

  # a) raylib's own CMake package.  Its config file may create the target
  #    even when it did not find the library, so raylib_FOUND is checked too,
  #    and a static raylib found this way may lack its private dependencies:
  #    the system libraries are appended (harmless when redundant).
  if(NOT _found)
    find_package(raylib CONFIG QUIET)
    if(raylib_FOUND AND TARGET raylib)
      set(_libs raylib ${_sys})
      _motus_raylib_links(_ok "" "${_libs}")
      if(_ok)
        _motus_raylib_make_target("" "${_libs}")
        set(_found TRUE)
        set(_source config)
        set(_detail "${raylib_DIR}")
      endif()
    endif()
  endif()

  # b) pkg-config.  The module's resolved libraries are used as a flat list
  #    (linking the PkgConfig:: INTERFACE target would let CMake put the
  #    system libraries before a static libraylib.a).  A static raylib also
  #    needs Libs.private, which is appended along with the system libraries.
  if(NOT _found)
    find_package(PkgConfig QUIET)
    if(PKG_CONFIG_FOUND)
      pkg_check_modules(MOTUS_PC_RAYLIB QUIET raylib)
      if(MOTUS_PC_RAYLIB_FOUND AND MOTUS_PC_RAYLIB_LINK_LIBRARIES)
        set(_libs ${MOTUS_PC_RAYLIB_LINK_LIBRARIES} ${MOTUS_PC_RAYLIB_LDFLAGS_OTHER})
        list(GET MOTUS_PC_RAYLIB_LINK_LIBRARIES 0 _pc_lib)
        if(_pc_lib MATCHES "\\.a$")
          foreach(_d IN LISTS MOTUS_PC_RAYLIB_STATIC_LIBRARY_DIRS)
            list(APPEND _libs "-L${_d}")
          endforeach()
          foreach(_l IN LISTS MOTUS_PC_RAYLIB_STATIC_LIBRARIES)
            if(NOT _l STREQUAL "raylib")
              list(APPEND _libs "${_l}")
            endif()
          endforeach()
        endif()
        list(APPEND _libs ${_sys})
        _motus_raylib_links(_ok "${MOTUS_PC_RAYLIB_INCLUDE_DIRS}" "${_libs}")
        if(_ok)
          _motus_raylib_make_target("${MOTUS_PC_RAYLIB_INCLUDE_DIRS}" "${_libs}")
          if(MOTUS_PC_RAYLIB_CFLAGS_OTHER)
            set_property(TARGET motus::raylib PROPERTY
                         INTERFACE_COMPILE_OPTIONS ${MOTUS_PC_RAYLIB_CFLAGS_OTHER})
          endif()
          set(_found TRUE)
          set(_source pkg-config)
          set(_detail "raylib ${MOTUS_PC_RAYLIB_VERSION}, ${_pc_lib}")
        endif()
      endif()
    endif()
  endif()

  # c) a plain prefix (scripts/bootstrap-raylib.sh or a hand-made install).
  if(NOT _found AND MOTUS_RAYLIB_PREFIX)
    set(_p "${MOTUS_RAYLIB_PREFIX}")
    if(EXISTS "${_p}/include/raylib.h")
      set(_lib "")
      foreach(_cand "${_p}/lib/libraylib.a" "${_p}/lib64/libraylib.a"
                    "${_p}/lib/raylib.lib" "${_p}/lib/libraylib.so" "${_p}/lib64/libraylib.so")
        if(EXISTS "${_cand}")
          set(_lib "${_cand}")
          break()
        endif()
      endforeach()
      if(_lib)
        set(_inc "${_p}/include")
        # libraylib.a normally bundles GLFW (raylib's default, and the case
        # for the bootstrap's wheel build): try without an external GLFW
        # first, then with one.
        set(_libs "${_lib}" ${_sys})
        _motus_raylib_links(_ok "${_inc}" "${_libs}")
        if(NOT _ok)
          _motus_raylib_find_glfw(_glfw "${_p}")
          if(_glfw)
            set(_libs "${_lib}" ${_glfw} ${_sys})
            _motus_raylib_links(_ok "${_inc}" "${_libs}")
          endif()
        endif()
        if(NOT _ok AND UNIX AND NOT APPLE)
          # raylib built against GL directly, or on targets that need atomics.
          find_package(OpenGL QUIET)
          set(_extra)
          if(TARGET OpenGL::GL)
            list(APPEND _extra OpenGL::GL)
          endif()
          find_library(MOTUS_RAYLIB_ATOMIC_LIBRARY NAMES atomic libatomic.so.1)
          mark_as_advanced(MOTUS_RAYLIB_ATOMIC_LIBRARY)
          if(MOTUS_RAYLIB_ATOMIC_LIBRARY)
            list(APPEND _extra "${MOTUS_RAYLIB_ATOMIC_LIBRARY}")
          endif()
          set(_libs "${_lib}" ${_glfw} ${_extra} ${_sys})
          _motus_raylib_links(_ok "${_inc}" "${_libs}")
        endif()
        if(_ok)
          _motus_raylib_make_target("${_inc}" "${_libs}")
          set(_found TRUE)
          set(_source prefix)
          set(_detail "${_lib}")
        else()
          set(_why "${_lib} was found but a test program did not link with it (see CMakeFiles/CMakeError.log or CMakeConfigureLog.yaml; on Debian: apt-get install libx11-dev)")
        endif()
      else()
        set(_why "${_p}/include/raylib.h exists but ${_p}/lib/libraylib.a does not")
      endif()
    endif()
  endif()

  # d) FetchContent from upstream (opt-in; needs network access to the git
  #    host, and the X11/GL development packages raylib's own build wants).
  if(NOT _found AND MOTUS_FETCH_RAYLIB)
    if(TARGET raylib)
      # e.g. a raylib config package that created an unusable target in a).
      set(_why "MOTUS_FETCH_RAYLIB=ON but a target named 'raylib' already exists, so it cannot be fetched")
    else()
      include(FetchContent)
      FetchContent_Declare(raylib
        GIT_REPOSITORY "${MOTUS_RAYLIB_GIT_REPOSITORY}"
        GIT_TAG        "${MOTUS_RAYLIB_GIT_TAG}"
        GIT_SHALLOW    TRUE
        GIT_PROGRESS   FALSE)
      # Keep raylib's build lean.  These are normal variables in this
      # function's scope, so they reach raylib's option() calls (CMP0077)
      # without touching the cache or leaking into the caller.
      set(CMAKE_POLICY_DEFAULT_CMP0077 NEW)
      set(BUILD_EXAMPLES OFF)
      set(BUILD_GAMES OFF)
      set(BUILD_REXM OFF)
      set(BUILD_SHARED_LIBS OFF)
      set(CUSTOMIZE_BUILD OFF)
      set(PLATFORM Desktop)
      message(STATUS "motus: fetching raylib ${MOTUS_RAYLIB_GIT_TAG} from ${MOTUS_RAYLIB_GIT_REPOSITORY}")
      FetchContent_MakeAvailable(raylib)
      if(TARGET raylib)
        # raylib's own target carries its include directory and private
        # link dependencies; nothing else is needed.
        add_library(motus::raylib INTERFACE IMPORTED)
        set_property(TARGET motus::raylib PROPERTY INTERFACE_LINK_LIBRARIES raylib)
        set(_found TRUE)
        set(_source fetch)
        set(_detail "${MOTUS_RAYLIB_GIT_TAG}")
      else()
        set(_why "FetchContent of raylib ${MOTUS_RAYLIB_GIT_TAG} did not define a 'raylib' target")
      endif()
    endif()
  endif()

  if(_found)
    set_property(GLOBAL PROPERTY MOTUS_RAYLIB_SOURCE "${_source}")
    message(STATUS "motus: raylib found (${_source}: ${_detail})")
  else()
    if(NOT _why)
      set(_why "not found via find_package(raylib), pkg-config, or the prefix ${MOTUS_RAYLIB_PREFIX}")
    endif()
    get_property(_told GLOBAL PROPERTY _MOTUS_RAYLIB_TOLD)
    if(NOT _told)   # say it once per configure, however often we are called
      set_property(GLOBAL PROPERTY _MOTUS_RAYLIB_TOLD TRUE)
      message(STATUS "motus: raylib example skipped -- ${_why}. "
                     "To build it: run scripts/bootstrap-raylib.sh (downloads prebuilt raylib into .deps/raylib), "
                     "or pass -DMOTUS_RAYLIB_PREFIX=/path/to/raylib/prefix, or -DMOTUS_FETCH_RAYLIB=ON to build it from source.")
    endif()
  endif()
  set(MOTUS_RAYLIB_FOUND ${_found} PARENT_SCOPE)
  set(MOTUS_RAYLIB_SOURCE "${_source}" PARENT_SCOPE)
endfunction()

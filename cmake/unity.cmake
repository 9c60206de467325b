# SPDX-License-Identifier: BSD-3-Clause
# cmake/unity.cmake - provide the static library target `mtt_unity`: the Unity
# C test framework (ThrowTheSwitch), never committed to this repository.
#
# Unity is looked for in this order:
#   (a) -DUNITY_SOURCE_DIR=<dir> holding unity.c (directly or in src/);
#   (b) an installed Unity: find_package(unity CONFIG) (target unity::framework),
#       else unity_internals.h + libunity found by find_path/find_library;
#   (c) <mtt source>/.deps/unity, filled by tools/ci/setup-unity.sh (gitignored);
#   (d) if MTT_FETCH_UNITY (default ON): download of the upstream release
#       (MTT_UNITY_URL, v2.6.0) with a 20 s timeout.  If that fails the
#       configure stops with a message naming tools/ci/setup-unity.sh.
#
# Tests link `mtt_unity`; it carries UNITY_INCLUDE_DOUBLE (double asserts) and
# puts unity.h on the include path as a system header.  An installed Unity
# (b) must have been built with UNITY_INCLUDE_DOUBLE as well.  MTT_UNITY_ORIGIN tells
# which of (a)-(d) was used.
include_guard(GLOBAL)

set(UNITY_SOURCE_DIR "" CACHE PATH
    "Directory with Unity's unity.c, unity.h, unity_internals.h (directly or in src/)")
option(MTT_FETCH_UNITY "Download Unity from upstream when it is not found locally" ON)
set(MTT_UNITY_URL "https://github.com/ThrowTheSwitch/Unity/archive/refs/tags/v2.6.0.tar.gz"
    CACHE STRING "Upstream Unity release archive used when MTT_FETCH_UNITY is ON")
set(MTT_UNITY_SHA256 "aa4c9fb1ae5fc5242f914c65f3557e817e40cb37f04a31e5ff76d1ab89dbf674"
    CACHE STRING "SHA-256 of MTT_UNITY_URL (empty: not checked)")

set(_mtt_unity_defs UNITY_INCLUDE_DOUBLE)

# Return in <out> the directory of unity.c under <dir> (dir or dir/src), or "".
function(_mtt_unity_src_in dir out)
  set(_r "")
  if(EXISTS "${dir}/unity.c" AND EXISTS "${dir}/unity.h" AND EXISTS "${dir}/unity_internals.h")
    set(_r "${dir}")
  elseif(EXISTS "${dir}/src/unity.c" AND EXISTS "${dir}/src/unity.h"
         AND EXISTS "${dir}/src/unity_internals.h")
    set(_r "${dir}/src")
  endif()
  set(${out} "${_r}" PARENT_SCOPE)
endfunction()

# Build mtt_unity from the sources in <srcdir>.
function(_mtt_unity_from_sources srcdir origin)
  add_library(mtt_unity STATIC "${srcdir}/unity.c")
  target_include_directories(mtt_unity SYSTEM PUBLIC "${srcdir}")
  target_compile_definitions(mtt_unity PUBLIC ${_mtt_unity_defs})
  set_target_properties(mtt_unity PROPERTIES
    C_STANDARD 99 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF
    FOLDER "third_party")
  set(MTT_UNITY_ORIGIN "${origin}: ${srcdir}" CACHE INTERNAL "")
  message(STATUS "mtt: Unity from ${origin} (${srcdir})")
endfunction()

if(TARGET mtt_unity)
  return()
endif()

# (a) explicit source directory --------------------------------------------
if(UNITY_SOURCE_DIR)
  _mtt_unity_src_in("${UNITY_SOURCE_DIR}" _src)
  if(NOT _src)
    message(FATAL_ERROR
      "UNITY_SOURCE_DIR=${UNITY_SOURCE_DIR} holds no unity.c/unity.h/unity_internals.h "
      "(looked in it and in its src/).")
  endif()
  _mtt_unity_from_sources("${_src}" "UNITY_SOURCE_DIR")
  return()
endif()

# (b) an installed Unity ------------------------------------------------------
find_package(unity CONFIG QUIET)
if(TARGET unity::framework)
  # The tests use double asserts: the installed Unity must have been built
  # with UNITY_INCLUDE_DOUBLE too (else UnityAssertDoublesWithin is missing).
  add_library(mtt_unity INTERFACE)
  target_link_libraries(mtt_unity INTERFACE unity::framework)
  target_compile_definitions(mtt_unity INTERFACE ${_mtt_unity_defs})
  set(MTT_UNITY_ORIGIN "installed package: ${unity_DIR}" CACHE INTERNAL "")
  message(STATUS "mtt: Unity from installed package unity::framework (${unity_DIR})")
  return()
endif()
# unity_internals.h is specific to ThrowTheSwitch's Unity (unity.h alone could
# be another project's header of that name).
find_path(MTT_UNITY_INCLUDE_DIR NAMES unity_internals.h PATH_SUFFIXES unity
          DOC "Include directory of an installed Unity (ThrowTheSwitch)")
if(MTT_UNITY_INCLUDE_DIR AND EXISTS "${MTT_UNITY_INCLUDE_DIR}/unity.h")
  # Take the library from the same prefix as the header only.
  get_filename_component(_upfx "${MTT_UNITY_INCLUDE_DIR}" DIRECTORY)
  if(MTT_UNITY_INCLUDE_DIR MATCHES "/unity$")
    get_filename_component(_upfx "${_upfx}" DIRECTORY)
  endif()
  find_library(MTT_UNITY_LIBRARY NAMES unity
               PATHS "${_upfx}"
               PATH_SUFFIXES lib lib64 "lib/${CMAKE_LIBRARY_ARCHITECTURE}"
               NO_DEFAULT_PATH
               DOC "Library of an installed Unity (ThrowTheSwitch)")
  if(MTT_UNITY_LIBRARY)
    add_library(mtt_unity STATIC IMPORTED GLOBAL)
    set_target_properties(mtt_unity PROPERTIES
      IMPORTED_LOCATION "${MTT_UNITY_LIBRARY}"
      INTERFACE_SYSTEM_INCLUDE_DIRECTORIES "${MTT_UNITY_INCLUDE_DIR}"
      INTERFACE_INCLUDE_DIRECTORIES "${MTT_UNITY_INCLUDE_DIR}"
      INTERFACE_COMPILE_DEFINITIONS "${_mtt_unity_defs}")
    set(MTT_UNITY_ORIGIN "installed library: ${MTT_UNITY_LIBRARY}" CACHE INTERNAL "")
    message(STATUS "mtt: Unity from installed library ${MTT_UNITY_LIBRARY}")
    return()
  endif()
endif()

# (c) .deps/unity from tools/ci/setup-unity.sh ----------------------------------
_mtt_unity_src_in("${mtt_SOURCE_DIR}/.deps/unity" _src)
if(_src)
  _mtt_unity_from_sources("${_src}" "tools/ci/setup-unity.sh")
  return()
endif()

# (d) download the upstream release -------------------------------------------
set(_mtt_unity_help
  "Unity (the C test framework) was not found.  Either\n"
  "  - run tools/ci/setup-unity.sh (as root: takes Unity from Debian's cjson source package into .deps/unity), or\n"
  "  - pass -DUNITY_SOURCE_DIR=<dir containing unity.c or src/unity.c>, or\n"
  "  - configure with -DMTT_BUILD_TESTS=OFF to build without tests.")
if(NOT MTT_FETCH_UNITY)
  message(FATAL_ERROR ${_mtt_unity_help}
    "\n(MTT_FETCH_UNITY is OFF, so no download was attempted.)")
endif()

set(_dl_dir "${CMAKE_BINARY_DIR}/_deps")
set(_tgz "${_dl_dir}/unity-upstream.tar.gz")
set(_xdir "${_dl_dir}/unity-src")

# unity.c in the extracted archive (its top folder is Unity-<version>/).
function(_mtt_unity_src_in_extracted out)
  set(_r "")
  file(GLOB _tops LIST_DIRECTORIES true "${_xdir}/*")
  foreach(_t IN LISTS _tops)
    _mtt_unity_src_in("${_t}" _r)
    if(_r)
      break()
    endif()
  endforeach()
  set(${out} "${_r}" PARENT_SCOPE)
endfunction()

_mtt_unity_src_in_extracted(_src)
if(_src)
  message(STATUS "mtt: using the Unity downloaded earlier to ${_xdir}")
else()
  # file(DOWNLOAD ... STATUS) rather than FetchContent: a failure comes back
  # to us (FetchContent stops with a cryptic sub-build error), and the
  # timeouts keep an offline machine from hanging.
  message(STATUS "mtt: Unity not found locally; downloading ${MTT_UNITY_URL} (timeout 20 s)")
  file(MAKE_DIRECTORY "${_dl_dir}")
  file(DOWNLOAD "${MTT_UNITY_URL}" "${_tgz}"
       TIMEOUT 20 INACTIVITY_TIMEOUT 10 STATUS _st TLS_VERIFY ON)
  list(GET _st 0 _code)
  list(GET _st 1 _msg)
  if(NOT _code EQUAL 0)
    file(REMOVE "${_tgz}")
    message(FATAL_ERROR ${_mtt_unity_help}
      "\n(MTT_FETCH_UNITY is ON, but the download of ${MTT_UNITY_URL} failed: ${_msg}.)")
  endif()
  if(MTT_UNITY_SHA256)
    file(SHA256 "${_tgz}" _sum)
    if(NOT _sum STREQUAL MTT_UNITY_SHA256)
      file(REMOVE "${_tgz}")
      message(FATAL_ERROR ${_mtt_unity_help}
        "\n(The download of ${MTT_UNITY_URL} has SHA-256 ${_sum}, expected ${MTT_UNITY_SHA256}.)")
    endif()
  endif()
  file(REMOVE_RECURSE "${_xdir}")
  file(ARCHIVE_EXTRACT INPUT "${_tgz}" DESTINATION "${_xdir}")
  file(REMOVE "${_tgz}")
  _mtt_unity_src_in_extracted(_src)
  if(NOT _src)
    message(FATAL_ERROR ${_mtt_unity_help}
      "\n(The archive ${MTT_UNITY_URL} holds no src/unity.c.)")
  endif()
endif()
_mtt_unity_from_sources("${_src}" "download of ${MTT_UNITY_URL}")

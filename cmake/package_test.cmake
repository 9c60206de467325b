# SPDX-License-Identifier: BSD-3-Clause
# cmake/package_test.cmake - the ctest package.consumer.
#
# 1. cmake --install <BUILD_DIR> --prefix <WORK_DIR>/prefix
# 2. configure, build and run test/consumer with -DCMAKE_PREFIX_PATH=<prefix>
#    (find_package(mtt CONFIG) + mtt::mtt); it must print "OK ... real=<EXPECT_REAL>"
# 3. if pkg-config is there: compile the same main.c with
#    `pkg-config --cflags --libs mtt` (PKG_CONFIG_PATH=<prefix>/<LIBDIR>/pkgconfig),
#    run it, and require the same output as 2.
cmake_minimum_required(VERSION 3.25)

foreach(_v BUILD_DIR CONSUMER_DIR WORK_DIR C_COMPILER LIBDIR)
  if(NOT ${_v})
    message(FATAL_ERROR "package_test.cmake: -D${_v}=... missing")
  endif()
endforeach()

function(run)
  cmake_parse_arguments(R "" "WHAT;OUT" "CMD" ${ARGN})
  string(REPLACE ";" " " _cmd "${R_CMD}")
  message("-- ${R_WHAT}: ${_cmd}")
  execute_process(COMMAND ${R_CMD} RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _out)
  if(NOT _rc EQUAL 0)
    message("${_out}")
    message(FATAL_ERROR "FAIL: ${R_WHAT} (exit ${_rc})")
  endif()
  if(R_OUT)
    set(${R_OUT} "${_out}" PARENT_SCOPE)
  endif()
endfunction()

set(_prefix "${WORK_DIR}/prefix")
set(_bdir "${WORK_DIR}/build")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

# 1. install
set(_cfg "")
if(CONFIG)
  set(_cfg --config "${CONFIG}")
endif()
run(WHAT "install" CMD "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${_prefix}" ${_cfg})
foreach(_f include/mtt/mtt.h include/mtt/config.h include/mtt/real.h
        ${LIBDIR}/cmake/mtt/mttConfig.cmake ${LIBDIR}/cmake/mtt/mttConfigVersion.cmake
        ${LIBDIR}/cmake/mtt/mttTargets.cmake ${LIBDIR}/pkgconfig/mtt.pc)
  if(NOT EXISTS "${_prefix}/${_f}")
    message(FATAL_ERROR "FAIL: the install lacks ${_f}")
  endif()
endforeach()

# 2. CMake consumer
set(_gen "")
if(GENERATOR)
  set(_gen -G "${GENERATOR}")
  if(MAKE_PROGRAM)
    list(APPEND _gen "-DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM}")
  endif()
endif()
set(_bt "${CONFIG}")
if(NOT _bt)
  set(_bt Release)
endif()
run(WHAT "configure consumer" CMD "${CMAKE_COMMAND}" -S "${CONSUMER_DIR}" -B "${_bdir}" ${_gen}
    "-DCMAKE_C_COMPILER=${C_COMPILER}" "-DCMAKE_BUILD_TYPE=${_bt}"
    "-DCMAKE_PREFIX_PATH=${_prefix}" -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON)
run(WHAT "build consumer" CMD "${CMAKE_COMMAND}" --build "${_bdir}" ${_cfg})
find_program(_exe mtt_consumer PATHS "${_bdir}" "${_bdir}/${_bt}" NO_DEFAULT_PATH NO_CACHE)
if(NOT _exe)
  message(FATAL_ERROR "FAIL: built consumer not found in ${_bdir}")
endif()
run(WHAT "run consumer (CMake)" CMD "${_exe}" OUT _cm_out)
string(STRIP "${_cm_out}" _cm_out)
message("   ${_cm_out}")
if(NOT _cm_out MATCHES "^OK ")
  message(FATAL_ERROR "FAIL: the consumer did not print OK")
endif()
if(EXPECT_REAL AND NOT _cm_out MATCHES " real=${EXPECT_REAL} ")
  message(FATAL_ERROR "FAIL: the consumer sees a mtt_real other than ${EXPECT_REAL}: "
                      "the package lost a compile definition")
endif()

# 3. pkg-config consumer
if(NOT PKG_CONFIG OR NOT EXISTS "${PKG_CONFIG}")
  message("-- pkg-config not found: pkg-config part skipped")
  message("OK: package consumer (CMake)")
  return()
endif()
set(ENV{PKG_CONFIG_PATH} "${_prefix}/${LIBDIR}/pkgconfig")
unset(ENV{PKG_CONFIG_LIBDIR})
run(WHAT "pkg-config" CMD "${PKG_CONFIG}" --cflags --libs mtt OUT _pc)
string(STRIP "${_pc}" _pc)
message("   ${_pc}")
separate_arguments(_pc_args UNIX_COMMAND "${_pc}")
set(_pexe "${WORK_DIR}/mtt_consumer_pkgconfig")
run(WHAT "compile consumer (pkg-config)"
    CMD "${C_COMPILER}" -std=c99 -o "${_pexe}" "${CONSUMER_DIR}/main.c" ${_pc_args})
run(WHAT "run consumer (pkg-config)" CMD "${_pexe}" OUT _pc_out)
string(STRIP "${_pc_out}" _pc_out)
message("   ${_pc_out}")
if(NOT _pc_out STREQUAL _cm_out)
  message(FATAL_ERROR "FAIL: the pkg-config build differs from the CMake build:\n"
                      "  cmake:      ${_cm_out}\n  pkg-config: ${_pc_out}")
endif()
message("OK: package consumer (CMake and pkg-config)")

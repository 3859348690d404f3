# SPDX-License-Identifier: Apache-2.0
# ======================================================================
# toolchain.cmake: the kit's toolchain choice, written once. Zephyr picks
# the compiler from ZEPHYR_TOOLCHAIN_VARIANT. When nothing is chosen (no
# ZEPHYR_TOOLCHAIN_VARIANT, no ZEPHYR_SDK_INSTALL_DIR), the kit's default is
# Debian's arm-none-eabi GCC through Zephyr's gnuarmemb variant, rooted
# where arm-none-eabi-gcc is found on PATH, with the toolchain's own picolibc
# (the only route to libstdc++ there). A Zephyr SDK is used instead whenever
# the user selects it.
#
#   include(): kit_toolchain() before find_package(Zephyr) (app/board.cmake)
#   cmake -P app/toolchain.cmake: the environment the default needs, as
#     NAME=value lines, nothing when a toolchain is chosen already, an error
#     when there is none. scripts/env.sh and scripts/setup.sh apply what it
#     prints; scripts/tests/test_one_rule.py holds kittools' copy
#     (kittools/workspace.py, environment) to it.
# ======================================================================
include_guard(GLOBAL)

# The default's variant and root (ZEPHYR_TOOLCHAIN_VARIANT,
# GNUARMEMB_TOOLCHAIN_PATH), or empty when a toolchain is chosen
function(kit_toolchain_default OUT_VARIANT OUT_ROOT)
    set(${OUT_VARIANT} "" PARENT_SCOPE)
    set(${OUT_ROOT} "" PARENT_SCOPE)
    if(ZEPHYR_TOOLCHAIN_VARIANT OR NOT "$ENV{ZEPHYR_TOOLCHAIN_VARIANT}" STREQUAL ""
       OR NOT "$ENV{ZEPHYR_SDK_INSTALL_DIR}" STREQUAL "")
        return()
    endif()
    find_program(KIT_ARM_GCC arm-none-eabi-gcc)
    if(NOT KIT_ARM_GCC)
        message(FATAL_ERROR
            "kit: no ARM toolchain. Install Debian's gcc-arm-none-eabi, picolibc-arm-none-eabi and "
            "libstdc++-arm-none-eabi-picolibc (scripts/setup.sh does), or set ZEPHYR_SDK_INSTALL_DIR "
            "to use a Zephyr SDK.")
    endif()
    # The installed compiler, not a link to it: its root holds its libraries
    get_filename_component(KIT_ARM_GCC_REAL "${KIT_ARM_GCC}" REALPATH)
    get_filename_component(KIT_ARM_GCC_BIN "${KIT_ARM_GCC_REAL}" DIRECTORY)
    get_filename_component(KIT_ARM_GCC_ROOT "${KIT_ARM_GCC_BIN}" DIRECTORY)
    set(${OUT_VARIANT} gnuarmemb PARENT_SCOPE)
    set(${OUT_ROOT} "${KIT_ARM_GCC_ROOT}" PARENT_SCOPE)
endfunction()

# The choice, for the build that includes this
macro(kit_toolchain)
    kit_toolchain_default(KIT_DEFAULT_VARIANT KIT_DEFAULT_ROOT)
    if(KIT_DEFAULT_VARIANT)
        set(ZEPHYR_TOOLCHAIN_VARIANT "${KIT_DEFAULT_VARIANT}" CACHE STRING "Zephyr toolchain variant")
        set(GNUARMEMB_TOOLCHAIN_PATH "${KIT_DEFAULT_ROOT}" CACHE PATH "arm-none-eabi toolchain root")
    endif()
    if(ZEPHYR_TOOLCHAIN_VARIANT STREQUAL "gnuarmemb" OR "$ENV{ZEPHYR_TOOLCHAIN_VARIANT}" STREQUAL "gnuarmemb")
        set(TOOLCHAIN_HAS_PICOLIBC ON CACHE BOOL "toolchain provides picolibc")
        # Kconfig reads this from the environment; without it picolibc's TLS
        # errno lands in an orphan .tbss section.
        set(ENV{ZEPHYR_TOOLCHAIN_SUPPORTS_THREAD_LOCAL_STORAGE} y)
    endif()
endmacro()

if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE)
    kit_toolchain_default(KIT_DEFAULT_VARIANT KIT_DEFAULT_ROOT)
    if(KIT_DEFAULT_VARIANT)
        execute_process(COMMAND "${CMAKE_COMMAND}" -E echo "ZEPHYR_TOOLCHAIN_VARIANT=${KIT_DEFAULT_VARIANT}")
        execute_process(COMMAND "${CMAKE_COMMAND}" -E echo "GNUARMEMB_TOOLCHAIN_PATH=${KIT_DEFAULT_ROOT}")
    endif()
endif()

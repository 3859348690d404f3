# SPDX-License-Identifier: Apache-2.0
# fprime_zephyr_setup(): F´'s own build system on top of Zephyr's, for an
# application that builds an F´ deployment into Zephyr's `app` target.
# Call it after the application's project() (F´'s sub-builds re-configure
# the application, and CMake insists on a literal project() there). Needs
# FPRIME_FRAMEWORK_PATH and, for the bridge, CMAKE_TOOLCHAIN_FILE set to
# fprime-zephyr's cmake/toolchain/zephyr.cmake before find_package(Zephyr).
include_guard(GLOBAL)

macro(fprime_zephyr_setup)
    if(NOT CONFIG_FPRIME)
        message(FATAL_ERROR "fprime_zephyr_setup(): CONFIG_FPRIME is off (modules/fprime/Kconfig)")
    endif()
    # The toolchain file's FPRIME_PLATFORM is set inside Zephyr's own
    # project() scope and does not reach the application.
    set(FPRIME_PLATFORM Zephyr)
    # F´'s settings loader replaces a defaulted install prefix with one next
    # to settings.ini; a normal variable counts as given and keeps F´'s
    # artifacts in the build folder.
    set(CMAKE_INSTALL_PREFIX "${CMAKE_BINARY_DIR}/build-artifacts")
    include("${FPRIME_FRAMEWORK_PATH}/cmake/FPrime.cmake")
    fprime_setup_included_code()
    # Build only what the deployment links: the framework and its libraries
    # register every module they have (the modules of modules/ add theirs to
    # FPRIME_ZEPHYR_NOT_IN_ALL: some do not compile against this Zephyr).
    get_property(FPRIME_ZEPHYR_NOT_IN_ALL GLOBAL PROPERTY FPRIME_ZEPHYR_NOT_IN_ALL)
    foreach(FPRIME_DIR IN ITEMS Fw Svc Os Drv CFDP Utils)
        list(APPEND FPRIME_ZEPHYR_NOT_IN_ALL "${FPRIME_FRAMEWORK_PATH}/${FPRIME_DIR}")
    endforeach()
    foreach(FPRIME_DIR IN LISTS FPRIME_ZEPHYR_NOT_IN_ALL)
        if(IS_DIRECTORY "${FPRIME_DIR}")
            set_property(DIRECTORY "${FPRIME_DIR}" PROPERTY EXCLUDE_FROM_ALL TRUE)
        endif()
    endforeach()
endmacro()

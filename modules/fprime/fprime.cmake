# SPDX-License-Identifier: Apache-2.0
# fprime_zephyr_setup(): F´'s own build system on top of Zephyr's, for an
# application that builds an F´ deployment into Zephyr's `app` target.
# Call it after the application's project() (F´'s sub-builds re-configure
# the application, and CMake insists on a literal project() there). Needs
# FPRIME_FRAMEWORK_PATH and, for the bridge, CMAKE_TOOLCHAIN_FILE set to
# fprime-zephyr's cmake/toolchain/zephyr.cmake before find_package(Zephyr);
# FPRIME_ZEPHYR_EXTRA_LOCATIONS, optional, adds module locations.
include_guard(GLOBAL)
set(FPRIME_ZEPHYR_MODULE_DIR "${CMAKE_CURRENT_LIST_DIR}")

# fprime-fpp's fpp-* commands are Python wrappers that start the native
# `fpp` binary beside them with the subcommand: calling the binary directly
# cuts each call from 120 to 69 ms (median of 10 runs here), and a configure runs about
# 120 fpp-depend calls before the build's own fpp-to-cpp ones. F´ uses a
# tool variable that is already set as it is: a two-line shell shim per tool
# in the build folder.
function(fprime_zephyr_native_fpp)
    find_program(FPRIME_FPP_WRAPPER fpp-depend)
    if(NOT FPRIME_FPP_WRAPPER)
        return()  # F´'s own check reports the missing tools
    endif()
    get_filename_component(FPP_BIN_DIR "${FPRIME_FPP_WRAPPER}" DIRECTORY)
    find_program(FPRIME_FPP_PYTHON NAMES python3 python HINTS "${FPP_BIN_DIR}" NO_DEFAULT_PATH)
    if(NOT FPRIME_FPP_PYTHON)
        return()
    endif()
    execute_process(COMMAND "${FPRIME_FPP_PYTHON}" -c "import fprime_fpp, os; print(os.path.dirname(fprime_fpp.__file__))"
        OUTPUT_VARIABLE FPP_PACKAGE OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE FPP_RESULT ERROR_QUIET)
    if(NOT FPP_RESULT EQUAL 0 OR NOT EXISTS "${FPP_PACKAGE}/fpp")
        return()  # the JAR variant, or another install: keep the wrappers
    endif()
    foreach(FPP_TOOL IN ITEMS depend to-cpp locate-defs to-dict)
        string(TOUPPER "FPP_${FPP_TOOL}" FPP_VARIABLE)
        string(REPLACE "-" "_" FPP_VARIABLE "${FPP_VARIABLE}")
        set(FPP_SHIM "${CMAKE_BINARY_DIR}/fpp-native/fpp-${FPP_TOOL}")
        file(WRITE "${FPP_SHIM}" "#!/bin/sh\nexec \"${FPP_PACKAGE}/fpp\" ${FPP_TOOL} \"$@\"\n")
        file(CHMOD "${FPP_SHIM}" PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE
             WORLD_READ WORLD_EXECUTE)
        set(${FPP_VARIABLE} "${FPP_SHIM}" PARENT_SCOPE)
    endforeach()
endfunction()

# An upstream the kit patches (modules/<project>/patches/*.patch, applied by
# scripts/setup.sh after west update) must carry every patch: refuse a
# workspace where one is missing rather than build the unfixed code.
function(fprime_zephyr_require_patches UPSTREAM_PATH PATCH_DIR)
    file(GLOB PATCHES "${PATCH_DIR}/*.patch")
    foreach(PATCH IN LISTS PATCHES)
        execute_process(COMMAND git -C "${UPSTREAM_PATH}" apply --reverse --check "${PATCH}"
            RESULT_VARIABLE PATCH_MISSING OUTPUT_QUIET ERROR_QUIET)
        if(PATCH_MISSING)
            message(FATAL_ERROR "kit: ${UPSTREAM_PATH} lacks the kit's patch ${PATCH}.\n"
                "Run scripts/setup.sh (it applies the patches after west update).")
        endif()
    endforeach()
endfunction()

# F´ writes a configuration file it supplies into the build folder, then the
# kit's override over it, on every configure (nasa/fprime#4676, fixed upstream
# after the kit's pin): the content ends as it was, but its time moves, and
# ninja regenerates and recompiles all that includes it (PlatformTypes.fpp,
# AcConstants.fpp: 360 steps and a relink on a warm build that changed
# nothing). At the end of each configure, a configuration file whose content
# is what it was at the end of the last one gets that configure's time back,
# from a copy kept beside it (file(COPY) keeps times). A changed file keeps
# its new time and becomes the copy.
function(fprime_zephyr_keep_config_times)
    set(KEPT_ROOT "${CMAKE_BINARY_DIR}/fprime-config-kept")
    get_property(CONFIG_MODULES GLOBAL PROPERTY FPRIME_CONFIG_MODULES)
    foreach(CONFIG_MODULE IN LISTS CONFIG_MODULES)
        foreach(SUPPLIED IN ITEMS SUPPLIED_SOURCES SUPPLIED_HEADERS SUPPLIED_AUTOCODER_INPUTS)
            get_target_property(CONFIG_FILES ${CONFIG_MODULE} ${SUPPLIED})
            foreach(CONFIG_FILE IN LISTS CONFIG_FILES)
                cmake_path(IS_PREFIX CMAKE_BINARY_DIR "${CONFIG_FILE}" NORMALIZE IN_BUILD)
                if(NOT IN_BUILD OR NOT EXISTS "${CONFIG_FILE}")
                    continue()
                endif()
                cmake_path(RELATIVE_PATH CONFIG_FILE BASE_DIRECTORY "${CMAKE_BINARY_DIR}" OUTPUT_VARIABLE RELATIVE)
                set(KEPT "${KEPT_ROOT}/${RELATIVE}")
                get_filename_component(CONFIG_DIR "${CONFIG_FILE}" DIRECTORY)
                get_filename_component(KEPT_DIR "${KEPT}" DIRECTORY)
                if(EXISTS "${KEPT}")
                    file(SHA256 "${CONFIG_FILE}" NOW)
                    file(SHA256 "${KEPT}" BEFORE)
                    if(NOW STREQUAL BEFORE)
                        file(COPY "${KEPT}" DESTINATION "${CONFIG_DIR}")
                        continue()
                    endif()
                endif()
                file(COPY "${CONFIG_FILE}" DESTINATION "${KEPT_DIR}")
            endforeach()
        endforeach()
    endforeach()
endfunction()

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
    fprime_zephyr_native_fpp()
    include("${FPRIME_FRAMEWORK_PATH}/cmake/FPrime.cmake")
    # Module locations beyond settings.ini's (FPRIME_ZEPHYR_EXTRA_LOCATIONS):
    # another F´ project whose modules the application builds, named from
    # its own root as in that project (its includes:
    # fprime_zephyr_location_includes). They are not library locations: F´
    # would warn that one has no library.cmake and skip it.
    # F´ names a file from the first location that holds it, and fails when a
    # later one gives it a name that is not a tail of that one: a location
    # nested in another (a project inside the application's repository) goes
    # before the one that holds it, any other after them all.
    foreach(FPRIME_ZEPHYR_LOCATION IN LISTS FPRIME_ZEPHYR_EXTRA_LOCATIONS)
        set(FPRIME_ZEPHYR_AT -1)
        set(FPRIME_ZEPHYR_INDEX 0)
        foreach(FPRIME_ZEPHYR_KNOWN IN LISTS FPRIME_BUILD_LOCATIONS)
            cmake_path(IS_PREFIX FPRIME_ZEPHYR_KNOWN "${FPRIME_ZEPHYR_LOCATION}" NORMALIZE FPRIME_ZEPHYR_HOLDS)
            if(FPRIME_ZEPHYR_HOLDS AND FPRIME_ZEPHYR_AT EQUAL -1)
                set(FPRIME_ZEPHYR_AT ${FPRIME_ZEPHYR_INDEX})
            endif()
            math(EXPR FPRIME_ZEPHYR_INDEX "${FPRIME_ZEPHYR_INDEX} + 1")
        endforeach()
        if(FPRIME_ZEPHYR_AT EQUAL -1)
            list(APPEND FPRIME_BUILD_LOCATIONS "${FPRIME_ZEPHYR_LOCATION}")
        else()
            list(INSERT FPRIME_BUILD_LOCATIONS ${FPRIME_ZEPHYR_AT} "${FPRIME_ZEPHYR_LOCATION}")
        endif()
    endforeach()
    fprime_setup_included_code()
    # F´'s CRC-32 from a table in flash, not one built in RAM (crc32_libcrc.c
    # says why): this file in place of libcrc's in F´'s Utils_Hash
    if(CONFIG_FPRIME_CRC32_IN_FLASH AND TARGET Utils_Hash)
        get_target_property(FPRIME_ZEPHYR_HASH_SOURCES Utils_Hash SOURCES)
        list(FILTER FPRIME_ZEPHYR_HASH_SOURCES EXCLUDE REGEX "/libcrc/lib_crc\\.c$")
        set_property(TARGET Utils_Hash PROPERTY SOURCES ${FPRIME_ZEPHYR_HASH_SOURCES}
                     "${FPRIME_ZEPHYR_MODULE_DIR}/crc32_libcrc.c")
    endif()
    # After every module of the application has registered its configuration
    cmake_language(DEFER DIRECTORY "${CMAKE_SOURCE_DIR}" CALL fprime_zephyr_keep_config_times)
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

# The include root of an extra module location (FPRIME_ZEPHYR_EXTRA_LOCATIONS)
# for the targets its folder DIR registered, at any depth, and for what
# links them (PUBLIC): "<deployment>/Top/..." as the project writes it. Not
# for every target: a location outside the application's tree would put its
# absolute path on every compile line, and ccache, which keys on the command
# line, would miss on every F´ object of every new scratch folder.
function(fprime_zephyr_location_includes DIR LOCATION)
    set(FPRIME_ZEPHYR_DIRS "${DIR}")
    # Bounded: each folder is taken once, and the folder tree is finite
    while(FPRIME_ZEPHYR_DIRS)
        list(POP_FRONT FPRIME_ZEPHYR_DIRS FPRIME_ZEPHYR_DIR)
        get_property(FPRIME_ZEPHYR_TARGETS DIRECTORY "${FPRIME_ZEPHYR_DIR}" PROPERTY BUILDSYSTEM_TARGETS)
        foreach(FPRIME_ZEPHYR_TARGET IN LISTS FPRIME_ZEPHYR_TARGETS)
            get_target_property(FPRIME_ZEPHYR_TYPE "${FPRIME_ZEPHYR_TARGET}" TYPE)
            if(FPRIME_ZEPHYR_TYPE STREQUAL "INTERFACE_LIBRARY")
                target_include_directories("${FPRIME_ZEPHYR_TARGET}" INTERFACE "${LOCATION}")
            elseif(NOT FPRIME_ZEPHYR_TYPE STREQUAL "UTILITY")
                target_include_directories("${FPRIME_ZEPHYR_TARGET}" PUBLIC "${LOCATION}")
            endif()
        endforeach()
        get_property(FPRIME_ZEPHYR_SUBDIRS DIRECTORY "${FPRIME_ZEPHYR_DIR}" PROPERTY SUBDIRECTORIES)
        list(APPEND FPRIME_ZEPHYR_DIRS ${FPRIME_ZEPHYR_SUBDIRS})
    endwhile()
endfunction()

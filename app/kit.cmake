# SPDX-License-Identifier: Apache-2.0
# ======================================================================
# kit.cmake: what the kit's Zephyr applications (app/ and tests/*) do
# around find_package(Zephyr). Before it: check the workspace and the
# board, pick the board's configuration and the toolchain, register the
# F´ modules (modules/). After the application's project(): the
# deployment, with the execution model Kconfig chose (CONFIG_KIT_MODEL_*).
#
#   include(../app/kit.cmake)  # checks, modules, then find_package(Zephyr)
#   project(...)
#   kit_deployment()           # F´, the shared deployment and the model
# ======================================================================
include_guard(GLOBAL)

get_filename_component(KIT_ROOT "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
# The west workspace's upstreams (paths in west.yml)
set(KIT_DEPS "${KIT_ROOT}/deps")
set(FPRIME_FRAMEWORK_PATH "${KIT_DEPS}/fprime" CACHE PATH "F´ (nasa/fprime)")
set(FPRIME_ZEPHYR_PATH "${KIT_DEPS}/fprime-zephyr" CACHE PATH "fprime-zephyr")
set(FPRIME_BAREMETAL_PATH "${KIT_DEPS}/fprime-baremetal" CACHE PATH "fprime-baremetal")

# --- The deployment ----------------------------------------------------
# The F´ deployment the kit measures: the reference one (app/) unless the
# build names another folder with the same seam (docs/your-deployment.md):
#   west build -b qemu_cortex_m3 app -- -DKIT_DEPLOYMENT_DIR=<folder>
set(KIT_DEPLOYMENT_DIR "${KIT_ROOT}/app" CACHE PATH "The F´ deployment the kit builds and measures")
include("${CMAKE_CURRENT_LIST_DIR}/deployment.cmake")
kit_check_deployment("${KIT_DEPLOYMENT_DIR}")
# Where its modules are named from: the kit's repository, or the team's own
# F´ project for a folder outside it, which F´ then builds modules in too
kit_deployment_location(KIT_DEPLOYMENT_LOCATION "${KIT_DEPLOYMENT_DIR}")
# ... kept in the cache, where the kit's tools read it (kittools.deployment)
set(KIT_DEPLOYMENT_LOCATION "${KIT_DEPLOYMENT_LOCATION}" CACHE INTERNAL "The F´ project the deployment is named from")
if(NOT KIT_DEPLOYMENT_LOCATION STREQUAL KIT_ROOT)
    set(FPRIME_ZEPHYR_EXTRA_LOCATIONS "${KIT_DEPLOYMENT_LOCATION}")
endif()

# --- Workspace, board and toolchain (app/board.cmake, shared with tests/floor)
include("${CMAKE_CURRENT_LIST_DIR}/board.cmake")
kit_require_workspace("${FPRIME_FRAMEWORK_PATH}/cmake/FPrime.cmake"
    "${FPRIME_ZEPHYR_PATH}/cmake/toolchain/zephyr.cmake" "${FPRIME_BAREMETAL_PATH}/library.cmake")

# --- Configuration ----------------------------------------------------
# Kit-wide settings, then the board's; the execution model and the scenario
# are Kconfig choices (app/Kconfig), and the board's defaults per model are
# its Kconfig.defconfig, sourced by app/Kconfig through this generated file.
if(NOT DEFINED CONF_FILE)
    set(CONF_FILE "${KIT_ROOT}/app/prj.conf" "${KIT_BOARD_DIR}/kit.conf")
    # ... and the deployment's own choices, where it makes any (the services
    # it has: docs/your-deployment.md)
    if(EXISTS "${KIT_DEPLOYMENT_DIR}/deployment.conf")
        list(APPEND CONF_FILE "${KIT_DEPLOYMENT_DIR}/deployment.conf")
    endif()
endif()
if(NOT DTC_OVERLAY_FILE)
    set(DTC_OVERLAY_FILE "${KIT_BOARD_DIR}/app.overlay")
endif()
set(KCONFIG_ROOT "${KIT_ROOT}/app/Kconfig")

# --- The ground link under QEMU ----------------------------------------
# The board's link UART (its app.overlay) is QEMU's second serial port: a
# Unix socket QEMU listens on, without waiting (bytes are dropped while no
# ground station is connected). The path is per build folder, so parallel
# runs (twister) never share one, and short, since a socket path is limited
# to 107 bytes. `kit gds` and the integration suite read it from the cache.
string(MD5 KIT_LINK_HASH "${CMAKE_BINARY_DIR}")
string(SUBSTRING "${KIT_LINK_HASH}" 0 12 KIT_LINK_HASH)
set(KIT_LINK_SOCKET "/tmp/kit-link-${KIT_LINK_HASH}.sock" CACHE STRING
    "Unix socket of the ground link's UART under QEMU")
string(LENGTH "${KIT_LINK_SOCKET}" KIT_LINK_SOCKET_LENGTH)
if(KIT_LINK_SOCKET_LENGTH GREATER 107)
    message(FATAL_ERROR "kit: KIT_LINK_SOCKET is ${KIT_LINK_SOCKET_LENGTH} bytes long; a Unix socket path "
        "holds at most 107. Choose a shorter one.")
endif()
list(APPEND QEMU_EXTRA_FLAGS
    -chardev "socket,id=kitlink,path=${KIT_LINK_SOCKET},server=on,wait=off" -serial chardev:kitlink)
file(MAKE_DIRECTORY "${CMAKE_BINARY_DIR}/Kconfig")
file(CONFIGURE OUTPUT "${CMAKE_BINARY_DIR}/Kconfig/Kconfig.kit_board"
    CONTENT "source \"${KIT_BOARD_DIR}/Kconfig.defconfig\"\n")
if(DEFINED KIT_VARIANT)
    message(FATAL_ERROR "kit: KIT_VARIANT is gone: the execution model is a Kconfig choice. Use "
        "-DCONFIG_KIT_MODEL_${KIT_VARIANT}=y (upper case) or west build -T app/kit.<model>.")
endif()

# --- Zephyr, with F´ as modules --------------------------------------
# fprime-zephyr's toolchain file only names the platform and supplies
# register_fprime_zephyr_deployment; Zephyr itself picks the compiler.
if(NOT DEFINED CMAKE_TOOLCHAIN_FILE)
    set(CMAKE_TOOLCHAIN_FILE "${FPRIME_ZEPHYR_PATH}/cmake/toolchain/zephyr.cmake")
endif()
list(APPEND ZEPHYR_EXTRA_MODULES
    "${KIT_ROOT}/modules/fprime" "${KIT_ROOT}/modules/fprime-zephyr" "${KIT_ROOT}/modules/fprime-baremetal"
    "${KIT_ROOT}/modules/qemu")
include("${KIT_ROOT}/modules/fprime/fprime.cmake")

# F´'s sub-build (it re-configures the application only to compute FPP
# locations, dependencies and module information) needs F´'s modules, not
# Zephyr: it takes the main build's resulting configuration instead of
# configuring Zephyr a second time (about a third of a configure's time),
# and a stand-in for Zephyr's `app` target that nothing builds.
if(DEFINED FPRIME_SUB_BUILD_TARGETS)
    set(KIT_SUB_BUILD ON)
    # It inherits the cross compiler, which cannot link a host program
    set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
    file(STRINGS "${FPRIME_BINARY_DIR}/zephyr/.config" KIT_MAIN_CONFIG REGEX "^CONFIG_[A-Za-z0-9_]+=")
    foreach(KIT_SETTING IN LISTS KIT_MAIN_CONFIG)
        string(REGEX MATCH "^(CONFIG_[A-Za-z0-9_]+)=\"?([^\"]*)\"?$" KIT_MATCHED "${KIT_SETTING}")
        set(${CMAKE_MATCH_1} "${CMAKE_MATCH_2}")
    endforeach()
else()
    set(KIT_SUB_BUILD OFF)
    find_package(Zephyr REQUIRED HINTS "${KIT_DEPS}/zephyr")
endif()
# F´'s text loggers: none on a 64 KiB target, unless the deployment imports
# F´'s CdhCore, which F´ builds only with them (its deployment.conf says so:
# CONFIG_KIT_FPRIME_TEXT_LOGGERS). F´ reads the setting when its modules are
# set up (kit_deployment, below), after Kconfig.
if(CONFIG_KIT_FPRIME_TEXT_LOGGERS)
    set(KIT_TEXT_LOGGERS ON)
else()
    set(KIT_TEXT_LOGGERS OFF)
endif()
set(FPRIME_ENABLE_TEXT_LOGGERS ${KIT_TEXT_LOGGERS} CACHE BOOL "F´'s text loggers (CONFIG_KIT_FPRIME_TEXT_LOGGERS)" FORCE)

# After the application's literal project() call
macro(kit_deployment)
    if(KIT_SUB_BUILD)
        add_library(app STATIC EXCLUDE_FROM_ALL "${FPRIME_ZEPHYR_PATH}/cmake/toolchain/empty.cpp")
    endif()
    fprime_zephyr_setup()

    # The deployment (KIT_DEPLOYMENT_DIR): its F´ configuration, the kit's
    # components and subtopologies (the instruments, the ground link), which
    # its topology imports, then its own components and its topology
    add_fprime_subdirectory("${KIT_DEPLOYMENT_DIR}/config")
    # The kit's components, the same in any deployment: the instruments',
    # health's ping probe, the ground link's health and the fatal handler
    # that reports a halt
    foreach(KIT_COMPONENT IN ITEMS Timing Uplink Downlink LinkHealth FatalHandler Load Faults PingProbe)
        add_fprime_subdirectory("${KIT_ROOT}/app/Components/${KIT_COMPONENT}")
    endforeach()
    # The kit's telemetry store, where the build chose it (app/Top/telemetry/)
    if(CONFIG_KIT_TELEMETRY_TABLE)
        add_fprime_subdirectory("${KIT_ROOT}/app/Components/TlmTable")
    endif()
    add_fprime_subdirectory("${KIT_ROOT}/app/Subtopologies/Instruments")
    add_fprime_subdirectory("${KIT_ROOT}/app/Subtopologies/GroundLink")
    add_fprime_subdirectory("${KIT_DEPLOYMENT_DIR}/Components")
    add_fprime_subdirectory("${KIT_DEPLOYMENT_DIR}/Top")
    # A deployment in its own F´ project: its includes from that project's root
    if(FPRIME_ZEPHYR_EXTRA_LOCATIONS)
        foreach(KIT_PART IN ITEMS config Components Top)
            fprime_zephyr_location_includes("${KIT_DEPLOYMENT_DIR}/${KIT_PART}" "${KIT_DEPLOYMENT_LOCATION}")
        endforeach()
    endif()

    # The execution model (CONFIG_KIT_MODEL_*): its folder's model.cmake
    # registers its config and OS layer and sets KIT_MODEL_SOURCES,
    # KIT_MODEL_IMPLEMENTATIONS and KIT_MODEL_FILE_IMPLEMENTATION.
    set(KIT_MODEL_DIR "${KIT_ROOT}/${CONFIG_KIT_MODEL_NAME}")
    include("${KIT_MODEL_DIR}/model.cmake")

    # F´'s file system, the same in every model: fprime-baremetal's MicroFs
    # in RAM (app/src/RamFs.cpp), or none. Each model names its Os::File
    # over it: as it is where one context runs (baremetal), behind a lock
    # where tasks preempt one another (rtos/Os/LockedFile.hpp).
    if(NOT KIT_MODEL_FILE_IMPLEMENTATION)
        message(FATAL_ERROR "${KIT_MODEL_DIR}/model.cmake sets no KIT_MODEL_FILE_IMPLEMENTATION: name the "
                            "model's Os::File over the RAM file system (baremetal/model.cmake, rtos/model.cmake)")
    endif()
    if(CONFIG_KIT_RAMFS)
        set(KIT_FILE_IMPLEMENTATION ${KIT_MODEL_FILE_IMPLEMENTATION})
    else()
        set(KIT_FILE_IMPLEMENTATION Os_File_Stub)
    endif()

    # The deployment's topology module, as F´ names it from its folder
    get_module_name("${KIT_DEPLOYMENT_DIR}/Top")
    set(KIT_TOPOLOGY_MODULE "${MODULE_NAME}")

    # Every scenario, and the choice among them (app/scenarios/Scenarios.cpp)
    file(GLOB KIT_SCENARIO_SOURCES CONFIGURE_DEPENDS "${KIT_ROOT}/app/scenarios/*.cpp")

    register_fprime_zephyr_deployment(kit_${CONFIG_KIT_MODEL_NAME}
        SOURCES
            "${KIT_ROOT}/app/src/main.cpp"
            "${KIT_ROOT}/app/src/Session.cpp"
            "${KIT_ROOT}/app/src/Report.cpp"
            "${KIT_ROOT}/app/src/Fatal.cpp"
            "${KIT_ROOT}/app/src/TickClock.cpp"
            "${KIT_ROOT}/app/src/Stages.cpp"
            ${KIT_SCENARIO_SOURCES}
            "${KIT_ROOT}/app/src/CountingAllocator.cpp"
            "${KIT_ROOT}/app/src/HeapMonitor.cpp"
            "${KIT_ROOT}/app/src/RamFs.cpp"
            "${KIT_ROOT}/app/src/Restart.cpp"
            "${KIT_ROOT}/app/src/Deployment.cpp"
            "${KIT_ROOT}/app/Subtopologies/GroundLink/GroundLink.cpp"
            ${KIT_MODEL_SOURCES}
        DEPENDS
            ${KIT_TOPOLOGY_MODULE}
        CHOOSES_IMPLEMENTATIONS
            ${KIT_FILE_IMPLEMENTATION}
            ${KIT_MODEL_IMPLEMENTATIONS}
    )
    target_include_directories(app PRIVATE "${KIT_ROOT}")
    # The kit's code reaches the deployment's topology as "Top/...": its
    # headers, and those F´ generates for it (FppConstantsAc.hpp: under the
    # build folder, at the deployment's path in the F´ project)
    file(RELATIVE_PATH KIT_DEPLOYMENT_PATH "${KIT_DEPLOYMENT_LOCATION}" "${KIT_DEPLOYMENT_DIR}")
    target_include_directories(app PRIVATE "${KIT_DEPLOYMENT_DIR}" "${CMAKE_BINARY_DIR}/${KIT_DEPLOYMENT_PATH}")
    if(NOT KIT_SUB_BUILD)
        kit_zephyr_link()
    endif()
endmacro()

# What only the main build links
macro(kit_zephyr_link)
    # Every C heap allocation goes through app/src/HeapMonitor.cpp
    foreach(KIT_HEAP_FUNCTION IN ITEMS malloc calloc realloc aligned_alloc memalign free)
        zephyr_ld_options("-Wl,--wrap=${KIT_HEAP_FUNCTION}")
    endforeach()
    include("${KIT_ROOT}/app/provenance.cmake")

    # What the firmware must know of the topology's dictionary (F´ lists it
    # on the topology module): its id for the LINK line, and its counts for
    # the fixed tables' compile-time checks (app/dictionary_header.cmake)
    set(KIT_DICTIONARY_HEADER "${CMAKE_BINARY_DIR}/kit/KitDictionary.hpp")
    add_custom_command(OUTPUT "${KIT_DICTIONARY_HEADER}"
        COMMAND "${CMAKE_COMMAND}" "-DDICTIONARY=$<TARGET_PROPERTY:${KIT_TOPOLOGY_MODULE},FPRIME_DICTIONARIES>"
            "-DOUTPUT=${KIT_DICTIONARY_HEADER}" -P "${KIT_ROOT}/app/dictionary_header.cmake"
        DEPENDS "$<TARGET_PROPERTY:${KIT_TOPOLOGY_MODULE},FPRIME_DICTIONARIES>" "${KIT_ROOT}/app/dictionary_header.cmake"
        COMMENT "Reading the F´ dictionary's id and counts")
    target_sources(app PRIVATE "${KIT_DICTIONARY_HEADER}" "${KIT_ROOT}/app/src/DictionaryChecks.cpp")
    target_include_directories(app PRIVATE "${CMAKE_BINARY_DIR}/kit")

    # The instruments' string constants (Kit.RamFs, the RAM file system's
    # names, in every deployment's dictionary: Instruments.fpp). F´ makes
    # their definitions in the subtopology's FppConstantsAc.cpp and, the
    # subtopology being an interface, compiles it nowhere; a setup that
    # names a file from them (the reference's parameter database) needs it.
    get_module_name("${KIT_ROOT}/app/Subtopologies/Instruments")
    get_target_property(KIT_INSTRUMENTS_DIR "${MODULE_NAME}" BINARY_DIR)
    set(KIT_INSTRUMENTS_CONSTANTS "${KIT_INSTRUMENTS_DIR}/FppConstantsAc.cpp")
    set_source_files_properties("${KIT_INSTRUMENTS_CONSTANTS}" PROPERTIES GENERATED TRUE)
    target_sources(app PRIVATE "${KIT_INSTRUMENTS_CONSTANTS}")
    add_dependencies(app "${MODULE_NAME}")
endmacro()

# ======================================================================
# kit.cmake: the build of the kit's Zephyr application, shared by app/ and
# the twister test applications in tests/. It checks its inputs (workspace,
# variant, board, toolchain) before anything is configured, then sets up
# Zephyr, then F´ on top of it with the variant's OS layer.
#
# Use (see app/CMakeLists.txt):
#   include(kit.cmake)   # checks, then find_package(Zephyr)
#   project(...)
#   kit_deployment()     # F´, the shared deployment and the variant
# ======================================================================
include_guard(GLOBAL)

get_filename_component(KIT_ROOT "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
set(KIT_DEPS "${KIT_ROOT}/deps")

# --- Workspace --------------------------------------------------------
foreach(KIT_UPSTREAM IN ITEMS zephyr fprime fprime-zephyr fprime-baremetal)
    if(NOT EXISTS "${KIT_DEPS}/${KIT_UPSTREAM}/CMakeLists.txt" AND NOT EXISTS "${KIT_DEPS}/${KIT_UPSTREAM}/library.cmake"
       AND NOT EXISTS "${KIT_DEPS}/${KIT_UPSTREAM}/${KIT_UPSTREAM}.cmake")
        message(FATAL_ERROR
            "kit: the west workspace is not provisioned: '${KIT_UPSTREAM}' is missing from deps/.\n"
            "Run scripts/setup.sh (it installs the tools and runs 'west update').")
    endif()
endforeach()

# --- Variant ----------------------------------------------------------
set(KIT_VARIANTS baremetal rtos)
if(NOT DEFINED KIT_VARIANT OR KIT_VARIANT STREQUAL "")
    message(FATAL_ERROR
        "kit: no variant chosen. Build one of them with\n"
        "  west build -b qemu_cortex_m3 -T app/kit.baremetal\n"
        "  west build -b qemu_cortex_m3 -T app/kit.rtos\n"
        "or pass -DKIT_VARIANT=baremetal|rtos.")
endif()
if(NOT KIT_VARIANT IN_LIST KIT_VARIANTS)
    message(FATAL_ERROR "kit: unknown variant '${KIT_VARIANT}'; the variants are: ${KIT_VARIANTS}.")
endif()
set(KIT_VARIANT_DIR "${KIT_ROOT}/${KIT_VARIANT}")

# --- Board ------------------------------------------------------------
# Every board the kit runs on has a folder in boards/ (see docs/porting.md).
# Zephyr splits "mps2/an385" into BOARD ("mps2") and BOARD_QUALIFIERS, and
# F´'s sub-builds inherit the split BOARD: they read the target from the
# cache entry the main configuration leaves (KIT_BOARD_TARGET) instead.
if(DEFINED FPRIME_SUB_BUILD_TARGETS AND DEFINED KIT_BOARD_TARGET)
    set(KIT_BOARD_SPEC "${KIT_BOARD_TARGET}")
elseif(DEFINED BOARD)
    set(KIT_BOARD_SPEC "${BOARD}")
elseif(DEFINED ENV{BOARD})
    set(KIT_BOARD_SPEC "$ENV{BOARD}")
endif()
# The folder is the board target with '/' as '_' (mps2/an385: mps2_an385);
# a folder named after the board alone covers all its qualifiers
# (qemu_cortex_m3/ti_lm3s6965: qemu_cortex_m3). scripts/kittools/workspace.py
# applies the same rule.
if(DEFINED KIT_BOARD_SPEC)
    string(REPLACE "/" "_" KIT_BOARD "${KIT_BOARD_SPEC}")
    if(NOT IS_DIRECTORY "${KIT_ROOT}/boards/${KIT_BOARD}")
        string(REGEX REPLACE "/.*$" "" KIT_BOARD "${KIT_BOARD_SPEC}")
    endif()
    if(NOT IS_DIRECTORY "${KIT_ROOT}/boards/${KIT_BOARD}")
        file(GLOB KIT_PORTED_BOARDS RELATIVE "${KIT_ROOT}/boards" "${KIT_ROOT}/boards/*")
        list(FILTER KIT_PORTED_BOARDS EXCLUDE REGEX "\\.")
        message(FATAL_ERROR
            "kit: board '${KIT_BOARD_SPEC}' has no kit port. Ported boards: ${KIT_PORTED_BOARDS}.\n"
            "To bring the kit to a new board: west kit new-board <board>, then docs/porting.md.")
    endif()
    set(KIT_BOARD_DIR "${KIT_ROOT}/boards/${KIT_BOARD}")
    set(KIT_BOARD_TARGET "${KIT_BOARD_SPEC}" CACHE STRING "Board target of this kit build" FORCE)
    foreach(KIT_BOARD_FILE IN ITEMS kit.conf baremetal.conf rtos.conf Tables.fpp)
        if(NOT EXISTS "${KIT_BOARD_DIR}/${KIT_BOARD_FILE}")
            message(FATAL_ERROR "kit: boards/${KIT_BOARD}/${KIT_BOARD_FILE} is missing; every port has one "
                "(see docs/porting.md).")
        endif()
    endforeach()
else()
    message(FATAL_ERROR "kit: no board given. Use west build -b qemu_cortex_m3 ...")
endif()

# --- Configuration fragments -----------------------------------------
# Kit-wide settings, then the variant's, then the board's (both variants',
# then this variant's: stack sizes).
if(NOT DEFINED CONF_FILE)
    set(CONF_FILE "${KIT_ROOT}/app/prj.conf" "${KIT_VARIANT_DIR}/variant.conf" "${KIT_BOARD_DIR}/kit.conf"
        "${KIT_BOARD_DIR}/${KIT_VARIANT}.conf")
endif()
if(EXISTS "${KIT_BOARD_DIR}/app.overlay" AND NOT DEFINED DTC_OVERLAY_FILE)
    set(DTC_OVERLAY_FILE "${KIT_BOARD_DIR}/app.overlay")
endif()
set(KCONFIG_ROOT "${KIT_ROOT}/app/Kconfig")

# --- Toolchain --------------------------------------------------------
# Default: Debian's arm-none-eabi GCC through Zephyr's gnuarmemb variant, with
# the toolchain's own picolibc (the only route to libstdc++ there). A Zephyr
# SDK is used instead whenever the user selects it.
if(NOT DEFINED ZEPHYR_TOOLCHAIN_VARIANT AND NOT DEFINED ENV{ZEPHYR_TOOLCHAIN_VARIANT}
   AND NOT DEFINED ENV{ZEPHYR_SDK_INSTALL_DIR})
    find_program(KIT_ARM_GCC arm-none-eabi-gcc)
    if(NOT KIT_ARM_GCC)
        message(FATAL_ERROR
            "kit: no ARM toolchain. Install Debian's gcc-arm-none-eabi, picolibc-arm-none-eabi and "
            "libstdc++-arm-none-eabi-picolibc (scripts/setup.sh does), or set ZEPHYR_SDK_INSTALL_DIR "
            "to use a Zephyr SDK.")
    endif()
    get_filename_component(KIT_ARM_GCC_BIN "${KIT_ARM_GCC}" DIRECTORY)
    get_filename_component(KIT_ARM_GCC_ROOT "${KIT_ARM_GCC_BIN}" DIRECTORY)
    set(ZEPHYR_TOOLCHAIN_VARIANT gnuarmemb CACHE STRING "Zephyr toolchain variant")
    set(GNUARMEMB_TOOLCHAIN_PATH "${KIT_ARM_GCC_ROOT}" CACHE PATH "arm-none-eabi toolchain root")
endif()
if(ZEPHYR_TOOLCHAIN_VARIANT STREQUAL "gnuarmemb" OR "$ENV{ZEPHYR_TOOLCHAIN_VARIANT}" STREQUAL "gnuarmemb")
    set(TOOLCHAIN_HAS_PICOLIBC ON CACHE BOOL "toolchain provides picolibc")
    # Kconfig reads this from the environment; without it picolibc's TLS errno
    # lands in an orphan .tbss section.
    set(ENV{ZEPHYR_TOOLCHAIN_SUPPORTS_THREAD_LOCAL_STORAGE} y)
endif()

# --- Zephyr, then F´ --------------------------------------------------
# fprime-zephyr's toolchain file only names the platform and supplies
# register_fprime_zephyr_deployment; Zephyr itself picks the compiler.
if(NOT DEFINED CMAKE_TOOLCHAIN_FILE)
    set(CMAKE_TOOLCHAIN_FILE "${KIT_DEPS}/fprime-zephyr/cmake/toolchain/zephyr.cmake")
endif()
set(FPRIME_ENABLE_TEXT_LOGGERS OFF CACHE BOOL "no text logging on a 64 KiB target")

find_package(Zephyr REQUIRED HINTS "${KIT_DEPS}/zephyr")

# Everything below runs after the application's literal project() call (F´'s
# sub-builds re-configure the application and CMake insists on seeing it).
macro(kit_deployment)

# FpConfig.h knobs (#ifndef-guarded): drop what costs RAM/ROM and serves a
# ground system or a debugger the kit does not have. Asserts report the file's
# path relative to its F´ project or library and the line: short, and enough
# to find it.
zephyr_compile_definitions(
    FW_ASSERT_LEVEL=FW_RELATIVE_PATH_ASSERT
    FW_OBJECT_NAMES=0
    FW_OBJECT_REGISTRATION=0
    FW_QUEUE_REGISTRATION=0
    FW_PORT_TRACING=0
    FW_PORT_SERIALIZATION=0
    FW_ENABLE_TEXT_LOGGING=0
    FW_SERIALIZABLE_TO_STRING=0
)

# The toolchain file's FPRIME_PLATFORM is set inside Zephyr's own project()
# scope and does not reach us; F´'s build artifacts stay in the build folder.
set(FPRIME_PLATFORM Zephyr)
# (F´'s settings loader replaces a defaulted install prefix with one next to
# settings.ini; a normal variable counts as given and keeps it here.)
set(CMAKE_INSTALL_PREFIX "${CMAKE_BINARY_DIR}/build-artifacts")
include("${KIT_DEPS}/fprime/cmake/FPrime.cmake")
fprime_setup_included_code()

# Build only what the deployment links: the framework and the libraries
# register every module they have, and some fprime-zephyr modules (LoRa,
# ZephyrTime) do not compile against Zephyr 4.0.
foreach(KIT_UPSTREAM_DIR IN ITEMS
        "${KIT_DEPS}/fprime/Fw" "${KIT_DEPS}/fprime/Svc" "${KIT_DEPS}/fprime/Os" "${KIT_DEPS}/fprime/Drv"
        "${KIT_DEPS}/fprime/CFDP" "${KIT_DEPS}/fprime/Utils"
        "${KIT_DEPS}/fprime-zephyr/fprime-zephyr/Os" "${KIT_DEPS}/fprime-zephyr/fprime-zephyr/Drv"
        "${KIT_DEPS}/fprime-zephyr/fprime-zephyr/Svc"
        "${KIT_DEPS}/fprime-baremetal/fprime-baremetal/Os" "${KIT_DEPS}/fprime-baremetal/fprime-baremetal/Svc")
    if(IS_DIRECTORY "${KIT_UPSTREAM_DIR}")
        set_property(DIRECTORY "${KIT_UPSTREAM_DIR}" PROPERTY EXCLUDE_FROM_ALL TRUE)
    endif()
endforeach()

# The shared deployment
add_fprime_subdirectory("${KIT_ROOT}/app/config")
add_fprime_subdirectory("${KIT_ROOT}/app/Components")
add_fprime_subdirectory("${KIT_ROOT}/app/Top")

# The scenario the run plays (CONFIG_KIT_SCENARIO): one source file each
set(KIT_SCENARIO_SOURCE "${KIT_ROOT}/app/scenarios/${CONFIG_KIT_SCENARIO}.cpp")
if(NOT EXISTS "${KIT_SCENARIO_SOURCE}")
    file(GLOB KIT_SCENARIOS RELATIVE "${KIT_ROOT}/app/scenarios" "${KIT_ROOT}/app/scenarios/*.cpp")
    string(REPLACE ".cpp" "" KIT_SCENARIOS "${KIT_SCENARIOS}")
    message(FATAL_ERROR "kit: unknown scenario CONFIG_KIT_SCENARIO=\"${CONFIG_KIT_SCENARIO}\"; "
        "the scenarios are: ${KIT_SCENARIOS} (app/scenarios/).")
endif()

# The variant: its config, its OS implementations and its main-loop half.
# variant.cmake sets KIT_VARIANT_SOURCES and KIT_VARIANT_IMPLEMENTATIONS.
include("${KIT_VARIANT_DIR}/variant.cmake")

register_fprime_zephyr_deployment(kit_${KIT_VARIANT}
    SOURCES
        "${KIT_ROOT}/app/src/main.cpp"
        "${KIT_ROOT}/app/src/Session.cpp"
        "${KIT_ROOT}/app/src/Report.cpp"
        "${KIT_ROOT}/app/src/Fatal.cpp"
        "${KIT_ROOT}/app/src/TickClock.cpp"
        "${KIT_SCENARIO_SOURCE}"
        "${KIT_ROOT}/app/src/CountingAllocator.cpp"
        "${KIT_ROOT}/app/src/HeapMonitor.cpp"
        ${KIT_VARIANT_SOURCES}
    DEPENDS
        app_Top
    CHOOSES_IMPLEMENTATIONS
        # No file system on either variant
        Os_File_Stub
        ${KIT_VARIANT_IMPLEMENTATIONS}
)
target_include_directories(app PRIVATE "${KIT_ROOT}")
# Every C heap allocation goes through app/src/HeapMonitor.cpp
foreach(KIT_HEAP_FUNCTION IN ITEMS malloc calloc realloc aligned_alloc memalign free)
    zephyr_ld_options("-Wl,--wrap=${KIT_HEAP_FUNCTION}")
endforeach()

# Provenance for the boot banner
function(kit_git_sha OUT DIR)
    execute_process(COMMAND git -C "${DIR}" rev-parse --short=12 HEAD
        OUTPUT_VARIABLE SHA OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE RC ERROR_QUIET)
    if(NOT RC EQUAL 0)
        set(SHA "unknown")
    endif()
    execute_process(COMMAND git -C "${DIR}" status --porcelain --untracked-files=no
        OUTPUT_VARIABLE DIRTY OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    if(NOT DIRTY STREQUAL "")
        set(SHA "${SHA}-dirty")
    endif()
    set(${OUT} "${SHA}" PARENT_SCOPE)
endfunction()
kit_git_sha(KIT_GIT_SHA "${KIT_ROOT}")
kit_git_sha(ZEPHYR_GIT_SHA "${KIT_DEPS}/zephyr")
kit_git_sha(FPRIME_GIT_SHA "${KIT_DEPS}/fprime")
target_compile_definitions(app PRIVATE
    KIT_GIT_SHA="${KIT_GIT_SHA}" ZEPHYR_GIT_SHA="${ZEPHYR_GIT_SHA}" FPRIME_GIT_SHA="${FPRIME_GIT_SHA}")
endmacro()

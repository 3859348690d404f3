# SPDX-License-Identifier: Apache-2.0
# ======================================================================
# board.cmake: the board folder and the toolchain of a kit application,
# before find_package(Zephyr). Included by app/kit.cmake (the deployment),
# app/plain_app.cmake (tests/floor/paths, tests/tick: plain Zephyr
# applications) and tests/floor/latency_measure, so all run under the same
# board configuration and compiler. Sets KIT_ROOT,
# KIT_BOARD (the boards/ folder's name) and KIT_BOARD_DIR.
# ======================================================================
include_guard(GLOBAL)

get_filename_component(KIT_ROOT "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)

# --- Workspace --------------------------------------------------------
# The west workspace's upstreams (paths in west.yml) must be there
function(kit_require_workspace)
    foreach(upstream_file IN LISTS ARGN)
        if(NOT EXISTS "${upstream_file}")
            message(FATAL_ERROR
                "kit: the west workspace is not provisioned: ${upstream_file} is missing.\n"
                "Run scripts/setup.sh (it installs the tools and runs 'west update').")
        endif()
    endforeach()
endfunction()
kit_require_workspace("${KIT_ROOT}/deps/zephyr/CMakeLists.txt")

# --- Board ------------------------------------------------------------
# Every board the kit runs on has a folder in boards/ (docs/porting.md),
# found by the rule of app/board_folder.cmake. Zephyr splits "mps2/an385"
# into BOARD and BOARD_QUALIFIERS, and F´'s sub-builds inherit the split
# BOARD: they read the cache entry the main configuration leaves.
include("${CMAKE_CURRENT_LIST_DIR}/board_folder.cmake")
if(DEFINED FPRIME_SUB_BUILD_TARGETS AND DEFINED KIT_BOARD_TARGET)
    set(KIT_BOARD_SPEC "${KIT_BOARD_TARGET}")
elseif(DEFINED BOARD)
    set(KIT_BOARD_SPEC "${BOARD}")
elseif(DEFINED ENV{BOARD})
    set(KIT_BOARD_SPEC "$ENV{BOARD}")
else()
    message(FATAL_ERROR "kit: no board given. Use west build -b qemu_cortex_m3 ...")
endif()
kit_board_folder(KIT_BOARD "${KIT_BOARD_SPEC}" "${KIT_ROOT}/boards")
if(NOT KIT_BOARD)
    file(GLOB KIT_PORTED_BOARDS RELATIVE "${KIT_ROOT}/boards" "${KIT_ROOT}/boards/*")
    list(FILTER KIT_PORTED_BOARDS EXCLUDE REGEX "\\.")
    message(FATAL_ERROR
        "kit: board '${KIT_BOARD_SPEC}' has no kit port. Ported boards: ${KIT_PORTED_BOARDS}.\n"
        "To bring the kit to a new board: west kit new-board <board>, then docs/porting.md.")
endif()
set(KIT_BOARD_DIR "${KIT_ROOT}/boards/${KIT_BOARD}")
set(KIT_BOARD_TARGET "${KIT_BOARD_SPEC}" CACHE STRING "Board target of this kit build" FORCE)
# (A Tables.fpp is optional: the deployment's table, app/Top/Tables.fpp,
# serves every board that has none.)
foreach(KIT_BOARD_FILE IN ITEMS kit.conf Kconfig.defconfig app.overlay)
    if(NOT EXISTS "${KIT_BOARD_DIR}/${KIT_BOARD_FILE}")
        message(FATAL_ERROR "kit: boards/${KIT_BOARD}/${KIT_BOARD_FILE} is missing; every port has one "
            "(see docs/porting.md).")
    endif()
endforeach()
# A real board's vendor HAL is a Zephyr module that west.yml allow-lists (at
# the revision the pinned Zephyr's own manifest gives). Without it Zephyr
# fails deep in its devicetree (a pinctrl include not found): the board's
# folder names the module and its folder in the workspace (boards/<board>/hal),
# and a workspace without it is refused here, saying what to do.
if(EXISTS "${KIT_BOARD_DIR}/hal")
    file(STRINGS "${KIT_BOARD_DIR}/hal" KIT_BOARD_HALS REGEX "^[a-z]")
    foreach(KIT_BOARD_HAL IN LISTS KIT_BOARD_HALS)
        string(REGEX MATCH "^([a-z0-9_]+)[ \t]+([^ \t]+)$" KIT_HAL_LINE "${KIT_BOARD_HAL}")
        if(NOT KIT_HAL_LINE)
            message(FATAL_ERROR "kit: boards/${KIT_BOARD}/hal: '${KIT_BOARD_HAL}' is not '<module> <folder>'")
        endif()
        if(NOT IS_DIRECTORY "${KIT_ROOT}/${CMAKE_MATCH_2}")
            message(FATAL_ERROR
                "kit: board '${KIT_BOARD_SPEC}' needs Zephyr's HAL module ${CMAKE_MATCH_1}, and the workspace "
                "has no ${CMAKE_MATCH_2}.\n"
                "west.yml must allow-list it (name-allowlist under the zephyr project); then run "
                "scripts/setup.sh (it runs 'west update').")
        endif()
    endforeach()
endif()

# --- Toolchain --------------------------------------------------------
# The kit's choice (app/toolchain.cmake, which the shell scripts read too)
include("${CMAKE_CURRENT_LIST_DIR}/toolchain.cmake")
kit_toolchain()

# SPDX-License-Identifier: Apache-2.0
# ======================================================================
# plain_app.cmake: a plain Zephyr application of the kit (no F´) under the
# deployment's board configuration, compiler and system clock, up to
# find_package(Zephyr): its own prj.conf, then the board's kit.conf (its
# QEMU conditions). Included by tests/floor/paths and tests/tick/start.
# ======================================================================
include("${CMAKE_CURRENT_LIST_DIR}/board.cmake")
if(NOT DEFINED CONF_FILE)
    set(CONF_FILE "${CMAKE_CURRENT_SOURCE_DIR}/prj.conf" "${KIT_BOARD_DIR}/kit.conf")
endif()
find_package(Zephyr REQUIRED HINTS "${KIT_ROOT}/deps/zephyr")

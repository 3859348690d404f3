# SPDX-License-Identifier: Apache-2.0
# ======================================================================
# board_folder.cmake: which boards/ folder holds a board target's port,
# the rule written once. The target with '/' as '_' (mps2/an385:
# mps2_an385), else the board's name alone, covering all its qualifiers
# (qemu_cortex_m3/ti_lm3s6965: qemu_cortex_m3). The full name wins, so one
# qualifier can have a port of its own. No folder: empty.
#
#   include(): kit_board_folder(<out> <target> <boards dir>)  (app/board.cmake)
#   cmake -DKIT_BOARD_TARGETS="mps2/an385;..." -DKIT_BOARDS_DIR=<dir> -P app/board_folder.cmake
#     prints "<target> <folder>" per target (the folder empty when none):
#     scripts/tests/test_one_rule.py holds kittools' copy of the rule
#     (kittools/workspace.py, board_folder) to what this prints.
# ======================================================================
include_guard(GLOBAL)

function(kit_board_folder OUT TARGET BOARDS_DIR)
    string(REPLACE "/" "_" KIT_FULL_NAME "${TARGET}")
    string(REGEX REPLACE "/.*$" "" KIT_BOARD_NAME "${TARGET}")
    foreach(KIT_NAME IN ITEMS "${KIT_FULL_NAME}" "${KIT_BOARD_NAME}")
        if(IS_DIRECTORY "${BOARDS_DIR}/${KIT_NAME}")
            set(${OUT} "${KIT_NAME}" PARENT_SCOPE)
            return()
        endif()
    endforeach()
    set(${OUT} "" PARENT_SCOPE)
endfunction()

if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE)
    foreach(KIT_TARGET IN LISTS KIT_BOARD_TARGETS)
        kit_board_folder(KIT_FOLDER "${KIT_TARGET}" "${KIT_BOARDS_DIR}")
        execute_process(COMMAND "${CMAKE_COMMAND}" -E echo "${KIT_TARGET} ${KIT_FOLDER}")
    endforeach()
endif()

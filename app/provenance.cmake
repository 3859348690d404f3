# SPDX-License-Identifier: Apache-2.0
# Provenance for the boot banner: the commits of the kit, Zephyr and F´
# (with -dirty for uncommitted changes).
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
kit_git_sha(ZEPHYR_GIT_SHA "${ZEPHYR_BASE}")
kit_git_sha(FPRIME_GIT_SHA "${FPRIME_FRAMEWORK_PATH}")
target_compile_definitions(app PRIVATE
    KIT_GIT_SHA="${KIT_GIT_SHA}" ZEPHYR_GIT_SHA="${ZEPHYR_GIT_SHA}" FPRIME_GIT_SHA="${FPRIME_GIT_SHA}")

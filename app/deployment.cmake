# SPDX-License-Identifier: Apache-2.0
# ======================================================================
# deployment.cmake: the seam between the kit and the F´ deployment it
# measures (KIT_DEPLOYMENT_DIR; docs/your-deployment.md). A deployment
# folder holds F´'s usual three parts, each an F´ CMake folder:
#   config/       its F´ configuration (register_fprime_config)
#   Components/   its own components
#   Top/          its topology, which imports the kit's instruments and
#                 ground link (`import Kit.Instruments`, `import Kit.GroundLink`:
#                 app/Subtopologies/)
# A folder that is not one is refused here, before Zephyr configures, with
# the one thing it lacks.
# ======================================================================
include_guard(GLOBAL)

# The F´ module location a deployment's modules are named from (F´ builds a
# module only inside a location: its framework, its libraries, its
# project): the deployment's own F´ project, the nearest folder above it
# with F´'s settings.ini (the one fprime-util made it in); else the kit's
# repository for a folder inside it, or the folder that holds it. The kit
# adds that location to F´'s (app/kit.cmake), so a team's deployment builds
# where it is, with the module names and include paths it has in its own
# project ("MyDeployment/Top/...").
function(kit_deployment_location OUT DIR)
    cmake_path(ABSOLUTE_PATH DIR NORMALIZE OUTPUT_VARIABLE KIT_FOLDER)
    cmake_path(IS_PREFIX KIT_ROOT "${KIT_FOLDER}" NORMALIZE KIT_INSIDE)
    cmake_path(GET KIT_FOLDER PARENT_PATH KIT_ABOVE)
    if(KIT_INSIDE)
        set(KIT_LOCATION "${KIT_ROOT}")
    else()
        set(KIT_LOCATION "${KIT_ABOVE}")
    endif()
    # Bounded: one step per folder up to the kit's root or the file system's
    while(NOT KIT_ABOVE STREQUAL KIT_ROOT)
        if(EXISTS "${KIT_ABOVE}/settings.ini")
            set(KIT_LOCATION "${KIT_ABOVE}")
            break()
        endif()
        cmake_path(GET KIT_ABOVE PARENT_PATH KIT_NEXT)
        if(KIT_NEXT STREQUAL KIT_ABOVE)
            break()
        endif()
        set(KIT_ABOVE "${KIT_NEXT}")
    endwhile()
    set(${OUT} "${KIT_LOCATION}" PARENT_SCOPE)
endfunction()

function(kit_check_deployment DIR)
    set(KIT_SEAM_DOC "The seam a deployment provides: docs/your-deployment.md.")
    if(NOT IS_DIRECTORY "${DIR}")
        message(FATAL_ERROR "kit: the deployment folder '${DIR}' (KIT_DEPLOYMENT_DIR) does not exist. ${KIT_SEAM_DOC}")
    endif()
    # Its modules are named from the folder above it: a deployment that is
    # itself a project's root has no name there
    kit_deployment_location(KIT_LOCATION "${DIR}")
    cmake_path(ABSOLUTE_PATH DIR NORMALIZE OUTPUT_VARIABLE KIT_FOLDER)
    if(KIT_FOLDER STREQUAL KIT_LOCATION OR (NOT KIT_FOLDER STREQUAL "${KIT_ROOT}/app" AND EXISTS "${KIT_FOLDER}/settings.ini"))
        message(FATAL_ERROR "kit: '${DIR}' is an F´ project's root (it has settings.ini); name the deployment "
            "folder inside it (the one fprime-util new --deployment made). ${KIT_SEAM_DOC}")
    endif()
    foreach(KIT_PART IN ITEMS config Components Top)
        if(NOT EXISTS "${DIR}/${KIT_PART}/CMakeLists.txt")
            message(FATAL_ERROR "kit: '${DIR}' is not a kit deployment: it has no ${KIT_PART}/CMakeLists.txt. "
                "${KIT_SEAM_DOC}")
        endif()
    endforeach()
    # The topology must import the kit's instruments and its ground link:
    # without them nothing is measured, and F´ or the linker would only fail
    # later on a missing instance
    file(GLOB_RECURSE KIT_TOPOLOGY_FILES "${DIR}/Top/*.fpp")
    foreach(KIT_SUBTOPOLOGY IN ITEMS Instruments GroundLink)
        set(KIT_IMPORTED OFF)
        foreach(KIT_FILE IN LISTS KIT_TOPOLOGY_FILES)
            file(STRINGS "${KIT_FILE}" KIT_IMPORT
                REGEX "^[ \t]*import[ \t]+(Kit\\.)?${KIT_SUBTOPOLOGY}[ \t]*(#.*)?$")
            if(KIT_IMPORT)
                set(KIT_IMPORTED ON)
            endif()
        endforeach()
        if(NOT KIT_IMPORTED)
            message(FATAL_ERROR "kit: the topology of '${DIR}' does not import the kit's ${KIT_SUBTOPOLOGY} "
                "subtopology: add `import Kit.${KIT_SUBTOPOLOGY}` to its topology (Top/*.fpp). ${KIT_SEAM_DOC}")
        endif()
    endforeach()
    # Its rate groups where the kit reads them (app/src/Deployment.hpp): the
    # counts in Top/KitTopology.hpp, the table RATE_GROUPS in a Top/ source.
    # Without them the kit's own code fails to compile, far from the cause.
    set(KIT_COUNTS "${DIR}/Top/KitTopology.hpp")
    if(EXISTS "${KIT_COUNTS}")
        file(STRINGS "${KIT_COUNTS}" KIT_COUNT REGEX "RATE_GROUP_COUNT[ \t]*=")
    endif()
    file(GLOB KIT_TOPOLOGY_SOURCES "${DIR}/Top/*.cpp")
    set(KIT_TABLE OFF)
    foreach(KIT_FILE IN LISTS KIT_TOPOLOGY_SOURCES)
        file(STRINGS "${KIT_FILE}" KIT_DEFINES REGEX "RateGroupSpec[ \t]+RATE_GROUPS[ \t]*\\[")
        if(KIT_DEFINES)
            set(KIT_TABLE ON)
        endif()
    endforeach()
    if(NOT KIT_COUNT OR NOT KIT_TABLE)
        message(FATAL_ERROR "kit: the kit cannot find the rate groups of '${DIR}': its Top/KitTopology.hpp must "
            "define RATE_GROUP_COUNT and a Top/*.cpp the table RATE_GROUPS (app/src/Deployment.hpp). ${KIT_SEAM_DOC}")
    endif()
endfunction()

# The priority, stack and queue table a deployment builds with on a board
# (docs/your-deployment.md): its board's own (Top/boards/<board folder>/
# Tables.fpp, for a board whose measured stacks or priorities differ; the
# reference deployment's are in the board's folder, boards/<board>/
# Tables.fpp, where kit new-board puts them), else its table for every
# board (Top/Tables.fpp). A deployment with neither for the board is
# refused, naming the boards it has tables for.
function(kit_deployment_tables OUT DIR BOARD)
    set(KIT_CANDIDATES "${DIR}/Top/boards/${BOARD}/Tables.fpp")
    cmake_path(ABSOLUTE_PATH DIR NORMALIZE OUTPUT_VARIABLE KIT_FOLDER)
    if(KIT_FOLDER STREQUAL "${KIT_ROOT}/app")
        list(APPEND KIT_CANDIDATES "${KIT_ROOT}/boards/${BOARD}/Tables.fpp")
    endif()
    list(APPEND KIT_CANDIDATES "${DIR}/Top/Tables.fpp")
    foreach(KIT_CANDIDATE IN LISTS KIT_CANDIDATES)
        if(EXISTS "${KIT_CANDIDATE}")
            set(${OUT} "${KIT_CANDIDATE}" PARENT_SCOPE)
            return()
        endif()
    endforeach()
    file(GLOB KIT_TABLE_BOARDS RELATIVE "${DIR}/Top/boards" "${DIR}/Top/boards/*/Tables.fpp")
    list(TRANSFORM KIT_TABLE_BOARDS REPLACE "/Tables.fpp$" "")
    if(NOT KIT_TABLE_BOARDS)
        set(KIT_TABLE_BOARDS "none")
    endif()
    message(FATAL_ERROR "kit: the deployment '${DIR}' has no table for board '${BOARD}' (boards it has one for: "
        "${KIT_TABLE_BOARDS}): add its priorities, stacks and queues for this board in "
        "Top/boards/${BOARD}/Tables.fpp, or for every board in Top/Tables.fpp. The seam a deployment provides: "
        "docs/your-deployment.md.")
endfunction()

# The same check from the kit's commands, before any build starts:
#   cmake -DKIT_ROOT=<kit> -DKIT_DEPLOYMENT_DIR=<folder> -P app/deployment.cmake
#   ... and with -DKIT_BOARDS=<board folder>;... its table for each board
# It prints the F´ project the deployment is named from:
#   -- KIT_DEPLOYMENT_LOCATION=<folder>
if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE)
    kit_check_deployment("${KIT_DEPLOYMENT_DIR}")
    kit_deployment_location(KIT_LOCATION "${KIT_DEPLOYMENT_DIR}")
    message(STATUS "KIT_DEPLOYMENT_LOCATION=${KIT_LOCATION}")
    foreach(KIT_BOARD_FOLDER IN LISTS KIT_BOARDS)
        kit_deployment_tables(KIT_TABLES "${KIT_DEPLOYMENT_DIR}" "${KIT_BOARD_FOLDER}")
    endforeach()
endif()

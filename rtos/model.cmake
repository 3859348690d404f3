# SPDX-License-Identifier: Apache-2.0
# RTOS execution model: every active component is a Zephyr thread, through
# fprime-zephyr's OSAL, with the kit's priority mapping on top (rtos/Os).
add_fprime_subdirectory("${CMAKE_CURRENT_LIST_DIR}/config")
add_fprime_subdirectory("${CMAKE_CURRENT_LIST_DIR}/Os")

set(KIT_MODEL_SOURCES
    "${CMAKE_CURRENT_LIST_DIR}/Variant.cpp"
    "${CMAKE_CURRENT_LIST_DIR}/ThreadStacks.cpp"  # every thread's stack at the table's size
    "${CMAKE_CURRENT_LIST_DIR}/AssertReport.cpp"  # an assert's report on a stack of its own
    "${CMAKE_CURRENT_LIST_DIR}/ModelChecks.cpp"  # build-time checks that the topology fits this model
)
set(KIT_MODEL_IMPLEMENTATIONS
    Kit_Os_Task_ZephyrPriority  # fprime-zephyr's task, with F´ priorities mapped onto Zephyr's
    Os_Mutex_Zephyr             # k_mutex / k_condvar
)
# MicroFs, each call under one lock (rtos/Os/LockedFile.hpp), where the
# build has a file system (app/kit.cmake)
set(KIT_MODEL_FILE_IMPLEMENTATION Kit_Os_File_LockedMicroFs)
if(CONFIG_KIT_QUEUE_KIT)
    list(APPEND KIT_MODEL_IMPLEMENTATIONS Kit_Os_Queue_Zephyr)  # semaphores and a spinlock (rtos/Os)
endif()

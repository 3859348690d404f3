# SPDX-License-Identifier: Apache-2.0
# Baremetal execution model: fprime-baremetal's cooperative Os::Task (every
# active component is a task the TaskRunner gives one slice per pass) on
# Zephyr with no threads at all. Zephyr is only the boot and driver layer
# here. (The TaskRunner's patch is checked by modules/fprime-baremetal.)
add_fprime_subdirectory("${CMAKE_CURRENT_LIST_DIR}/config")
add_fprime_subdirectory("${CMAKE_CURRENT_LIST_DIR}/Os")

set(KIT_MODEL_SOURCES
    "${CMAKE_CURRENT_LIST_DIR}/Variant.cpp"
    "${CMAKE_CURRENT_LIST_DIR}/ThreadPointer.cpp"  # errno's thread-local block: Zephyr gives none without threads
    "${CMAKE_CURRENT_LIST_DIR}/ModelChecks.cpp"  # build-time checks that the topology fits this model
)
set(KIT_MODEL_IMPLEMENTATIONS
    Kit_Os_Task_BaremetalTimed  # fprime-baremetal's cooperative task, slices timed (baremetal/Os)
    Os_Mutex_Stub        # one context: nothing to exclude (also the condition variable)
    Os_Cpu_Baremetal
    Os_Memory_Baremetal
)
if(CONFIG_KIT_QUEUE_KIT)
    list(APPEND KIT_MODEL_IMPLEMENTATIONS Kit_Os_Queue_Cooperative)  # no lock, no waiting (baremetal/Os)
endif()
# F´'s files on the RAM file system (app/kit.cmake): fprime-baremetal's
# MicroFs as it is, which takes no lock; one context, so nothing can race
set(KIT_MODEL_FILE_IMPLEMENTATION Os_File_Baremetal_MicroFs)

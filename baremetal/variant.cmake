# Baremetal variant: fprime-baremetal's cooperative Os::Task (every active
# component is a task the TaskRunner gives one slice per pass) on Zephyr with
# no threads at all. Zephyr is only the boot and driver layer here.
# fprime-baremetal's TaskRunner needs the kit's fix (see patches/): refuse to
# build a workspace where scripts/setup.sh has not applied it.
file(GLOB KIT_BAREMETAL_PATCHES "${CMAKE_CURRENT_LIST_DIR}/patches/fprime-baremetal/*.patch")
foreach(KIT_PATCH IN LISTS KIT_BAREMETAL_PATCHES)
    execute_process(COMMAND git -C "${KIT_DEPS}/fprime-baremetal" apply --reverse --check "${KIT_PATCH}"
        RESULT_VARIABLE KIT_PATCH_MISSING OUTPUT_QUIET ERROR_QUIET)
    if(KIT_PATCH_MISSING)
        message(FATAL_ERROR "kit: deps/fprime-baremetal lacks the kit's patch ${KIT_PATCH}.\n"
            "Run scripts/setup.sh (it applies the patches after west update).")
    endif()
endforeach()

add_fprime_subdirectory("${CMAKE_CURRENT_LIST_DIR}/config")
add_fprime_subdirectory("${CMAKE_CURRENT_LIST_DIR}/Os")

set(KIT_VARIANT_SOURCES "${CMAKE_CURRENT_LIST_DIR}/Variant.cpp")
set(KIT_VARIANT_IMPLEMENTATIONS
    Kit_Os_Task_BaremetalTimed  # fprime-baremetal's cooperative task, slices timed (baremetal/Os)
    Os_Mutex_Stub        # one context: nothing to exclude (also the condition variable)
    Os_Cpu_Baremetal
    Os_Memory_Baremetal
)

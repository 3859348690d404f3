// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  ThreadPointer.cpp
// \brief  A thread-local block for the model's one context
//
// Zephyr sets the thread pointer (z_arm_tls_ptr on Cortex-M) when it
// switches to a thread, to that thread's thread-local block. A build
// without threads (CONFIG_MULTITHREADING=n) never switches, so the pointer
// stays 0 and every thread-local variable lives at a small address: the
// C library's errno among them. A malloc that fails writes ENOMEM to
// address 8: on mps2/an385, whose MPU guards that region, an MPU fault
// ("Data Access Violation, MMFAR 0x8") instead of a null the caller can
// handle; on qemu_cortex_m3 a write into flash that QEMU drops. This gives
// the main context a block laid out as Zephyr lays out a thread's
// (arch/arm/core/tls.c: an 8 B control block, then .tdata, then .tbss),
// before anything at all runs.
// ======================================================================
#include <zephyr/init.h>
#include <zephyr/kernel.h>
#include <zephyr/linker/linker-defs.h>

#include <cstdint>
#include <cstring>

#if defined(CONFIG_THREAD_LOCAL_STORAGE)
#if !defined(CONFIG_CPU_CORTEX_M)
#error "baremetal/ThreadPointer.cpp sets Cortex-M's thread pointer: set this architecture's here"
#endif

extern "C" uintptr_t z_arm_tls_ptr;

namespace {

//! The control block the toolchain expects before the data (two words)
constexpr size_t CONTROL_BLOCK = 2 * sizeof(uintptr_t);
//! The build's thread-local data is picolibc's errno (4 B), and no more:
//! nucleo_g071rb's small build had 28 B of RAM to spare
constexpr size_t BLOCK_BYTES = 16;
alignas(8) uint8_t s_block[BLOCK_BYTES];

int setThreadPointer() {
    const size_t data = static_cast<size_t>(reinterpret_cast<uintptr_t>(__tdata_size));
    const size_t bss = static_cast<size_t>(reinterpret_cast<uintptr_t>(__tbss_size));
    if (CONTROL_BLOCK + data + bss > BLOCK_BYTES) {
        // Too early for the console: a halt the debugger shows, never a
        // block that overlaps what follows it
        k_panic();
    }
    uint8_t* const tls = &s_block[CONTROL_BLOCK];
    (void)memcpy(tls, __tdata_start, data);
    (void)memset(tls + data, 0, bss);
    z_arm_tls_ptr = reinterpret_cast<uintptr_t>(&s_block[0]);
    return 0;
}

}  // namespace

SYS_INIT(setThreadPointer, EARLY, 0);
#endif

// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Fatal.cpp
// \brief  Where every fatal path ends, in both variants
//
// Zephyr calls k_sys_fatal_error_handler after it has printed its own report
// ("ZEPHYR FATAL ERROR n: ..."): for CPU faults, a stack overflow caught by
// the stack sentinel, and k_panic(), which the kit's FatalHandler (F´ FATAL
// events, so F´ asserts too) and the baremetal stack guard raise. The kit adds
// one line naming the reason and the execution context, then twister's
// failure marker, so a run that dies fails at once instead of waiting for
// twister's time-out, and halts. A fatal fault a scenario injected on
// purpose (Fatal::expect) is reported without the marker. The kit's own
// detectors (the baremetal stack guard) end here too, through Fatal::halt.
// ======================================================================
#include "app/src/Fatal.hpp"
#include "app/src/Report.hpp"
#include "app/src/Variant.hpp"

#include <zephyr/fatal.h>
#include <zephyr/kernel.h>
#include <zephyr/sys/printk.h>

namespace {

volatile bool s_expecting = false;
volatile unsigned int s_expectedReason = 0;

const char* reasonName(unsigned int reason) {
    switch (reason) {
        case K_ERR_CPU_EXCEPTION:
            return "cpu_exception";
        case K_ERR_SPURIOUS_IRQ:
            return "spurious_irq";
        case K_ERR_STACK_CHK_FAIL:
            return "stack_overflow";
        case K_ERR_KERNEL_OOPS:
            return "kernel_oops";
        case K_ERR_KERNEL_PANIC:
            return "kernel_panic";
        default:
            return "arch_specific";
    }
}

}  // namespace

void Kit::Fatal::expect(unsigned int reason) {
    s_expectedReason = reason;
    s_expecting = true;
}

void Kit::Fatal::halt(unsigned int reason) {
    // Without an MPU, an overflow of the baremetal main stack runs into the
    // interrupt stack below it, and an interrupt taken meanwhile returns
    // through a frame the overflow shares: a CPU fault before the guard is
    // checked. A fault with the guard's paint gone is that overflow.
    const Kit::Variant::GuardBreach breach = Kit::Variant::guardState();
    if (breach.breached && reason != K_ERR_STACK_CHK_FAIL) {
        Kit::Report::guardBreach(breach);
        reason = K_ERR_STACK_CHK_FAIL;
    }
    const bool expected = s_expecting && reason == s_expectedReason;
    Kit::Report::halt(reasonName(reason), reason, expected);
    // Nothing else may run: Zephyr's halt masks interrupts and spins until the
    // runner (twister, scripts/kit) stops QEMU.
    k_fatal_halt(reason);
}

extern "C" void k_sys_fatal_error_handler(unsigned int reason, const struct arch_esf* esf) {
    (void)esf;
    Kit::Fatal::halt(reason);
}

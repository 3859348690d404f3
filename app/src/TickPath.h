/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The first steps of every tick, shared by the deployment and the kit's
 * kernel-floor measurements (tests/floor), so the floor is measured from
 * the same stamp, taken the same way, as the deployment's latencies:
 *
 * - kit_tick_stamp: the board tick is a periodic k_timer; its expiry
 *   function (run in the system clock ISR) stamps the free-running counter
 *   first thing, then counts the tick (app/src/TickClock.cpp);
 * - kit_tick_idle_until: the thread-less main loop sleeps until the tick
 *   count moves (baremetal/Variant.cpp's waitForTick).
 *
 * C, header-only: tests/floor/paths is a plain Zephyr application without F´.
 */
#ifndef KIT_TICKPATH_H
#define KIT_TICKPATH_H

#include <stdint.h>
#include <zephyr/kernel.h>

/* Stamp tick `*fired` into a ring of `history` stamps, then count it. A
 * 32-bit aligned store is atomic on Cortex-M: readers see the stamp before
 * the count that makes it theirs. */
static inline void kit_tick_stamp(volatile uint32_t *fired, uint32_t *stamps, uint32_t history)
{
	const uint32_t tick = *fired;

	stamps[tick % history] = k_cycle_get_32();
	*fired = tick + 1U;
}

/* Sleep until `ticks_fired()` differs from `handled`, with no window between the
 * check and the sleep: on ARMv7-M k_cpu_idle() masks with PRIMASK before it
 * lifts the irq_lock (BASEPRI) and sleeps in WFI, so a tick that fires after
 * the check still wakes it. Not k_cpu_atomic_idle(): it sleeps in WFE, which
 * QEMU executes as a busy spin, costing wall time (a soak ran 5x slower)
 * though not virtual time. */
static inline void kit_tick_idle_until(uint32_t (*ticks_fired)(void), uint32_t handled)
{
	unsigned int key = irq_lock();

	while (ticks_fired() == handled) {
		k_cpu_idle();
		key = irq_lock();
	}
	irq_unlock(key);
}

#endif /* KIT_TICKPATH_H */

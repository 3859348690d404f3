/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The first steps of every tick, shared by the deployment and the kit's
 * kernel-floor measurements (tests/floor), so the floor is measured from
 * the same stamp, taken the same way, as the deployment's latencies:
 *
 * - kit_tick_start: the board tick is a periodic k_timer, started early in
 *   a kernel tick;
 * - kit_tick_stamp: its expiry
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

/* Start the periodic board tick `timer`, every `period_us`, early in a
 * kernel tick. Zephyr adds a timeout in ticks from the current tick as it
 * reads it (z_add_timeout, next_timeout), and the system clock driver turns
 * that into cycles from a later reading of its own
 * (sys_clock_set_timeout): a start that a tick boundary passes between the
 * two readings gets its first expiry one tick late, announced with the
 * next one, and the periodic timer, re-armed from the tick it was due at,
 * fires its second expiry at once: two ticks a few hundred cycles apart, a
 * run that starts with a slip. k_timer_start(timer, period, period) did
 * that on mps3/corstone300/an547's rtos run (ticks 0 and 1 stamped 192
 * cycles apart), and on 7 of 252 phases on qemu_cortex_m3, 22 of 455 on
 * mps2/an385 (tests/tick/start sweeps the start across a tick). So the
 * start waits for a boundary and adds the timer, interrupts locked, while
 * the tick is young: the next boundary is most of a tick away. Bounded:
 * a boundary is at most a tick away, and only a start held off for half
 * a tick (by interrupts) takes another. */
#define KIT_TICK_START_ATTEMPTS 4U

static inline void kit_tick_start(struct k_timer *timer, uint32_t period_us)
{
	const uint32_t kernel_tick = sys_clock_hw_cycles_per_sec() / CONFIG_SYS_CLOCK_TICKS_PER_SEC;

	for (uint32_t attempt = 0U; attempt < KIT_TICK_START_ATTEMPTS; attempt++) {
		/* `before` is always read before an uptime that was still `tick`:
		 * the boundary that ends `tick` is after it */
		uint32_t before = k_cycle_get_32();
		const int64_t tick = k_uptime_ticks();

		for (;;) { /* until the boundary: at most one kernel tick */
			const uint32_t stamp = k_cycle_get_32();

			if (k_uptime_ticks() != tick) {
				break;
			}
			before = stamp;
		}

		const unsigned int key = irq_lock();

		if (k_cycle_get_32() - before < kernel_tick / 2U) {
			k_timer_start(timer, K_USEC(period_us), K_USEC(period_us));
			irq_unlock(key);
			return;
		}
		irq_unlock(key);
	}
	k_panic(); /* interrupts held the start off half a tick, every time */
}

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

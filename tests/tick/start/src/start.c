/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The board tick's start (app/src/TickPath.h, kit_tick_start) at every
 * phase of a kernel tick. The tick is started again and again, each time a
 * little later after a kernel tick boundary: COARSE_STARTS spread over the
 * whole tick, then one every FINE_STEP cycles over its last 1/FINE_SHARE,
 * where a start straddles the next boundary while the kernel adds its
 * timeout. Each start must fire its first TICKS ticks one period apart,
 * within half a period. A start whose first expiry comes a tick late fires
 * its second at once (Zephyr's periodic timer re-arms from the tick it was
 * due at): k_timer_start(timer, period, period) does that on a start a few
 * hundred cycles before a boundary, and this test fails with it.
 *
 * A line for each bad start, its first stamps after the boundary it
 * followed,
 *   KIT TICKSTART bad phase=C started=C stamps=C,C,C,C
 * then one for the sweep,
 *   KIT TICKSTART starts=N bad=N shortest=C longest=C period=C
 * (C in counter cycles: the shortest and longest gap between two of a
 * start's first ticks), then
 *   KIT END app=tick_start result=PASS|FAIL
 */
#include <stdint.h>
#include <zephyr/kernel.h>
#include <zephyr/sys/printk.h>

#include "app/src/TickPath.h"

#define PERIOD_US 1000U
#define TICKS 4U
#define COARSE_STARTS 64U
#define FINE_SHARE 16U
#define FINE_STEP 4U

static struct k_timer s_tick;
static volatile uint32_t s_fired;
static uint32_t s_stamps[TICKS];

static void on_expiry(struct k_timer *timer)
{
	ARG_UNUSED(timer);
	if (s_fired < TICKS) {
		kit_tick_stamp(&s_fired, s_stamps, TICKS);
	}
}

static uint32_t ticks_fired(void)
{
	return s_fired;
}

struct sweep {
	uint32_t period; /* the tick's period, counter cycles */
	uint32_t starts;
	uint32_t bad;
	uint32_t shortest;
	uint32_t longest;
};

/* Start the tick `phase` cycles after a kernel tick boundary; take its
 * first TICKS ticks */
static void start_at(struct sweep *sweep, uint32_t phase)
{
	const int64_t tick = k_uptime_ticks();

	while (k_uptime_ticks() == tick) {
		/* the uptime moves at a kernel tick boundary: at most one tick */
	}
	const uint32_t boundary = k_cycle_get_32();

	while (k_cycle_get_32() - boundary < phase) {
		/* phase < one kernel tick */
	}
	s_fired = 0U;
	const uint32_t started = k_cycle_get_32();

	kit_tick_start(&s_tick, PERIOD_US);
	for (uint32_t handled = 0U; handled < TICKS; handled = ticks_fired()) {
		kit_tick_idle_until(ticks_fired, handled);
	}
	k_timer_stop(&s_tick);

	bool bad = false;

	for (uint32_t i = 1U; i < TICKS; i++) {
		const uint32_t gap = s_stamps[i] - s_stamps[i - 1U];

		sweep->shortest = MIN(sweep->shortest, gap);
		sweep->longest = MAX(sweep->longest, gap);
		bad = bad || gap < sweep->period / 2U || gap > sweep->period + sweep->period / 2U;
	}
	sweep->starts++;
	if (bad) {
		sweep->bad++;
		printk("KIT TICKSTART bad phase=%u started=%u stamps=%u,%u,%u,%u\n", (unsigned int)phase,
		       (unsigned int)(started - boundary), (unsigned int)(s_stamps[0] - boundary),
		       (unsigned int)(s_stamps[1] - boundary), (unsigned int)(s_stamps[2] - boundary),
		       (unsigned int)(s_stamps[3] - boundary));
	}
}

int main(void)
{
	const uint32_t cycles_hz = (uint32_t)sys_clock_hw_cycles_per_sec();
	const uint32_t kernel_tick = cycles_hz / CONFIG_SYS_CLOCK_TICKS_PER_SEC;
	struct sweep sweep = {
		.period = (uint32_t)(((uint64_t)cycles_hz * PERIOD_US) / 1000000U),
		.shortest = UINT32_MAX,
	};

	k_timer_init(&s_tick, on_expiry, NULL);
	for (uint32_t i = 0U; i < COARSE_STARTS; i++) {
		start_at(&sweep, (kernel_tick * i) / COARSE_STARTS);
	}
	for (uint32_t phase = kernel_tick - kernel_tick / FINE_SHARE; phase < kernel_tick; phase += FINE_STEP) {
		start_at(&sweep, phase);
	}
	printk("KIT TICKSTART starts=%u bad=%u shortest=%u longest=%u period=%u\n", (unsigned int)sweep.starts,
	       (unsigned int)sweep.bad, (unsigned int)sweep.shortest, (unsigned int)sweep.longest,
	       (unsigned int)sweep.period);
	printk("KIT END app=tick_start result=%s\n", sweep.bad == 0U ? "PASS" : "FAIL");
	return 0;
}

/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The kernel's floor under the kit's rate-group latencies: how long Zephyr
 * itself takes from the tick's stamp to the first instruction of the code
 * that would dispatch the 1 kHz group, on each path shape an execution
 * model uses, with nothing of F´ in between. The tick and its stamp are the
 * deployment's own (app/src/TickPath.h), so a model's latency divided by
 * its shape's floor is the share F´ and the model add.
 *
 * Without threads (CONFIG_MULTITHREADING=n, the baremetal models' build):
 *   wfi   the main loop sleeping in WFI until the tick count moves, as
 *         baremetal/Variant.cpp's waitForTick does.
 * With threads (the rtos model's build):
 *   sem   the tick's expiry gives a semaphore a thread waits on, as
 *         rtos/Variant.cpp's tick thread does;
 *   msgq  that thread puts the tick into a k_msgq and a less urgent thread
 *         takes it: the shape of the rtos model's tick thread handing the
 *         tick to a rate-group thread.
 *
 * Each path runs SAMPLES ticks after WARMUP and prints one line,
 *   KIT FLOOR path=<path> samples=N missed=N p50=C p99=C max=C cycles_hz=F
 * (C in counter cycles, the counter the deployment stamps with), then
 *   KIT END app=floor result=PASS|FAIL
 * FAIL if a path missed a tick (it fell a whole period behind). Under QEMU
 * icount the numbers are exact and the same on every run.
 */
#include <stdint.h>
#include <stdlib.h>
#include <zephyr/kernel.h>
#include <zephyr/sys/printk.h>

#include "app/src/TickPath.h"

#define PERIOD_US 1000U
#define WARMUP 16U
#define SAMPLES 1000U
#define HISTORY 64U

static struct k_timer s_tick;
static volatile uint32_t s_fired;
static uint32_t s_stamps[HISTORY];
static uint32_t s_latency[SAMPLES];
static bool s_failed;

/* What the tick's expiry does after its stamp: the path's wake-up */
static void (*volatile s_wake)(void);

static void on_expiry(struct k_timer *timer)
{
	ARG_UNUSED(timer);
	kit_tick_stamp(&s_fired, s_stamps, HISTORY);
	if (s_wake != NULL) {
		s_wake();
	}
}

static int by_value(const void *a, const void *b)
{
	const uint32_t x = *(const uint32_t *)a;
	const uint32_t y = *(const uint32_t *)b;

	return (x > y) - (x < y);
}

/* A path's latencies, one per tick, from the tick's stamp to `now` */
struct path_run {
	uint32_t handled; /* ticks taken so far */
	uint32_t samples;
	uint32_t missed;
};

static void path_start(struct path_run *run, void (*wake)(void))
{
	*run = (struct path_run){0};
	s_fired = 0U;
	s_wake = wake;
	k_timer_init(&s_tick, on_expiry, NULL);
	kit_tick_start(&s_tick, PERIOD_US);
}

/* Take tick `run->handled` at cycle `now`; false once the run is complete */
static bool path_take(struct path_run *run, uint32_t now)
{
	const uint32_t tick = run->handled;

	if (s_fired - tick > 1U) {
		run->missed++; /* the path fell a period behind */
	}
	if (tick >= WARMUP && run->samples < SAMPLES) {
		s_latency[run->samples++] = now - s_stamps[tick % HISTORY];
	}
	run->handled = tick + 1U;
	return run->samples < SAMPLES;
}

static void path_report(const char *name, struct path_run *run)
{
	k_timer_stop(&s_tick);
	s_wake = NULL;
	qsort(s_latency, run->samples, sizeof(s_latency[0]), by_value);
	const uint32_t n = run->samples;
	if (n != SAMPLES || run->missed != 0U) {
		s_failed = true;
	}
	printk("KIT FLOOR path=%s samples=%u missed=%u p50=%u p99=%u max=%u cycles_hz=%u\n", name,
	       (unsigned int)n, (unsigned int)run->missed, (unsigned int)(n ? s_latency[n / 2U] : 0U),
	       (unsigned int)(n ? s_latency[(n * 99U) / 100U] : 0U),
	       (unsigned int)(n ? s_latency[n - 1U] : 0U), (unsigned int)sys_clock_hw_cycles_per_sec());
}

#if !defined(CONFIG_MULTITHREADING)

static uint32_t ticks_fired(void)
{
	return s_fired;
}

static void floor_wfi(void)
{
	struct path_run run;

	path_start(&run, NULL);
	do {
		kit_tick_idle_until(ticks_fired, run.handled);
	} while (path_take(&run, k_cycle_get_32()));
	path_report("wfi", &run);
}

#else

/* The less urgent thread of the msgq path: the rtos model's tick thread is
 * the main thread at CONFIG_MAIN_THREAD_PRIORITY, its rate groups below it */
#define TAKER_PRIORITY (CONFIG_MAIN_THREAD_PRIORITY + 1)
#define TAKER_STACK 1024

K_SEM_DEFINE(s_tick_sem, 0, 1);
K_MSGQ_DEFINE(s_ticks, sizeof(uint32_t), 4, 4);
K_SEM_DEFINE(s_taker_done, 0, 1);
K_THREAD_STACK_DEFINE(s_taker_stack, TAKER_STACK);
static struct k_thread s_taker;
static struct path_run s_msgq_run;

static void give_tick(void)
{
	k_sem_give(&s_tick_sem);
}

static void floor_sem(void)
{
	struct path_run run;

	k_sem_reset(&s_tick_sem);
	path_start(&run, give_tick);
	do {
		while (s_fired == run.handled) {
			(void)k_sem_take(&s_tick_sem, K_FOREVER);
		}
	} while (path_take(&run, k_cycle_get_32()));
	path_report("sem", &run);
}

static void taker(void *a, void *b, void *c)
{
	ARG_UNUSED(a);
	ARG_UNUSED(b);
	ARG_UNUSED(c);
	uint32_t tick = 0U;
	bool more = true;

	while (more) {
		(void)k_msgq_get(&s_ticks, &tick, K_FOREVER);
		const uint32_t now = k_cycle_get_32();

		s_msgq_run.handled = tick;
		more = path_take(&s_msgq_run, now);
	}
	k_sem_give(&s_taker_done);
}

static void floor_msgq(void)
{
	k_sem_reset(&s_tick_sem);
	k_msgq_purge(&s_ticks);
	path_start(&s_msgq_run, give_tick);
	(void)k_thread_create(&s_taker, s_taker_stack, K_THREAD_STACK_SIZEOF(s_taker_stack), taker, NULL,
			      NULL, NULL, TAKER_PRIORITY, 0, K_NO_WAIT);
	uint32_t posted = 0U;

	/* The tick thread: one message per tick, until the taker has its samples */
	while (k_sem_take(&s_taker_done, K_NO_WAIT) != 0) {
		while (s_fired == posted) {
			(void)k_sem_take(&s_tick_sem, K_FOREVER);
		}
		if (k_msgq_put(&s_ticks, &posted, K_NO_WAIT) != 0) {
			s_msgq_run.missed++; /* the taker fell four ticks behind */
		}
		posted++;
	}
	path_report("msgq", &s_msgq_run);
}

#endif

int main(void)
{
#if !defined(CONFIG_MULTITHREADING)
	floor_wfi();
#else
	floor_sem();
	floor_msgq();
#endif
	printk("KIT END app=floor result=%s\n", s_failed ? "FAIL" : "PASS");
	return 0;
}

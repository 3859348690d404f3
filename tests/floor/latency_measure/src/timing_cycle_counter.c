/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Zephyr's timing API on the kernel's cycle counter (k_cycle_get_32(): on
 * Cortex-M, SysTick counted by the system timer driver), through the board
 * timing hooks CONFIG_BOARD_HAS_TIMING_FUNCTIONS selects. The counter is 32
 * bits; a difference is taken modulo 2^32, right for any span shorter than
 * the counter's wrap (about 6 minutes at 12 MHz). Reading it costs more than
 * reading DWT's CYCCNT (a driver call); the benchmark measures that cost and
 * subtracts it from its figures.
 */
#include <zephyr/kernel.h>
#include <zephyr/timing/timing.h>

void board_timing_init(void)
{
}

void board_timing_start(void)
{
}

void board_timing_stop(void)
{
}

timing_t board_timing_counter_get(void)
{
	return k_cycle_get_32();
}

uint64_t board_timing_cycles_get(volatile timing_t *const start, volatile timing_t *const end)
{
	return (uint32_t)((uint32_t)*end - (uint32_t)*start);
}

uint64_t board_timing_freq_get(void)
{
	return sys_clock_hw_cycles_per_sec();
}

uint64_t board_timing_cycles_to_ns(uint64_t cycles)
{
	return cycles * NSEC_PER_SEC / board_timing_freq_get();
}

uint64_t board_timing_cycles_to_ns_avg(uint64_t cycles, uint32_t count)
{
	return board_timing_cycles_to_ns(cycles) / count;
}

uint32_t board_timing_freq_get_mhz(void)
{
	return (uint32_t)(board_timing_freq_get() / 1000000U);
}

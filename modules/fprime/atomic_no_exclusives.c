/* SPDX-License-Identifier: Apache-2.0 */
/*
 * std::atomic on a core without exclusive access (ARMv6-M, ARMv8-M
 * Baseline: Cortex-M0, M0+, M1, M23). GCC has no ldrex/strex there, so it
 * compiles every read-modify-write of a std::atomic (F´'s Os::Stub::Mutex,
 * the kit's link counters) into a call to libatomic's __atomic_<op>_<size>,
 * and the bare-metal toolchain ships no libatomic. These are those calls,
 * for objects of 1, 2 and 4 bytes (aligned loads and stores need none: GCC
 * inlines them), each atomic because it runs with interrupts locked: the
 * parts concerned are single-core. Built only for them (CMakeLists.txt) and
 * without link-time optimization, since the calls are made by code
 * generation after LTO has decided which symbols are used.
 */
#include <stdbool.h>
#include <string.h>

#include <zephyr/irq.h>

#define KIT_ATOMIC_RMW(NAME, SIZE, TYPE, OLD_OR_NEW, EXPR)                                              \
	TYPE __atomic_##NAME##_##SIZE(volatile void *object, TYPE operand, int order)                      \
	{                                                                                                  \
		volatile TYPE *const at = (volatile TYPE *)object;                                          \
		const unsigned int key = irq_lock();                                                       \
		const TYPE old = *at;                                                                      \
		const TYPE new = (TYPE)(EXPR);                                                             \
		*at = new;                                                                                 \
		irq_unlock(key);                                                                           \
		(void)order;                                                                               \
		return OLD_OR_NEW;                                                                         \
	}

#define KIT_ATOMIC_SIZE(SIZE, TYPE)                                                                     \
	KIT_ATOMIC_RMW(exchange, SIZE, TYPE, old, operand)                                                 \
	KIT_ATOMIC_RMW(fetch_add, SIZE, TYPE, old, old + operand)                                          \
	KIT_ATOMIC_RMW(fetch_sub, SIZE, TYPE, old, old - operand)                                          \
	KIT_ATOMIC_RMW(fetch_and, SIZE, TYPE, old, old & operand)                                          \
	KIT_ATOMIC_RMW(fetch_or, SIZE, TYPE, old, old | operand)                                           \
	KIT_ATOMIC_RMW(fetch_xor, SIZE, TYPE, old, old ^ operand)                                          \
	KIT_ATOMIC_RMW(add_fetch, SIZE, TYPE, new, old + operand)                                          \
	KIT_ATOMIC_RMW(sub_fetch, SIZE, TYPE, new, old - operand)                                          \
	KIT_ATOMIC_RMW(and_fetch, SIZE, TYPE, new, old & operand)                                          \
	KIT_ATOMIC_RMW(or_fetch, SIZE, TYPE, new, old | operand)                                           \
	KIT_ATOMIC_RMW(xor_fetch, SIZE, TYPE, new, old ^ operand)                                          \
	bool __atomic_compare_exchange_##SIZE(volatile void *object, void *expected, TYPE desired,         \
					      bool weak, int success, int failure)                         \
	{                                                                                                  \
		volatile TYPE *const at = (volatile TYPE *)object;                                          \
		TYPE wanted;                                                                               \
		memcpy(&wanted, expected, sizeof(wanted));                                                 \
		const unsigned int key = irq_lock();                                                       \
		const TYPE found = *at;                                                                    \
		const bool same = (found == wanted);                                                       \
		if (same) {                                                                                \
			*at = desired;                                                                     \
		}                                                                                          \
		irq_unlock(key);                                                                           \
		if (!same) {                                                                               \
			memcpy(expected, &found, sizeof(found));                                           \
		}                                                                                          \
		(void)weak;                                                                                \
		(void)success;                                                                             \
		(void)failure;                                                                             \
		return same;                                                                               \
	}

/* The types GCC declares these built-ins with (uint32_t is unsigned long here) */
KIT_ATOMIC_SIZE(1, unsigned char)
KIT_ATOMIC_SIZE(2, unsigned short)
KIT_ATOMIC_SIZE(4, unsigned int)

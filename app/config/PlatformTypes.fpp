# SPDX-License-Identifier: Apache-2.0
# Integer types for a 32-bit microcontroller. fprime-zephyr's platform sizes
# everything in 64 bits; on a Cortex-M3 every 64-bit division is a library
# call, and fprime-baremetal's TaskRunner takes one per task-table slot on
# every pass (100 slots): that alone cost 1.5 ms per pass, more than the 1 kHz
# period. 32 bits covers every size on a 64 KiB-RAM board.

@ Sizes (buffers, counts); unsigned
type PlatformSizeType = U32

@ Signed offsets
type PlatformSignedSizeType = I32

@ Small indices (ports, arrays); signed
type PlatformIndexType = I16

type PlatformAssertArgType = I32

@ Task priorities, F´ convention: higher is more urgent
type PlatformTaskPriorityType = U8

type PlatformTaskIdType = I32

type PlatformQueuePriorityType = U8

# SPDX-License-Identifier: Apache-2.0
# QEMU runs it as qemu_cortex_m3 (the same machine, lm3s6965evb)
include(${ZEPHYR_BASE}/boards/qemu/cortex_m3/board.cmake)

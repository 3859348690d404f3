// SPDX-License-Identifier: Apache-2.0
// The fake kernel's state (fake/zephyr/kernel.h): a 1 MHz cycle counter, so
// that one cycle is one microsecond and the Kconfig bounds read as cycles
#include <zephyr/kernel.h>

namespace KitFake {
uint32_t cycles = 0;
int cyclesPerSecond = 1000000;
bool inIsr = false;
}  // namespace KitFake

// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Scenarios.cpp
// \brief  Every scenario by name, and the choice of the one a run plays
//
// A build holds every scenario, so that one build per execution model and
// board serves the whole suite (tests/deployment): with
// CONFIG_KIT_SCENARIO_AT_BOOT the firmware prints its SELECT line and
// reads the scenario's name from the console, one line, before anything
// else runs, then restarts into it; without it, it plays
// CONFIG_KIT_SCENARIO at once.
//
// Why the restart: under QEMU icount, the wait for the console line lasts a
// virtual time that depends on the host, and what follows it would run at a
// different phase of every clock each time (the timing samples, and their
// hash, would differ run to run). A reset restarts the machine's clocks
// with the firmware; the name waits in RAM the startup code leaves alone
// (__noinit), so the scenario runs exactly as a build made for it does.
// ======================================================================
#include <Fw/Types/Assert.hpp>
#include "app/scenarios/Scenario.hpp"

#include <zephyr/device.h>
#include <zephyr/drivers/uart.h>
#include <zephyr/kernel.h>
#include <zephyr/linker/section_tags.h>
#include <zephyr/sys/printk.h>
#include <zephyr/sys/reboot.h>
#include <zephyr/sys/util.h>

#include <cstring>

namespace Kit {
namespace Scenario {

namespace {

struct Entry {
    const char* name;  //!< its file's name in app/scenarios/ and its name on the console
    Play play;
};

constexpr Entry SCENARIOS[] = {
    {"nominal", playNominal},
    {"load", playLoad},
    {"faults", playFaults},
    {"soak", playSoak},
    {"stack_overflow", playStackOverflow},
    {"assert", playAssert},
    {"ground", playGround},
};

// The longest script a scenario plays (faults.cpp)
constexpr FwSizeType SCRIPT_CAPACITY = 10;
Uplink::Frame s_script[SCRIPT_CAPACITY];

Play byName(const char* name) {
    for (const Entry& entry : SCENARIOS) {
        if (std::strcmp(entry.name, name) == 0) {
            return entry.play;
        }
    }
    return nullptr;
}

// One line from the console, polled (the baremetal model has no threads to
// block): characters past the buffer are dropped, and the name is then
// refused as unknown
void readLine(char* line, FwSizeType capacity) {
    const struct device* const console = DEVICE_DT_GET(DT_CHOSEN(zephyr_console));
    FwSizeType length = 0;
    bool truncated = false;
    // Waits for the ground's (or the test's) line, as long as it takes: no
    // bound, like the ground scenario's service loop
    for (;;) {
        unsigned char c = 0;
        if (uart_poll_in(console, &c) != 0) {
            continue;
        }
        if (c == '\n' || c == '\r') {
            if (length > 0 || truncated) {
                break;
            }
            continue;  // the \n of a \r\n, or an empty line
        }
        if (length + 1 < capacity) {
            line[length++] = static_cast<char>(c);
        } else {
            truncated = true;
        }
    }
    line[truncated ? 0 : length] = '\0';
}

constexpr U32 CHOSEN_MAGIC = 0x4B495453u;  // "KITS"
constexpr FwSizeType NAME_CAPACITY = 24;

// The name read before the restart, for the boot after it
struct Chosen {
    U32 magic;
    char name[NAME_CAPACITY];
};
__noinit Chosen s_chosen;

// The scenario a restart was asked for (taken once), or nullptr
Play takeChosen() {
    if (s_chosen.magic != CHOSEN_MAGIC) {
        return nullptr;
    }
    s_chosen.magic = 0;
    s_chosen.name[NAME_CAPACITY - 1] = '\0';
    const Play play = byName(s_chosen.name);
    if (play != nullptr) {
        printk("KIT SCENARIO name=%s\n", s_chosen.name);
    }
    return play;
}

}  // namespace

Play choose() {
    if (!IS_ENABLED(CONFIG_KIT_SCENARIO_AT_BOOT)) {
        const Play play = byName(CONFIG_KIT_SCENARIO);
        FW_ASSERT(play != nullptr);
        return play;
    }
    const Play chosen = takeChosen();
    if (chosen != nullptr) {
        return chosen;
    }
    char line[NAME_CAPACITY];
    for (;;) {
        printk("KIT SELECT scenarios=");
        for (FwSizeType i = 0; i < FW_NUM_ARRAY_ELEMENTS(SCENARIOS); i++) {
            printk("%s%s", (i > 0) ? "," : "", SCENARIOS[i].name);
        }
        printk(" (send one name and a newline)\n");
        readLine(line, sizeof line);
        const Play play = byName(line);
        if (play != nullptr) {
            s_chosen.magic = CHOSEN_MAGIC;
            (void)std::memcpy(s_chosen.name, line, sizeof s_chosen.name);
            printk("KIT SELECT chosen=%s (restarting into it)\n", line);
            sys_reboot(SYS_REBOOT_COLD);
        }
        printk("KIT SELECT unknown=%s\n", line[0] != '\0' ? line : "(too long)");
    }
}

void resumeAfterRestart() {
    // The name this boot took is still there (takeChosen cleared the magic
    // only); a build that does not ask plays its own scenario anyway
    if (IS_ENABLED(CONFIG_KIT_SCENARIO_AT_BOOT) && byName(s_chosen.name) != nullptr) {
        s_chosen.magic = CHOSEN_MAGIC;
    }
}

Uplink::Frame* scriptFrames(FwSizeType count) {
    FW_ASSERT(count <= SCRIPT_CAPACITY, static_cast<FwAssertArgType>(count));
    return s_script;
}

}  // namespace Scenario
}  // namespace Kit

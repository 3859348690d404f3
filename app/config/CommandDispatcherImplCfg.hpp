// SPDX-License-Identifier: Apache-2.0
// Dispatch table: one entry per registered opcode (the kit has ~20).
// Sequence tracking: commands in flight from the uplink at once.
#ifndef CMDDISPATCHER_COMMANDDISPATCHERIMPLCFG_HPP_
#define CMDDISPATCHER_COMMANDDISPATCHERIMPLCFG_HPP_

enum {
    CMD_DISPATCHER_DISPATCH_TABLE_SIZE = 32,
    CMD_DISPATCHER_SEQUENCER_TABLE_SIZE = 4,
};

#endif

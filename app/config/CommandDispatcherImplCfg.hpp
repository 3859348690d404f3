// SPDX-License-Identifier: Apache-2.0
// Dispatch table: one entry per registered opcode. The dictionary has 16
// commands, and the table holds exactly those (`scripts/kit sizing`: 32
// entries left 16 spare, 12 B each, 192 B). The dispatcher asserts at
// registration when a command has no entry, so a new command needs a larger
// table: `scripts/kit test` says so first, from the build's dictionary
// (kittools.sizes.sizing), before anything boots.
// Sequence tracking: commands in flight from the uplink at once.
#ifndef CMDDISPATCHER_COMMANDDISPATCHERIMPLCFG_HPP_
#define CMDDISPATCHER_COMMANDDISPATCHERIMPLCFG_HPP_

enum {
#if defined(CONFIG_KIT_SERVICE_CDH)
    CMD_DISPATCHER_DISPATCH_TABLE_SIZE = 21,  //!< Svc.Health's 3 and Svc.Version's 2 among them
#else
    CMD_DISPATCHER_DISPATCH_TABLE_SIZE = 16,
#endif
    CMD_DISPATCHER_SEQUENCER_TABLE_SIZE = 4,
};

#endif

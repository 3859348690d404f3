// SPDX-License-Identifier: Apache-2.0
// Dispatch table: one entry per registered opcode, and exactly the
// dictionary's commands (`scripts/kit sizing`: 32 entries for 16 commands
// left 16 spare, 12 B each, 192 B). The dispatcher asserts at
// registration when a command has no entry (CommandDispatcherImpl.cpp:47,
// at boot), so the build fails first when the table is smaller than its
// dictionary's commands (app/src/DictionaryChecks.cpp). The deployment's
// share is a Kconfig setting (CONFIG_KIT_DEPLOYMENT_COMMANDS, app/Kconfig:
// the reference's by default, another deployment's in its
// deployment.conf); each optional service adds its own commands here.
// Sequence tracking: commands in flight from the uplink at once.
#ifndef CMDDISPATCHER_COMMANDDISPATCHERIMPLCFG_HPP_
#define CMDDISPATCHER_COMMANDDISPATCHERIMPLCFG_HPP_

enum {
    //! The deployment's own and the kit's instruments' (app/Kconfig)
    KIT_DEPLOYMENT_COMMANDS = CONFIG_KIT_DEPLOYMENT_COMMANDS,
#if defined(CONFIG_KIT_SERVICE_CDH)
    KIT_CDH_COMMANDS = 5,  //!< Svc.Health's 3 and Svc.Version's 2
#else
    KIT_CDH_COMMANDS = 0,
#endif
#if defined(CONFIG_KIT_SERVICE_PARAMS)
    KIT_PARAM_COMMANDS = 3,  //!< Svc.PrmDb's
#else
    KIT_PARAM_COMMANDS = 0,
#endif
#if defined(CONFIG_KIT_SERVICE_FILES)
    KIT_FILE_COMMANDS = 3,  //!< Svc.FileDownlink's
#else
    KIT_FILE_COMMANDS = 0,
#endif
#if defined(CONFIG_KIT_SERVICE_SEQUENCER)
    KIT_SEQUENCER_COMMANDS = 8,  //!< Svc.CmdSequencer's
#else
    KIT_SEQUENCER_COMMANDS = 0,
#endif
    CMD_DISPATCHER_DISPATCH_TABLE_SIZE =
        KIT_DEPLOYMENT_COMMANDS + KIT_CDH_COMMANDS + KIT_PARAM_COMMANDS + KIT_FILE_COMMANDS + KIT_SEQUENCER_COMMANDS,
    CMD_DISPATCHER_SEQUENCER_TABLE_SIZE = 4,
};

#endif

// SPDX-License-Identifier: Apache-2.0
// TlmChan keeps two copies (double buffer) of a hash table of telemetry
// entries. F´'s default (500 buckets) is about half a megabyte. A bucket is
// taken the first time a channel is written and never given back, and TlmChan
// asserts when it needs one more than it has: the bucket count must cover
// every channel of the dictionary. The deployment's share is a Kconfig
// setting (CONFIG_KIT_DEPLOYMENT_CHANNELS, app/Kconfig: the reference's 42
// by default, which the ground link brought past the 32 this once held,
// unnoticed until the sizing advice counted them); the passive forms of the
// rate groups and the dispatcher and each optional service change it here.
// The build fails when its dictionary has more channels than buckets
// (app/src/DictionaryChecks.cpp). The slots only spread the search: fewer
// than the components with channels (13) costs time, not correctness.
#ifndef TLMCHANIMPLCFG_HPP_
#define TLMCHANIMPLCFG_HPP_

namespace {
enum {
#if defined(CONFIG_KIT_SERVICE_CDH)
    CDH_CHANNELS = 23,  //!< Svc.Health's 1 and Svc.Version's 22 (app/Top/services/)
#else
    CDH_CHANNELS = 0,
#endif
#if defined(CONFIG_KIT_SERVICE_FILE_UPLINK)
    FILE_CHANNELS = 6,  //!< Svc.FileDownlink's 3 and Svc.FileUplink's 3 (app/Top/services/)
#elif defined(CONFIG_KIT_SERVICE_FILES)
    FILE_CHANNELS = 3,  //!< Svc.FileDownlink's (app/Top/services/)
#else
    FILE_CHANNELS = 0,
#endif
#if defined(CONFIG_KIT_SERVICE_SEQUENCER)
    SEQUENCER_CHANNELS = 5,  //!< Svc.CmdSequencer's (app/Top/services/)
#else
    SEQUENCER_CHANNELS = 0,
#endif
    SERVICE_CHANNELS = CDH_CHANNELS + FILE_CHANNELS + SEQUENCER_CHANNELS,
};
enum {
    TLMCHAN_NUM_TLM_HASH_SLOTS = 8,  //!< Slots in the hash table
    TLMCHAN_HASH_MOD_VALUE = 8,      //!< Modulo of the hashing function
// F´'s PassiveRateGroup has three channels, ActiveRateGroup two: one more
// per rate group (three in the reference and tests/team/Thermal; the build's
// check catches another count). PassiveCmdDispatcher has none,
// CommandDispatcher three.
#if defined(CONFIG_KIT_RATE_GROUPS_PASSIVE) && defined(CONFIG_KIT_CMD_DISPATCHER_PASSIVE)
    TLMCHAN_HASH_BUCKETS = CONFIG_KIT_DEPLOYMENT_CHANNELS + SERVICE_CHANNELS,
#elif defined(CONFIG_KIT_RATE_GROUPS_PASSIVE)
    TLMCHAN_HASH_BUCKETS = CONFIG_KIT_DEPLOYMENT_CHANNELS + 3 + SERVICE_CHANNELS,
#elif defined(CONFIG_KIT_CMD_DISPATCHER_PASSIVE)
    TLMCHAN_HASH_BUCKETS = CONFIG_KIT_DEPLOYMENT_CHANNELS - 3 + SERVICE_CHANNELS,
#else
    TLMCHAN_HASH_BUCKETS = CONFIG_KIT_DEPLOYMENT_CHANNELS + SERVICE_CHANNELS,
#endif
};
}  // namespace

#endif

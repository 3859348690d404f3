// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// The fixed tables that must hold an entry for each of the dictionary's
// commands or channels, checked against this build's dictionary (its
// counts: app/dictionary_header.cmake) when the build compiles, not when
// the firmware boots:
// - F´'s command dispatchers (CommandDispatcher, and fprime-baremetal's
//   PassiveCmdDispatcher) assert when a command registers past their
//   table, at boot;
// - F´'s parameter database refuses a parameter past its table (its
//   PrmDbFull event), and the component then runs on its default;
// - F´'s telemetry stores (TlmChan, fprime-baremetal's TlmLinearChan)
//   assert the first time a channel is written past their buckets, at
//   any time of a run.
// A deployment that fails here raises its share in its deployment.conf
// (CONFIG_KIT_DEPLOYMENT_COMMANDS, CONFIG_KIT_DEPLOYMENT_CHANNELS,
// CONFIG_KIT_DEPLOYMENT_PARAMETERS:
// app/Kconfig); the compiler's note gives both counts. `scripts/kit
// sizing <build>` gives the spare entries and what they cost.
// ======================================================================
#include <config/CommandDispatcherImplCfg.hpp>
#include <config/PrmDbImplCfg.hpp>
#include <config/TlmChanImplCfg.hpp>

#include "KitDictionary.hpp"  // generated: app/dictionary_header.cmake

static_assert(CMD_DISPATCHER_DISPATCH_TABLE_SIZE >= KIT_DICTIONARY_COMMANDS,
              "the command dispatch table (CMD_DISPATCHER_DISPATCH_TABLE_SIZE) is smaller than the dictionary's "
              "commands: raise CONFIG_KIT_DEPLOYMENT_COMMANDS in the deployment's deployment.conf (app/Kconfig)");
static_assert(TLMCHAN_HASH_BUCKETS >= KIT_DICTIONARY_CHANNELS - VERSION_SILENT_CHANNELS,
              "the telemetry buckets (TLMCHAN_HASH_BUCKETS) are fewer than the dictionary's channels this build "
              "can write (all but Svc.Version's silent ones: app/config/TlmChanImplCfg.hpp.in): raise "
              "CONFIG_KIT_DEPLOYMENT_CHANNELS in the deployment's deployment.conf (app/Kconfig)");
static_assert(PRMDB_NUM_DB_ENTRIES >= KIT_DICTIONARY_PARAMETERS,
              "the parameter database (PRMDB_NUM_DB_ENTRIES) is smaller than the dictionary's parameters: raise "
              "CONFIG_KIT_DEPLOYMENT_PARAMETERS in the deployment's deployment.conf (app/Kconfig)");

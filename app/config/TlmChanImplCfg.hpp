// SPDX-License-Identifier: Apache-2.0
// TlmChan keeps two copies (double buffer) of a hash table of telemetry
// entries. F´'s default (500 buckets) is about half a megabyte; the kit has
// fewer than 32 channels, and the bucket count must cover all of them.
#ifndef TLMCHANIMPLCFG_HPP_
#define TLMCHANIMPLCFG_HPP_

namespace {
enum {
    TLMCHAN_NUM_TLM_HASH_SLOTS = 8,  //!< Slots in the hash table
    TLMCHAN_HASH_MOD_VALUE = 8,      //!< Modulo of the hashing function
    TLMCHAN_HASH_BUCKETS = 32        //!< Buckets: at least the number of channels
};
}

#endif

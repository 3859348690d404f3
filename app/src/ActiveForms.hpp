// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  ActiveForms.hpp
// \brief  The tasks the rate groups and the dispatcher take in the form the
//         execution model chose (CONFIG_KIT_RATE_GROUPS_PASSIVE,
//         CONFIG_KIT_CMD_DISPATCHER_PASSIVE): one rule for every
//         deployment's count of active instances
// ======================================================================
#ifndef KIT_ACTIVEFORMS_HPP
#define KIT_ACTIVEFORMS_HPP

#include <Fw/FPrimeBasicTypes.hpp>

namespace Kit {

//! Tasks of `groups` rate groups: none where they are passive (called in the tick)
constexpr FwSizeType activeRateGroups(FwIndexType groups) {
#if defined(CONFIG_KIT_RATE_GROUPS_PASSIVE)
    (void)groups;
    return 0;
#else
    return static_cast<FwSizeType>(groups);
#endif
}

//! The dispatcher's task: none where it is passive (dispatched in its sender's call)
#if defined(CONFIG_KIT_CMD_DISPATCHER_PASSIVE)
constexpr FwSizeType ACTIVE_DISPATCHERS = 0;
#else
constexpr FwSizeType ACTIVE_DISPATCHERS = 1;
#endif

}  // namespace Kit

#endif

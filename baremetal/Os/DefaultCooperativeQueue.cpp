// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  DefaultCooperativeQueue.cpp
// \brief  Os::Queue is the kit's cooperative queue (F´ links its delegate)
//
// Apart from CooperativeQueue.cpp, as F´ keeps its own Default*.cpp: the
// host tests (baremetal/Os/test/ut) link the queue into a program whose
// Os::Queue is F´'s generic one.
// ======================================================================
#include "baremetal/Os/CooperativeQueue.hpp"

#include <Os/Delegate.hpp>

namespace Os {

QueueInterface* QueueInterface::getDelegate(QueueHandleStorage& aligned_new_memory) {
    return Os::Delegate::makeDelegate<QueueInterface, Kit::CooperativeQueue, QueueHandleStorage>(aligned_new_memory);
}

}  // namespace Os

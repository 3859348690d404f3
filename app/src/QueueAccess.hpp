// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  QueueAccess.hpp
// \brief  An active or queued component's message queue, read by the kit
//
// F´ keeps a component's message queue protected
// (Fw::QueuedComponentBase::m_queue) and has no accessor for it; a member
// pointer formed in a derived class's scope reads it, without changing F´.
// Never instantiated.
// ======================================================================
#ifndef KIT_QUEUEACCESS_HPP
#define KIT_QUEUEACCESS_HPP

#include <Fw/Comp/ActiveComponentBase.hpp>
#include <Os/Queue.hpp>

namespace Kit {

struct QueueOf : Fw::QueuedComponentBase {
    static const Os::Queue& of(const Fw::QueuedComponentBase& component) { return component.*(&QueueOf::m_queue); }
    // F´'s count of messages its `drop` ports lost: a protected accessor, and not const
    static FwSizeType dropped(const Fw::QueuedComponentBase& component) {
        return (const_cast<Fw::QueuedComponentBase&>(component).*(&QueueOf::getNumMsgsDropped))();
    }
};

}  // namespace Kit

#endif

// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Scenario.hpp
// \brief  What a run plays after setup: every build holds every scenario
//
// One file of app/scenarios/ per scenario, each defining its function
// below; Scenarios.cpp lists them by name and picks the one to play: the
// build's CONFIG_KIT_SCENARIO, or, with CONFIG_KIT_SCENARIO_AT_BOOT, the
// name the console sends at boot (the suite plays every scenario on one
// build that way). Every scenario drives the same deployment through
// Session (ticks), the uplink (commands, as a ground system would send
// them) and Report (the console record).
// ======================================================================
#ifndef KIT_SCENARIO_HPP
#define KIT_SCENARIO_HPP

#include <Fw/Types/Serializable.hpp>
#include "app/Components/Uplink/Uplink.hpp"
#include "app/src/CountingAllocator.hpp"

namespace Kit {
namespace Scenario {

struct Context {
    U32 probeCost;                       //!< the timing probe's cycles per rate-group cycle
    const CountingAllocator& allocator;  //!< F´'s allocator
};

//! A scenario plays and prints its record; true when every check passed
using Play = bool (*)(const Context& context);

bool playNominal(const Context& context);        //!< nominal.cpp
bool playLoad(const Context& context);           //!< load.cpp
bool playFaults(const Context& context);         //!< faults.cpp
bool playSoak(const Context& context);           //!< soak.cpp
bool playStackOverflow(const Context& context);  //!< stack_overflow.cpp
bool playAssert(const Context& context);         //!< assert.cpp
bool playGround(const Context& context);         //!< ground.cpp

//! The scenario this run plays (Scenarios.cpp): the build's, or the one the
//! console names at boot
Play choose();

//! Before a warm restart the running deployment asks for (Faults.RESTART,
//! app/src/Restart.cpp): the boot after it plays the same scenario again
//! without asking the console, as a restart into a chosen scenario does
void resumeAfterRestart();

//! The uplink script's frames, `count` of them, in static storage all
//! scenarios share (one plays per boot): a local array of frames would cost
//! the main stack, which on baremetal is every task's
Uplink::Frame* scriptFrames(FwSizeType count);

//! Command arguments, serialized as F´ does (big-endian)
class Args {
  public:
    Args() : m_buffer(m_bytes, sizeof m_bytes) {}
    template <typename T>
    Args& add(T value) {
        const Fw::SerializeStatus status = m_buffer.serializeFrom(value);
        FW_ASSERT(status == Fw::FW_SERIALIZE_OK, status);
        return *this;
    }
    const U8* bytes() const { return m_bytes; }
    FwSizeType size() const { return m_buffer.getSize(); }

  private:
    U8 m_bytes[Uplink::FRAME_MAX];
    Fw::ExternalSerializeBuffer m_buffer;
};

//! A well-formed command frame with these arguments
inline Uplink::Frame command(U32 cycle, FwOpcodeType opcode, const Args& args) {
    return Uplink::commandFrame(cycle, opcode, args.bytes(), args.size());
}

}  // namespace Scenario
}  // namespace Kit

#endif

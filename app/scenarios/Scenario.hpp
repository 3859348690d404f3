// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Scenario.hpp
// \brief  What a run plays after setup: one scenario per build
//
// CONFIG_KIT_SCENARIO names the file of app/scenarios/ that implements
// run(); app/kit.cmake compiles that one. Every scenario drives the same
// deployment through Session (ticks), the uplink (commands, as a ground
// system would send them) and Report (the console record).
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

//! Play the scenario and print its record; true when every check passed
bool run(const Context& context);

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

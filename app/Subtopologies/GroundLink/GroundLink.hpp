// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  GroundLink.hpp
// \brief  Configure the kit's ground link (GroundLink.fpp) in any deployment
// ======================================================================
#ifndef KIT_GROUNDLINK_HPP
#define KIT_GROUNDLINK_HPP

#include <Fw/Comp/ActiveComponentBase.hpp>
#include "app/src/CountingAllocator.hpp"

namespace Kit {
namespace GroundLink {

//! Sizes the link's buffers, accumulator and queues from `allocator` (it
//! counts, so the link's share is measured) and opens the link UART
//! (asserts if the board's is not ready).
//! `takesFilePackets`: the deployment has a file uplink, so a buffer holds
//! a file packet's frame. `eventService`: the deployment's event service,
//! whose free queue slots LinkHealth keeps ground commands within.
void configure(CountingAllocator& allocator, bool takesFilePackets, const Fw::QueuedComponentBase& eventService);

//! Releases what configure() took (after the tasks stopped)
void cleanup();

//! Bytes of the F´ allocator the link took at configure() (BufferManager
//! pool, frame accumulator, ComQueue's packet queues)
FwSizeType bufferBytes();

//! The link UART's line rate (bits/s: its devicetree current-speed)
U32 baudRate();

//! The link UART's driver reports receive errors (uart_err_check)
bool uartErrorsReported();

}  // namespace GroundLink
}  // namespace Kit

#endif

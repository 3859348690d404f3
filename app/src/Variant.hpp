// ======================================================================
// \title  Variant.hpp
// \brief  What each execution model supplies to the shared main loop
//
// The whole baremetal-vs-RTOS difference in the main loop is these
// functions: baremetal/Variant.cpp and rtos/Variant.cpp implement them.
// ======================================================================
#ifndef KIT_VARIANT_HPP
#define KIT_VARIANT_HPP

#include <Fw/FPrimeBasicTypes.hpp>

namespace Kit {
namespace Variant {

//! "baremetal" or "rtos"
const char* name();

//! Called from the tick ISR after the tick is counted and stamped
void onTickIsr();

//! Return once more than `handled` ticks have fired (sleeping meanwhile)
void waitForTick(U32 handled);

//! After each tick has been handed to the rate group driver
void afterTick();

//! After the last tick: let queued work finish before results are read
void drain();

//! Before setup: prepare stack measurement (baremetal paints the main stack)
void prepareStacks();

//! Print a "KIT STACK" line per stack with its size and high-water mark
void reportStacks();

//! The high-water marks of all stacks, added up, in bytes
U32 stackUsedTotal();

//! The execution context running now, for a fatal report: the active
//! component whose thread it is (rtos), or "main" (baremetal)
const char* contextName();

//! Print a "KIT CPU" line per execution context (thread, or cooperative
//! task, and idle): runs, average and worst cycles per run, share of the
//! `runCycles` the run lasted
void reportCpu(U64 runCycles);

}  // namespace Variant
}  // namespace Kit

#endif

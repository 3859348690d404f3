// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Variant.hpp
// \brief  What each execution model supplies to the shared main loop
//
// The whole difference between the models in the main loop is these
// functions: <model>/Variant.cpp implements them (baremetal/Variant.cpp,
// rtos/Variant.cpp). The interface is one-way: a model hands data to app/
// (stacks, contexts, CPU time, a stack-guard breach) and never includes the
// topology or prints the record; app/src/Report.cpp alone formats it.
// ======================================================================
#ifndef KIT_VARIANT_HPP
#define KIT_VARIANT_HPP

#include <Fw/FPrimeBasicTypes.hpp>
// After F´'s headers: Zephyr's define names (EMPTY) that F´'s enums use
#include <zephyr/autoconf.h>

namespace Kit {
namespace Variant {

//! The most execution contexts (threads, cooperative tasks, idle) a model
//! reports: the topology's active instances plus the others (4: the main
//! thread, idle, rtos's assert report, room for a kernel work queue); the kit's
//! services have at most 12, a deployment that gives its count
//! (CONFIG_KIT_DEPLOYMENT_TASKS) its own
#if defined(CONFIG_KIT_DEPLOYMENT_OWN_TASKS)
constexpr U32 MAX_CONTEXTS = CONFIG_KIT_DEPLOYMENT_TASKS + 4;
#else
constexpr U32 MAX_CONTEXTS = 16;
#endif

//! What a model's execution contexts are, for the record ("context=")
enum class ContextKind : U8 {
    THREAD,  //!< a preemptive thread with a stack of its own
    SLICE,   //!< a cooperative task's slices, run from the one main loop
};

//! An execution context: app/ names it after the active component whose
//! object holds `owner` (F´ names its threads ActComp_<n> when object names
//! are compiled out), else by `name`
struct Context {
    const char* name;   //!< the context's own name ("main", "idle", Zephyr's thread name), or nullptr
    const void* owner;  //!< an address inside the component it runs (its task's argument), or nullptr
};

//! One stack and its high-water mark
struct StackUse {
    Context context;
    U32 size;  //!< bytes
    U32 used;  //!< bytes ever used
};

//! One execution context's CPU time over the run
struct CpuUse {
    Context context;
    U32 runs;       //!< scheduling windows (thread) or slices (cooperative)
    U32 avgCycles;  //!< per run
    U32 maxCycles;  //!< the longest run
    U64 cycles;     //!< in all
    //! A task run on the rtos model's shared thread (rtos/Os/SharedThread.hpp),
    //! whose own line holds its cycles too: "context=shared"
    bool shared = false;
};

//! How a time-budgeted cooperative policy treated one context (baremetal's
//! budgeted policy: baremetal/Os/BudgetedScheduler.hpp)
struct ScheduleUse {
    Context context;
    bool critical;          //!< cycle-locked: never deferred
    U32 anticipatedCycles;  //!< the slice time the policy anticipates now
    U32 deferrals;          //!< turns it did not fit before the next tick
    U32 expedited;          //!< slices run after too many deferrals, fit or not
    U32 late;               //!< slices that ended after the next tick was due
};

//! The policy's guard margin: now and the largest it reached
struct GuardMargin {
    U32 cycles;
    U32 maxCycles;
};

//! A stack guard that lost its paint (baremetal's detector; no MPU assumed)
struct GuardBreach {
    bool breached;
    U32 word;           //!< which guard word, from the bottom
    uintptr_t address;  //!< where it is
};

//! The kind of every context of this model
ContextKind contextKind();

//! Called from the tick ISR after the tick is counted and stamped
void onTickIsr();

//! Return once `ticksFired()` has moved past `handled` (sleeping meanwhile)
void waitForTick(U32 (*ticksFired)(), U32 handled);

//! After each tick has been handed to the rate group driver; `nextTickAt`
//! is the cycle count the next tick is due at (a policy that budgets its
//! work before it needs it). A breach means the run must stop
//! (app/src/Session.cpp halts it)
GuardBreach afterTick(U32 nextTickAt);

//! After the last tick: let queued work finish before results are read
GuardBreach drain();

//! The stack guard as it is now, running nothing: a fatal report asks, so a
//! fault that an overflow caused before the guard was checked is named one
GuardBreach guardState();

//! Before setup, after the deployment's objects are built: prepare the
//! stacks and their measurement (baremetal paints the main stack; rtos
//! provides the thread stacks and the thread that reports an assert)
void prepareStacks();

//! Every stack with its size and high-water mark; returns how many
U32 stacks(StackUse (&out)[MAX_CONTEXTS]);

//! Every execution context's CPU time (threads or cooperative tasks, and
//! idle); returns how many
U32 cpu(CpuUse (&out)[MAX_CONTEXTS]);

//! A budgeted policy's decisions per context and its guard margin; returns
//! how many contexts (0: the model does not budget its work)
U32 schedule(ScheduleUse (&out)[MAX_CONTEXTS], GuardMargin& guard);

//! The execution context running now, for a fatal report
Context currentContext();

//! The stack of the context running now (a fault's: the thread that took
//! it), for a fatal report: one entry, no table on the fault's stack
StackUse currentStack();

}  // namespace Variant
}  // namespace Kit

#endif

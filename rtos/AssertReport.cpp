// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  rtos/AssertReport.cpp
// \brief  An F´ assert's report, on a thread of its own
//
// F´ reports an assert on the thread that raised it: the deployment's hook
// (Svc.AssertFatalAdapter) formats its message, serializes its FATAL event
// and, through the event manager, calls the fatal handler, 1028 B beyond
// the assert (the dispatcher's stack at the assert scenario's halt,
// qemu_cortex_m3). Each thread's stack held 472 B beyond its high-water
// mark for it (app/Top/Tables.fpp): enough only for an assert raised
// 556 B or more above that mark; deeper, the report overflowed the stack.
// Here the report runs on this file's thread, whose stack is sized for it
// (CONFIG_KIT_ASSERT_STACK_SIZE), above every other: the asserting thread
// hands over its file, line and arguments and waits, at most 436 B beyond
// the assert. The deployment's own hook still makes the report, with the
// same arguments: this one steps aside (deregisterHook) and raises the
// assert again through Fw::SwAssert, on its own stack, then steps back in.
// So it works with whatever hook a deployment registers, F´'s or its own.
//
// The run halts either way (the fatal handler); what this changes is where
// the report's bytes are. The halt's "KIT STACK" line is then this
// thread's ("name=assert": the report's depth, which sizes its stack), and
// its "context=assert"; the assert's message names its file and line. An
// assert in an interrupt, or in the report itself, is reported where it is
// raised, as before.
// ======================================================================
#include "rtos/AssertReport.hpp"

#include <zephyr/kernel.h>
#include <Fw/Types/Assert.hpp>

namespace Kit {
namespace AssertReport {

namespace {

constexpr FwSizeType MAX_ARGS = 6;
static_assert(CONFIG_NUM_COOP_PRIORITIES > 0, "the assert report runs at a cooperative priority");

//! What the asserting thread hands over
struct Request {
    FILE_NAME_ARG file;
    FwSizeType lineNo;
    FwSizeType numArgs;
    FwAssertArgType args[MAX_ARGS];
};

class Relay final : public Fw::AssertHook {
  public:
    void reportAssert(FILE_NAME_ARG file,
                      FwSizeType lineNo,
                      FwSizeType numArgs,
                      FwAssertArgType arg1,
                      FwAssertArgType arg2,
                      FwAssertArgType arg3,
                      FwAssertArgType arg4,
                      FwAssertArgType arg5,
                      FwAssertArgType arg6) override;
    //! The deployment's hook took its action in the report (raiseAgain)
    void doAssert() override {}
};

K_THREAD_STACK_DEFINE(s_stack, CONFIG_KIT_ASSERT_STACK_SIZE);
struct k_thread s_thread;
K_MUTEX_DEFINE(s_oneAtATime);
K_SEM_DEFINE(s_requested, 0, 1);
K_SEM_DEFINE(s_reported, 0, 1);
Request s_request;
Relay s_relay;

//! The assert again, through F´'s own path, with this hook out of the way:
//! the deployment's hook reports it and takes its action here
void raiseAgain(const Request& request) {
    s_relay.deregisterHook();
    const FwAssertArgType* const a = request.args;
    switch (request.numArgs) {
        case 0:
            (void)Fw::SwAssert(request.file, request.lineNo);
            break;
        case 1:
            (void)Fw::SwAssert(request.file, a[0], request.lineNo);
            break;
        case 2:
            (void)Fw::SwAssert(request.file, a[0], a[1], request.lineNo);
            break;
        case 3:
            (void)Fw::SwAssert(request.file, a[0], a[1], a[2], request.lineNo);
            break;
        case 4:
            (void)Fw::SwAssert(request.file, a[0], a[1], a[2], a[3], request.lineNo);
            break;
        case 5:
            (void)Fw::SwAssert(request.file, a[0], a[1], a[2], a[3], a[4], request.lineNo);
            break;
        default:
            (void)Fw::SwAssert(request.file, a[0], a[1], a[2], a[3], a[4], a[5], request.lineNo);
            break;
    }
    s_relay.registerHook();
}

void reportLoop(void*, void*, void*) {
    // Bounded by the asserts raised: each request is one assert
    for (;;) {
        (void)k_sem_take(&s_requested, K_FOREVER);
        raiseAgain(s_request);
        k_sem_give(&s_reported);
    }
}

void Relay::reportAssert(FILE_NAME_ARG file,
                         FwSizeType lineNo,
                         FwSizeType numArgs,
                         FwAssertArgType arg1,
                         FwAssertArgType arg2,
                         FwAssertArgType arg3,
                         FwAssertArgType arg4,
                         FwAssertArgType arg5,
                         FwAssertArgType arg6) {
    const Request request = {
        file, lineNo, numArgs > MAX_ARGS ? MAX_ARGS : numArgs, {arg1, arg2, arg3, arg4, arg5, arg6}};
    // An interrupt cannot wait, and the report thread cannot hand over to
    // itself: both report where they are
    if (k_is_in_isr() || k_current_get() == &s_thread) {
        raiseAgain(request);
        return;
    }
    (void)k_mutex_lock(&s_oneAtATime, K_FOREVER);
    s_request = request;
    // The report thread is cooperative: it runs now, to the end of the
    // report (the fatal handler halts the run there)
    k_sem_give(&s_requested);
    (void)k_sem_take(&s_reported, K_FOREVER);
    (void)k_mutex_unlock(&s_oneAtATime);
}

}  // namespace

void start() {
    // The least urgent cooperative priority: above every thread of the
    // deployment and the tick, none of which can then preempt a report
    const k_tid_t tid = k_thread_create(&s_thread, s_stack, K_THREAD_STACK_SIZEOF(s_stack), reportLoop, nullptr,
                                        nullptr, nullptr, K_PRIO_COOP(CONFIG_NUM_COOP_PRIORITIES - 1), 0, K_NO_WAIT);
    (void)k_thread_name_set(tid, "assert");
    s_relay.registerHook();
}

}  // namespace AssertReport
}  // namespace Kit

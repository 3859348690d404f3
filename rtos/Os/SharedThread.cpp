// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  rtos/Os/SharedThread.cpp
// \brief  One thread for the active components of a band of F´ levels
// ======================================================================
#include <Fw/Comp/ActiveComponentBase.hpp>
#include <Fw/Types/Assert.hpp>
#include <atomic>
// After F´'s headers: Zephyr's define names (EMPTY) that F´'s enums use
#include "rtos/Os/PriorityMap.hpp"
#include "rtos/Os/SharedThread.hpp"
#include "rtos/Os/ZephyrQueue.hpp"

namespace Kit {
namespace SharedThread {

#if CONFIG_KIT_RTOS_SHARED_LEVEL_HIGH > 0

namespace {

//! An active component's protected parts that its own thread loop would
//! use: its queue, one message's dispatch, its preamble. Reached through
//! pointers to members named in a class derived from F´'s base, which
//! C++ allows; the class is never made.
struct Access : public Fw::ActiveComponentBase {
    static Os::Queue& queueOf(Fw::ActiveComponentBase& component) { return component.*(&Access::m_queue); }
    static MsgDispatchStatus dispatchOne(Fw::ActiveComponentBase& component) {
        return (component.*(&Access::dispatch))();
    }
    static void begin(Fw::ActiveComponentBase& component) { (component.*(&Access::preamble))(); }
};

struct Member {
    Fw::ActiveComponentBase* component = nullptr;
    Os::Queue* queue = nullptr;
    FwTaskPriorityType level = 0;
    bool begun = false;  //!< its preamble ran (the thread's)
    bool done = false;   //!< it took its exit message
    U32 runs = 0;
    U32 maxCycles = 0;
    U64 cycles = 0;
};

//! The most active components the thread takes (rtos/Kconfig.model)
constexpr U32 MAX_MEMBERS = CONFIG_KIT_RTOS_SHARED_MEMBERS;

Member s_members[MAX_MEMBERS];
//! Members are added (by the thread starting the topology) while the
//! thread may read the table: an entry is whole before the count shows it
std::atomic<U32> s_count{0};
//! Given by every member's queue after a send, and by each join
K_SEM_DEFINE(s_work, 0, 1);
struct k_thread s_thread;
//! Where the next search starts: members of one level take turns
U32 s_next = 0;
bool s_running = false;

//! The most urgent member with a message, or nullptr
Member* mostUrgentWithWork(U32 count) {
    Member* best = nullptr;
    for (U32 step = 0; step < count; step++) {
        Member& member = s_members[(s_next + step) % count];
        if (member.done || member.queue->getMessagesAvailable() == 0) {
            continue;
        }
        if (best == nullptr || member.level > best->level) {
            best = &member;
        }
    }
    return best;
}

//! This thread's own cycles so far (its runtime statistics: a preempting
//! thread's cycles are not in them)
U64 ownCycles() {
    k_thread_runtime_stats_t stats = {};
    (void)k_thread_runtime_stats_get(&s_thread, &stats);
    return stats.execution_cycles;
}

void dispatch(Member& member) {
    const U64 before = ownCycles();
    const Fw::ActiveComponentBase::MsgDispatchStatus status = Access::dispatchOne(*member.component);
    const U64 spent = ownCycles() - before;
    member.runs++;
    member.cycles += spent;
    member.maxCycles = spent > member.maxCycles ? static_cast<U32>(spent) : member.maxCycles;
    if (status == Fw::ActiveComponentBase::MsgDispatchStatus::MSG_DISPATCH_EXIT) {
        member.done = true;  // as its own thread would have ended
    }
}

void run(void* unused1, void* unused2, void* unused3) {
    (void)unused1;
    (void)unused2;
    (void)unused3;
    for (;;) {
        (void)k_sem_take(&s_work, K_FOREVER);
        const U32 count = s_count.load(std::memory_order_acquire);
        for (U32 i = 0; i < count; i++) {
            if (!s_members[i].begun) {
                s_members[i].begun = true;
                Access::begin(*s_members[i].component);
            }
        }
        // Until every member's queue is empty, one message at a time: a send
        // meanwhile gives the semaphore again, so none is left behind
        for (Member* next = mostUrgentWithWork(count); next != nullptr; next = mostUrgentWithWork(count)) {
            s_next = static_cast<U32>((next - s_members) + 1) % count;
            dispatch(*next);
        }
    }
}

}  // namespace

void start(k_thread_stack_t* stack, size_t size) {
    FW_ASSERT(enabled());
    const int priority =
        zephyrPriority(CONFIG_KIT_RTOS_SHARED_LEVEL_HIGH, CONFIG_NUM_PREEMPT_PRIORITIES, CONFIG_MAIN_THREAD_PRIORITY);
    FW_ASSERT(priority >= 0, CONFIG_KIT_RTOS_SHARED_LEVEL_HIGH);
    (void)k_thread_create(&s_thread, stack, size, run, nullptr, nullptr, nullptr, priority, 0, K_NO_WAIT);
    (void)k_thread_name_set(&s_thread, "services");
    s_running = true;
}

bool running() {
    return s_running;
}

Os::TaskInterface::Status join(const Os::TaskInterface::Arguments& arguments) {
    // Os::Task hands its delegate its own wrapper around the routine; an
    // active component's routine takes the component (F´'s
    // ActiveComponentBase::start), the only kind of task the kit starts
    FW_ASSERT(arguments.m_routine == &Os::Task::TaskRoutineWrapper::run);
    const Os::Task::TaskRoutineWrapper* const wrapper =
        static_cast<const Os::Task::TaskRoutineWrapper*>(arguments.m_routine_argument);
    FW_ASSERT(wrapper != nullptr && wrapper->m_user_argument != nullptr);
    const U32 count = s_count.load(std::memory_order_relaxed);
    FW_ASSERT(count < MAX_MEMBERS, static_cast<FwAssertArgType>(count));
    Member& member = s_members[count];
    member.component = static_cast<Fw::ActiveComponentBase*>(wrapper->m_user_argument);
    member.queue = &Access::queueOf(*member.component);
    member.level = arguments.m_priority;
    // The kit's queue (CONFIG_KIT_QUEUE_KIT, checked in rtos/ModelChecks.cpp)
    // gives this thread's semaphore after each send
    static_cast<ZephyrQueueHandle*>(member.queue->getHandle())->m_listener = &s_work;
    s_count.store(count + 1, std::memory_order_release);
    // Its preamble, and any message sent before the listener was set
    k_sem_give(&s_work);
    return Os::TaskInterface::Status::OP_OK;
}

U32 memberCount() {
    return s_count.load(std::memory_order_acquire);
}

MemberUse memberUse(U32 index) {
    FW_ASSERT(index < memberCount(), static_cast<FwAssertArgType>(index));
    const Member& member = s_members[index];
    return {member.component, member.runs, member.maxCycles, member.cycles};
}

#else  // No shared thread: none of its RAM, and nothing may join it

void start(k_thread_stack_t* stack, size_t size) {
    (void)stack;
    (void)size;
    FW_ASSERT(0);
}

Os::TaskInterface::Status join(const Os::TaskInterface::Arguments& arguments) {
    (void)arguments;
    FW_ASSERT(0);
    return Os::TaskInterface::Status::INVALID_PARAMS;
}

bool running() {
    return false;
}

U32 memberCount() {
    return 0;
}

MemberUse memberUse(U32 index) {
    FW_ASSERT(0, static_cast<FwAssertArgType>(index));
    return {nullptr, 0, 0, 0};
}

#endif

}  // namespace SharedThread
}  // namespace Kit

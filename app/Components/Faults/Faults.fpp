# SPDX-License-Identifier: Apache-2.0

module Kit {

    @ Fault injection by command, so one build exercises every detection:
    @ an overrun of a rate group, a stack overflow of the commanding context
    @ and an F´ assert. A member of every rate group (before the timing probe's
    @ end record), where an armed overrun runs.
    passive component Faults {

        @ Rate group member (port index = rate group index)
        sync input port schedIn: [RateGroupDriverRateGroupPorts] Svc.Sched

        import Fw.Command
        import Fw.Event
        time get port timeCaller

        @ The next cycle of a rate group computes this much longer
        sync command OVERRUN(
            rateGroup: U8 @< Rate group index (0 is the fastest)
            us: U32 @< Extra computation, at most OVERRUN_MAX_US
        ) opcode 0

        @ Use this many bytes of the commanding context's stack (the command
        @ dispatcher's thread on rtos, the one main stack on baremetal)
        sync command STACK_OVERFLOW(
            $bytes: U32 @< Stack to use, at most STACK_MAX_BYTES
        ) opcode 1

        @ Fail an F´ assert in the command handler
        sync command ASSERT(
            code: U32 @< Reported as the assert's argument
        ) opcode 2

        event OverrunInjected(rateGroup: U8, us: U32) severity warning low id 0 format "Rate group {} overran by {} us (injected)"

        event StackOverflowInjected($bytes: U32) severity warning high id 1 format "Using {} bytes of stack (injected)"

        event InjectionRejected(value: U32, limit: U32) severity warning low id 2 format "Fault injection value {} is above its limit {}"
    }
}

# SPDX-License-Identifier: Apache-2.0

module Kit {

    @ How CORRUPT_FILE damages a file
    enum FileDamage : U8 {
        TRUNCATE  @< keep the file's first `offset` bytes
        FLIP      @< invert every bit of the byte at `offset`
    }

    @ Fault injection by command, so one build exercises every detection:
    @ an overrun of a rate group, a stack overflow of the commanding context,
    @ an F´ assert, a damaged file and a warm restart. A member of every rate
    @ group (before the timing probe's end record), where an armed overrun
    @ runs and an armed restart counts down (the slowest group).
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

        @ Damage a file in place, as a bad write or a radiation hit would
        @ (TRUNCATE keeps at most TRUNCATE_MAX_BYTES)
        sync command CORRUPT_FILE(
            file: string size FileNameStringSize @< The file's path
            damage: FileDamage @< What to do to it
            offset: U32 @< Where (TRUNCATE: the size it keeps)
        ) opcode 3

        @ Restart the processor warm, as a watchdog or a fault recovery
        @ does: RAM is not cleared, so the RAM file system keeps its files
        @ (app/src/RamFs.cpp). The restart comes RESTART_DELAY_CYCLES cycles
        @ of the slowest group after the answer, so that the answer and the
        @ event reach the ground first.
        sync command RESTART opcode 4

        event OverrunInjected(rateGroup: U8, us: U32) severity warning low id 0 format "Rate group {} overran by {} us (injected)"

        event StackOverflowInjected($bytes: U32) severity warning high id 1 format "Using {} bytes of stack (injected)"

        event InjectionRejected(value: U32, limit: U32) severity warning low id 2 format "Fault injection value {} is above its limit {}"

        event FileCorrupted(file: string size FileNameStringSize, damage: FileDamage, offset: U32, $size: U32) severity warning low id 3 format "File {} damaged ({} at {}), was {} bytes (injected)"

        @ The file could not be read or written whole (F´'s Os::File status)
        event FileNotCorrupted(file: string size FileNameStringSize, status: I32) severity warning low id 4 format "File {} could not be damaged: file status {}"

        event RestartArmed(cycles: U32) severity warning high id 5 format "Warm restart in {} cycles of the slowest rate group (injected)"
    }
}

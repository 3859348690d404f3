# SPDX-License-Identifier: Apache-2.0
"""A console log in the firmware's format (shape of app/src/Report.cpp output)."""

from __future__ import annotations


def console_log(variant: str = "baremetal", slips: int = 0, result: str = "PASS", stack_used: int = 1000,
                context: str | None = None) -> str:
    # How the variant runs its tasks: threads on rtos, cooperative slices on baremetal
    context = context or ("thread" if variant == "rtos" else "slice")
    return "\n".join([
        "*** Booting Zephyr OS build 0d6f47a50097 ***",
        f"KIT BANNER variant={variant} board=qemu_cortex_m3 kit=abc zephyr=4.0.0/0d6f fprime=6c80 tick_hz=1000 "
        "sys_tick_hz=1000 cycles_hz=12000000 icount_shift=4 run_ticks=2000 hyperperiod_ticks=100",
        f"KIT RG name=rg1kHz hz=1000 cycles=2000 expected=2000 slips={slips} late_starts=0 lost_stamps=0 "
        "latency_min=550 latency_p50=600 latency_p99=1100 latency_max=1200 exec_min=73 exec_p50=80 exec_p99=2000 "
        "exec_max=2400 jitter_min=0 jitter_p50=12 jitter_p99=120 jitter_max=157 period_min=11842 period_max=12157",
        f"KIT TASK name=rg1kHz runs=2000 exec_avg=90 exec_max=2400 late=0 cpu_permille=75 context={context}",
        "KIT HIST rg=rg1kHz metric=latency buckets=544:10,576:1990",
        "KIT HASH samples=5999 fnv=0x1234abcd",
        "KIT CMD frame=0 opcode=0x500 noop=yes response=OK",
        f"KIT STACK name=main size=2048 used={stack_used}",
        "KIT CPU name=rg1kHz runs=2001 avg=90 max=2400 cpu_permille=75",
        "KIT CPU name=idle runs=2000 avg=10069 max=11589 cpu_permille=837",
        f"KIT END variant={variant} result={result} uptime_ms=2005",
    ])

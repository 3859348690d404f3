# SPDX-License-Identifier: Apache-2.0
# Port-array sizes, cut to what the kit's topology uses: every port is an
# object in RAM, so the F´ defaults (sized for a Linux Ref app) cost kilobytes.

@ Members per active rate group (probe start + up to 10 components + probe end)
constant ActiveRateGroupOutputPorts = 12

@ Members per passive rate group (baremetal_passive: the same members as
@ the active ones'; no other build has an instance, so no other pays)
constant PassiveRateGroupOutputPorts = 12

@ Rate groups driven by the tick: 1 kHz, 100 Hz, 10 Hz
constant RateGroupDriverRateGroupPorts = 3

@ Components that own commands, in the largest build (with health, version,
@ prmDb and fileDownlink: 11; fpp-to-dict says "too many ports" when short)
constant CmdDispatcherComponentCommandPorts = 11

@ Command sources: the scripted uplink (index 0), the ground link (1)
constant CmdDispatcherSequencePorts = 2

constant SeqDispatcherSequencerPorts = 1
constant CmdSplitterPorts = CmdDispatcherSequencePorts
constant StaticMemoryAllocations = 1
@ Health's ping entries: events, tlmSend, the active dispatcher, the
@ active rate groups where the model pings them, the parameter database,
@ the file downlink (app/Top/services/)
constant HealthPingPorts = 8
constant FileDownCompletePorts = 1
@ Downlink queues: events, telemetry
constant ComQueueComPorts = 2
constant ComQueueBufferPorts = 1
constant BufferRepeaterOutputPorts = 1
constant DpManagerNumPorts = 1
constant DpWriterNumProcPorts = 1
constant FileNameStringSize = 64

@ Text of an assert message, built on the asserting task's stack
constant FwAssertTextSize = 128
constant AssertFatalAdapterEventFileSize = FileNameStringSize

# SPDX-License-Identifier: Apache-2.0
# The thermal deployment's instances: its own components and F´'s services.
# The rate groups and the dispatcher, in the form the model chose, are in
# rategroups/ and dispatcher/; the kit's instruments and ground link are the
# kit's subtopologies (app/Subtopologies/).
module Thermal {

  instance events: Svc.EventManager base id 0x4600 \
    queue size Kit.Queues.events \
    stack size Kit.Stacks.events \
    priority Kit.Priorities.events

  instance tlmSend: Svc.TlmChan base id 0x4700 \
    queue size Kit.Queues.tlmSend \
    stack size Kit.Stacks.tlmSend \
    priority Kit.Priorities.tlmSend

  instance rateGroupDriver: Svc.RateGroupDriver base id 0x4000

  instance osTime: Svc.OsTime base id 0x4800

  instance fatalAdapter: Svc.AssertFatalAdapter base id 0x4900

  @ The kit's fatal handler: a FATAL event halts with the kit's report
  instance fatalHandler: Kit.FatalHandler base id 0x4A00

  instance thermistors: Thermal.Thermistors base id 0x5000

  instance heaterControl: Thermal.HeaterControl base id 0x5100

}

# SPDX-License-Identifier: Apache-2.0

module Kit {

    @ Ends the run on a FATAL event: prints the event ID and stops the
    @ system with a kernel panic, so a test harness sees a failure at once
    @ instead of waiting for a time-out on a spinning loop.
    passive component FatalHandler {

        @ FATAL events announced by the event manager
        sync input port FatalReceive: Svc.FatalEvent
    }
}

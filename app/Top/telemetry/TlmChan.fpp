# SPDX-License-Identifier: Apache-2.0
# The telemetry store: F´'s TlmChan (two hash tables, double buffered, in
# the object; sized in app/config/TlmChanImplCfg.hpp.in). The build takes this
# file, TlmTable.fpp or TlmLinearChan.fpp beside it (app/Top/CMakeLists.txt).
module Kit {

  instance tlmSend: Svc.TlmChan base id 0x0700 \
    queue size Queues.tlmSend \
    stack size Stacks.tlmSend \
    priority Priorities.tlmSend

}

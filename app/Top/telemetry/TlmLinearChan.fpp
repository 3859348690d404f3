# SPDX-License-Identifier: Apache-2.0
# The telemetry store: fprime-baremetal's TlmLinearChan (one table of
# TLMCHAN_HASH_BUCKETS entries, searched linearly, taken from F´'s allocator
# at setup: app/Top/KitTopology.cpp), with CONFIG_KIT_TELEMETRY_LINEAR. The
# same ports and telemetry as TlmChan.fpp beside it.
module Kit {

  instance tlmSend: Baremetal.TlmLinearChan base id 0x0700 \
    queue size Queues.tlmSend \
    stack size Stacks.tlmSend \
    priority Priorities.tlmSend

}

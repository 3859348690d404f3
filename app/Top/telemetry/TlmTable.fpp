# SPDX-License-Identifier: Apache-2.0
# The telemetry store: the kit's TlmTable (one table in its object, read
# through a sequence lock: app/Components/TlmTable), with CONFIG_KIT_TELEMETRY_TABLE.
# The same ports and telemetry as TlmChan.fpp beside it.
module Kit {

  instance tlmSend: Kit.TlmTable base id 0x0700 \
    queue size Queues.tlmSend \
    stack size Stacks.tlmSend \
    priority Priorities.tlmSend

}

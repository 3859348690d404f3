# SPDX-License-Identifier: Apache-2.0
# The rate groups as F´'s ActiveRateGroup, a task each (every model but
# baremetal_passive); PassiveRateGroups.fpp beside it is the other form.
module Thermal {

  instance rg50Hz: Svc.ActiveRateGroup base id 0x4100 \
    queue size Kit.Queues.rateGroup \
    stack size Kit.Stacks.rg50Hz \
    priority Kit.Priorities.rg50Hz

  instance rg10Hz: Svc.ActiveRateGroup base id 0x4200 \
    queue size Kit.Queues.rateGroup \
    stack size Kit.Stacks.rg10Hz \
    priority Kit.Priorities.rg10Hz

  instance rg1Hz: Svc.ActiveRateGroup base id 0x4300 \
    queue size Kit.Queues.rateGroup \
    stack size Kit.Stacks.rg1Hz \
    priority Kit.Priorities.rg1Hz

}

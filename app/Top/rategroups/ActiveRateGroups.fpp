# SPDX-License-Identifier: Apache-2.0
# The rate groups as F´'s ActiveRateGroup: each a task (a thread on rtos, a
# TaskRunner task on baremetal) that the driver hands its cycle through its
# queue. The build takes this file or PassiveRateGroups.fpp beside it
# (app/Top/CMakeLists.txt).
module Kit {

  instance rg1kHz: Svc.ActiveRateGroup base id 0x0100 \
    queue size Queues.rateGroup \
    stack size Stacks.rg1kHz \
    priority Priorities.rg1kHz

  instance rg100Hz: Svc.ActiveRateGroup base id 0x0200 \
    queue size Queues.rateGroup \
    stack size Stacks.rg100Hz \
    priority Priorities.rg100Hz

  instance rg10Hz: Svc.ActiveRateGroup base id 0x0300 \
    queue size Queues.rateGroup \
    stack size Stacks.rg10Hz \
    priority Priorities.rg10Hz

}

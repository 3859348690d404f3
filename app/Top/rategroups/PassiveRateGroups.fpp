# SPDX-License-Identifier: Apache-2.0
# The rate groups as F´'s PassiveRateGroup (CONFIG_KIT_RATE_GROUPS_PASSIVE,
# baremetal_passive): the driver calls each due group, and the group its
# members, in the main loop's own call, the pattern F´'s baremetal guide
# recommends. No queue, no task, no stack of their own. The same ports as
# ActiveRateGroups.fpp beside it, so the connections do not change.
module Kit {

  instance rg1kHz: Svc.PassiveRateGroup base id 0x0100

  instance rg100Hz: Svc.PassiveRateGroup base id 0x0200

  instance rg10Hz: Svc.PassiveRateGroup base id 0x0300

}

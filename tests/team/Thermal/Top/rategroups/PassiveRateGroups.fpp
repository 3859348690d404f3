# SPDX-License-Identifier: Apache-2.0
# The rate groups as F´'s PassiveRateGroup (CONFIG_KIT_RATE_GROUPS_PASSIVE:
# baremetal_passive), called in the tick; the same ports as
# ActiveRateGroups.fpp beside it.
module Thermal {

  instance rg50Hz: Svc.PassiveRateGroup base id 0x4100

  instance rg10Hz: Svc.PassiveRateGroup base id 0x4200

  instance rg1Hz: Svc.PassiveRateGroup base id 0x4300

}

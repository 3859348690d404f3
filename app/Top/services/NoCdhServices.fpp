# SPDX-License-Identifier: Apache-2.0
# A board profile's build without F´'s health and version services
# (CONFIG_KIT_SERVICE_CDH off: the board's Kconfig.defconfig says why, with
# the numbers). CdhServices.fpp beside it is the build with them.
module Kit {

  @ No health, no version: the 10 Hz group's member [9] is unconnected
  topology CdhServices {

    instance rg10Hz

  }

}

# SPDX-License-Identifier: Apache-2.0
# No file uplink: the board's profile leaves it out for this model
# (CONFIG_KIT_SERVICE_FILE_UPLINK=n), and the router drops the ground's file
# packets (F´'s FprimeRouter with its fileOut unconnected).
# FileUplinkServices.fpp beside it is the build with it.
module Kit {

  @ No entry for the file uplink: the next entry is where it would be
  constant pingEntriesToUplink = pingEntriesToFiles

  @ No file uplink
  topology FileUplinkServices {

    instance router

  }

}

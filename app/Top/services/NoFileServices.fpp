# SPDX-License-Identifier: Apache-2.0
# No file downlink: the board's profile leaves it out for this model
# (CONFIG_KIT_SERVICE_FILES=n). FileServices.fpp beside it is the build
# with it.
module Kit {

  @ No entry for the file downlink: the next entry is where it would be
  constant pingEntriesToFiles = pingEntriesToParams

  @ No file downlink
  topology FileServices {

    instance comQueue

  }

}

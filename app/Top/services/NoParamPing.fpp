# SPDX-License-Identifier: Apache-2.0
# No ping of the parameter database: the build has no health, or no
# database. ParamPing.fpp beside it is the build with both.
module Kit {

  @ No entry for the database: the next entry is where it would be
  constant pingEntriesToParams = pingEntriesToRateGroups

  @ No entry for the parameter database
  topology ParamHealth {

    instance controller

  }

}

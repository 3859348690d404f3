# SPDX-License-Identifier: Apache-2.0
# Health's ping of the parameter database, the entry after the rate
# groups' (where the build has both health and the database).
# NoParamPing.fpp beside it is the build without.
module Kit {

  @ Health's entries up to the database's: the next entry's index
  constant pingEntriesToParams = pingEntriesToRateGroups + 1

  @ The parameter database's ping
  topology ParamHealth {

    instance $health
    instance prmDb
    instance prmDbPing

    connections Health {
      $health.PingSend[pingEntriesToRateGroups] -> prmDbPing.pingIn
      prmDbPing.pingOut -> prmDb.pingIn
      prmDb.pingOut -> prmDbPing.returnIn
      prmDbPing.returnOut -> $health.PingReturn[pingEntriesToRateGroups]
    }

  }

}

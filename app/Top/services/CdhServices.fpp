# SPDX-License-Identifier: Apache-2.0
# F´'s health and version services (Svc/Subtopologies/CdhCore's $health and
# version; the kit's dispatcher, events, telemetry and fatal handling are
# its own forms, app/Top/), with the kit's probe on each ping
# (CONFIG_KIT_SERVICE_CDH). NoCdhServices.fpp beside it is a board profile's
# build without them; app/Top/topology.fpp imports whichever the build chose.
module Kit {

  @ Health and version, run by the 10 Hz group, and the pings of the
  @ services every build has
  topology CdhServices {

    instance $health
    instance version
    instance events
    instance tlmSend
    instance eventsPing
    instance tlmSendPing
    instance rg10Hz

    connections RateGroups {
      rg10Hz.RateGroupMemberOut[9] -> $health.Run
    }

    # Health pings every active component that has ping ports, through the
    # kit's probe, which times each round trip. Entry i is port i of health
    # and entry i of the table in KitTopology.cpp: the services here (0, 1),
    # the active dispatcher (2, DispatcherPing.fpp), the active rate groups
    # where the model pings them (3-5, RateGroupPings.fpp) and the parameter
    # database after them (ParamPing.fpp): each file's constant says where
    # the next begins. F´'s ComQueue has no ping
    # ports; the kit's Load is the background load it measures, a worker F´
    # leaves out of health checking.
    connections Health {
      $health.PingSend[0] -> eventsPing.pingIn
      eventsPing.pingOut -> events.pingIn
      events.pingOut -> eventsPing.returnIn
      eventsPing.returnOut -> $health.PingReturn[0]

      $health.PingSend[1] -> tlmSendPing.pingIn
      tlmSendPing.pingOut -> tlmSend.pingIn
      tlmSend.pingOut -> tlmSendPing.returnIn
      tlmSendPing.returnOut -> $health.PingReturn[1]
    }

  }

}

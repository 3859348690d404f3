# SPDX-License-Identifier: Apache-2.0
# F´'s command sequencer (the Ref deployment's cmdSeq) on the kit's RAM file
# system: the 10 Hz group runs its clock, its commands reach the dispatcher on
# their own port (2: after the scripted uplink's and the ground's), and health
# pings it, the entry after the file uplink's (CONFIG_KIT_SERVICE_SEQUENCER,
# which needs the file uplink: its sequences come from the ground).
# NoSequencerServices.fpp beside it is a board profile's build without it;
# app/Top/topology.fpp imports whichever the build chose.
module Kit {

  @ The command sequencer
  topology SequencerServices {

    instance cmdSeq
    instance cmdSeqPing
    instance cmdDisp
    instance rg10Hz
    instance $health

    connections RateGroups {
      rg10Hz.RateGroupMemberOut[11] -> cmdSeq.schedIn
    }

    connections Sequencer {
      cmdSeq.comCmdOut -> cmdDisp.seqCmdBuff[2]
      cmdDisp.seqCmdStatus[2] -> cmdSeq.cmdResponseIn
    }

    connections Health {
      $health.PingSend[pingEntriesToUplink] -> cmdSeqPing.pingIn
      cmdSeqPing.pingOut -> cmdSeq.pingIn
      cmdSeq.pingOut -> cmdSeqPing.returnIn
      cmdSeqPing.returnOut -> $health.PingReturn[pingEntriesToUplink]
    }

  }

}

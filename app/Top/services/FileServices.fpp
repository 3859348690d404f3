# SPDX-License-Identifier: Apache-2.0
# F´'s file downlink (Svc/Subtopologies/FileHandling's fileDownlink) from the
# kit's RAM file system (app/src/RamFs.cpp), run by the 10 Hz group, its
# packets through the link's queue after the events and telemetry, and
# health's ping of it, the entry after the parameter database's
# (CONFIG_KIT_SERVICE_FILES, which needs health). NoFileServices.fpp beside
# it is a board profile's build without it; app/Top/topology.fpp imports
# whichever the build chose.
module Kit {

  @ Health's entries up to the file downlink's: the next entry's index
  constant pingEntriesToFiles = pingEntriesToParams + 1

  @ The file downlink
  topology FileServices {

    instance fileDownlink
    instance fileDownlinkPing
    instance comQueue
    instance rg10Hz
    instance $health

    connections RateGroups {
      rg10Hz.RateGroupMemberOut[10] -> fileDownlink.Run
    }

    # ComQueue's buffer queue (its lowest priority: KitTopology.cpp's
    # configureLink) takes a file packet; the framer hands the buffer back
    # through it once framed, and then the downlink sends the next
    connections Downlink {
      fileDownlink.bufferSendOut -> comQueue.bufferQueueIn[0]
      comQueue.bufferReturnOut[0] -> fileDownlink.bufferReturn
    }

    connections Health {
      $health.PingSend[pingEntriesToParams] -> fileDownlinkPing.pingIn
      fileDownlinkPing.pingOut -> fileDownlink.pingIn
      fileDownlink.pingOut -> fileDownlinkPing.returnIn
      fileDownlinkPing.returnOut -> $health.PingReturn[pingEntriesToParams]
    }

  }

}

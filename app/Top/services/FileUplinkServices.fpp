# SPDX-License-Identifier: Apache-2.0
# F´'s file uplink (Svc/Subtopologies/FileHandling's fileUplink) to the kit's
# RAM file system (app/src/RamFs.cpp): the link's router hands it each file
# packet in a buffer of the link's pool, which goes back to the router once
# the packet is written; health pings it, the entry after the file
# downlink's (CONFIG_KIT_SERVICE_FILE_UPLINK, which needs the downlink).
# NoFileUplinkServices.fpp beside it is a board profile's build without it;
# app/Top/topology.fpp imports whichever the build chose.
module Kit {

  @ Health's entries up to the file uplink's: the next entry's index
  constant pingEntriesToUplink = pingEntriesToFiles + 1

  @ The file uplink
  topology FileUplinkServices {

    instance fileUplink
    instance fileUplinkPing
    instance router
    instance $health

    connections GroundUplink {
      router.fileOut -> fileUplink.bufferSendIn
      fileUplink.bufferSendOut -> router.fileBufferReturnIn
    }

    connections Health {
      $health.PingSend[pingEntriesToFiles] -> fileUplinkPing.pingIn
      fileUplinkPing.pingOut -> fileUplink.pingIn
      fileUplink.pingOut -> fileUplinkPing.returnIn
      fileUplinkPing.returnOut -> $health.PingReturn[pingEntriesToFiles]
    }

  }

}

# SPDX-License-Identifier: Apache-2.0
# F´'s parameter database (Svc/Subtopologies/FileHandling's prmDb) on the
# kit's RAM file system (app/src/RamFs.cpp), and the components whose
# parameters it keeps (CONFIG_KIT_SERVICE_PARAMS). NoParamServices.fpp beside
# it is a board profile's build without it; app/Top/topology.fpp imports
# whichever the build chose.
module Kit {

  @ The parameter database and its clients
  topology ParamServices {

    instance prmDb
    instance controller

    connections Parameters {
      controller.prmGetOut -> prmDb.getPrm
      controller.prmSetOut -> prmDb.setPrm
    }

  }

}

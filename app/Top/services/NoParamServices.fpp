# SPDX-License-Identifier: Apache-2.0
# No parameter database: the components keep their parameters' defaults
# (app/Components/ParamDefaults answers every read "not in the database"),
# and a parameter's save command fails (its port is unconnected). ParamServices.fpp beside it is the build with F´'s
# database (CONFIG_KIT_SERVICE_PARAMS).
module Kit {

  @ The parameters' clients, answered by the defaults
  topology ParamServices {

    instance paramDefaults
    instance controller

    connections Parameters {
      controller.prmGetOut -> paramDefaults.getPrm
    }

  }

}

# SPDX-License-Identifier: Apache-2.0
# No ping of the dispatcher: the build has no health (CONFIG_KIT_SERVICE_CDH
# off) or its dispatcher is fprime-baremetal's passive one, with no task to
# answer. DispatcherPing.fpp beside it is the build with it.
module Kit {

  @ Health's ping entries after the dispatcher's (none)
  constant pingEntriesToDispatcher = 2

  @ Entry 2 absent
  topology DispatcherHealth {

    instance cmdDisp

  }

}

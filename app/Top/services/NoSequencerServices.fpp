# SPDX-License-Identifier: Apache-2.0
# No command sequencer: the board's profile leaves it out for this model
# (CONFIG_KIT_SERVICE_SEQUENCER=n). SequencerServices.fpp beside it is the
# build with it.
module Kit {

  @ No command sequencer
  topology SequencerServices {

    instance cmdDisp

  }

}

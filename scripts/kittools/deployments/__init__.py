# SPDX-License-Identifier: Apache-2.0
"""`kit new-deployment`: an F´ deployment folder as `fprime-util new
--deployment` makes it, given the kit's seam (docs/your-deployment.md).

  fpp       the little of FPP the tool reads: instances, imports, connections
  template  what the deployment is: its instances, rate groups and rates
  seam      the seam's files the tool writes, from that model (cpp: its C++ ones)
  adapt     the edits of the deployment's own files, and the run's record
"""

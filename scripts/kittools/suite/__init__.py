# SPDX-License-Identifier: Apache-2.0
"""`kit test`'s suite: twister runs, results, determinism, device, porting, host tests, budget."""

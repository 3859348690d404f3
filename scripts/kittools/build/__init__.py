# SPDX-License-Identifier: Apache-2.0
"""What the kit reads from a build folder and how it runs one."""

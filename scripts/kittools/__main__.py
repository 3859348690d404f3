# SPDX-License-Identifier: Apache-2.0
import sys

from kittools.cli import main

sys.exit(main())

# SPDX-License-Identifier: Apache-2.0
"""kittools is imported as installed (scripts/setup.sh installs scripts/ into the
venv, editable); the tests' own helpers (sample_console) sit next to them."""

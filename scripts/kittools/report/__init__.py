# SPDX-License-Identifier: Apache-2.0
"""The report: its document model, analyses, tables, plots and renderers."""

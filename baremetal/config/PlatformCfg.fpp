# SPDX-License-Identifier: Apache-2.0
# OS handle storage for the baremetal variant. Each F´ Os object embeds a
# handle of these sizes (checked by static_assert in Os/Delegate.hpp), so
# they are kept near what fprime-baremetal, F´'s stubs and fprime-zephyr's
# RawTime/Console actually need on a 32-bit target.
constant FW_CONSOLE_HANDLE_MAX_SIZE = 8
constant FW_TASK_HANDLE_MAX_SIZE = 24
constant FW_FILE_HANDLE_MAX_SIZE = 8
constant FW_MUTEX_HANDLE_MAX_SIZE = 8
constant FW_QUEUE_HANDLE_MAX_SIZE = 368
constant FW_DIRECTORY_HANDLE_MAX_SIZE = 8
constant FW_FILESYSTEM_HANDLE_MAX_SIZE = 8
constant FW_RAW_TIME_HANDLE_MAX_SIZE = 16
constant FW_RAW_TIME_SERIALIZATION_MAX_SIZE = 8
constant FW_CONDITION_VARIABLE_HANDLE_MAX_SIZE = 8
constant FW_CPU_HANDLE_MAX_SIZE = 8
constant FW_MEMORY_HANDLE_MAX_SIZE = 8
constant FW_HANDLE_ALIGNMENT = 8
constant FW_FILE_CHUNK_SIZE = 32

# SPDX-License-Identifier: Apache-2.0
# Buffer and string sizes for a 64 KiB-RAM target. Every queued command, event
# and telemetry message carries a buffer of FW_COM_BUFFER_MAX_SIZE, so this one
# number sets most of the queue memory; 128 bytes holds every packet the kit
# sends (the longest is an event with three U32 arguments).

constant FW_OBJ_SIMPLE_REG_BUFF_SIZE = 32
constant FW_QUEUE_NAME_BUFFER_SIZE = 16
constant FW_TASK_NAME_BUFFER_SIZE = 16
constant FW_COM_BUFFER_MAX_SIZE = 128
constant FW_SM_SIGNAL_BUFFER_MAX_SIZE = 16
constant FW_CMD_ARG_BUFFER_MAX_SIZE = FW_COM_BUFFER_MAX_SIZE - SIZE_OF_FwOpcodeType - SIZE_OF_FwPacketDescriptorType
constant FW_CMD_STRING_MAX_SIZE = 32
constant FW_LOG_BUFFER_MAX_SIZE = FW_COM_BUFFER_MAX_SIZE - SIZE_OF_FwEventIdType - SIZE_OF_FwPacketDescriptorType
constant FW_LOG_STRING_MAX_SIZE = 64
constant FW_TLM_BUFFER_MAX_SIZE = 16
constant FW_STATEMENT_ARG_BUFFER_MAX_SIZE = FW_CMD_ARG_BUFFER_MAX_SIZE
constant FW_TLM_STRING_MAX_SIZE = 12
constant FW_PARAM_BUFFER_MAX_SIZE = 16
constant FW_PARAM_STRING_MAX_SIZE = 12
constant FW_FILE_BUFFER_MAX_SIZE = 16
constant FW_INTERNAL_INTERFACE_STRING_MAX_SIZE = 32
constant FW_LOG_TEXT_BUFFER_SIZE = 64
constant FW_FIXED_LENGTH_STRING_SIZE = 64
constant FW_OBJ_SIMPLE_REG_ENTRIES = 1
constant FW_QUEUE_SIMPLE_QUEUE_ENTRIES = 1
constant FW_ASSERT_COUNT_MAX = 4
constant FW_CONTEXT_DONT_CARE = 0xFF
dictionary constant FW_SERIALIZE_TRUE_VALUE = 0xFF
dictionary constant FW_SERIALIZE_FALSE_VALUE = 0x00

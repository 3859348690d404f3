/* SPDX-License-Identifier: Apache-2.0 */
/*
 * libcrc's update_crc_32 (F´'s Utils/Hash/libcrc/lib_crc.h: F´'s file CRCs,
 * the file uplink's checksum, the sequencer's and the parameter file's
 * CRCs) on Zephyr's crc32_ieee_update: the same CRC-32 (IEEE 802.3, the
 * reflected polynomial 0xEDB88320), a byte at a time.
 *
 * Why: libcrc computes a 256-entry table into RAM at its first call, 1 KiB
 * of RAM, and its other tables (CRC-16, CCITT, DNP, Kermit, which F´'s
 * modules here never call) come with it. Zephyr's table is 16 entries in
 * flash. fprime.cmake builds this file in place of lib_crc.c in F´'s
 * Utils_Hash, where CONFIG_FPRIME_CRC32_IN_FLASH is set (modules/fprime/Kconfig).
 */
#include <zephyr/sys/crc.h>

#include <Utils/Hash/libcrc/lib_crc.h>

unsigned long update_crc_32(unsigned long crc, char c) {
    const uint8_t byte = (uint8_t)c;

    /* crc32_ieee_update complements the register on the way in and out;
     * libcrc's update works on the register itself
     */
    return ~(unsigned long)crc32_ieee_update(~(uint32_t)crc, &byte, 1U);
}

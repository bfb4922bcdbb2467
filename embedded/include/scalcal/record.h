/* A calibration as a fixed-size record for flash: 128 bytes, little-endian whatever the CPU, IEEE
 * float32 values whatever the build's precision, a magic, a layout version and a CRC-32 (IEEE 802.3,
 * the zlib one) over everything before it. Layout (byte offsets; README.md has the table):
 *   0 u32 magic 0x4C414353 ("SCAL")   4 u16 version (1)   6 u16 size (128)
 *   8 u8 model (3, 6, 9)   9 u8 flags (bit 0: magnitude auto)   10 u16 positions   12 u32 samples
 *  16 f32 offset[3]   28 f32 matrix[3][3] by rows   64 f32 magnitude   68 f32 nominal_gain
 *  72 f32 bias_std[3]   84 f32 scale_deviation_std[3]   96 f32 nonorthogonality_std[3]
 * 108 f32 noise   112 f32 residual_rms   116 u32 sequence (the caller's counter: the newest record
 * of several slots wins)   120 u32 reserved (0)   124 u32 crc32 of bytes 0..123. */
#ifndef SCALCAL_RECORD_H
#define SCALCAL_RECORD_H

#include <stdint.h>

#include "scalcal/calibration.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SCALCAL_RECORD_SIZE 128
#define SCALCAL_RECORD_MAGIC 0x4C414353u
#define SCALCAL_RECORD_VERSION 1

/* Writes cal as a record. SCALCAL_E_ARGUMENT for a null pointer or a model other than 3, 6, 9. */
scalcal_status scalcal_record_write(const scalcal_calibration* cal, uint32_t sequence,
                                    uint8_t record[SCALCAL_RECORD_SIZE]);

/* Reads a record back: SCALCAL_E_RECORD for a wrong magic, version, size or checksum (an erased page
 * of 0xFF reads as that), SCALCAL_E_DEGENERATE for a matrix that is not a correction. The gains,
 * scale deviations and non-orthogonality are recomputed from the matrix; gain_std and
 * nominal_gain_std are not stored (NaN). sequence may be null. */
scalcal_status scalcal_record_read(const uint8_t record[SCALCAL_RECORD_SIZE], scalcal_calibration* cal,
                                   uint32_t* sequence);

/* CRC-32 (reflected polynomial 0xEDB88320, initial and final xor 0xFFFFFFFF) of n bytes. */
uint32_t scalcal_crc32(const uint8_t* data, uint32_t n);

#ifdef __cplusplus
}
#endif

#endif

/* The flash record (scalcal/record.h): explicit little-endian bytes, float32 values, CRC-32. */
#include <string.h>

#include "internal.h"
#include "scalcal/record.h"

uint32_t scalcal_crc32(const uint8_t* data, uint32_t n) {
  uint32_t crc = 0xFFFFFFFFu, i;
  int bit;
  for (i = 0; i < n; ++i) {
    crc ^= data[i];
    for (bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xFFFFFFFFu;
}

static void put_u32(uint8_t* p, uint32_t v) {
  p[0] = (uint8_t)v, p[1] = (uint8_t)(v >> 8), p[2] = (uint8_t)(v >> 16), p[3] = (uint8_t)(v >> 24);
}
static uint32_t get_u32(const uint8_t* p) {
  return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}
static void put_f32(uint8_t* p, scalcal_real v) {
  const float f = (float)v;
  uint32_t u;
  memcpy(&u, &f, 4);
  put_u32(p, u);
}
static scalcal_real get_f32(const uint8_t* p) {
  const uint32_t u = get_u32(p);
  float f;
  memcpy(&f, &u, 4);
  return (scalcal_real)f;
}

scalcal_status scalcal_record_write(const scalcal_calibration* cal, uint32_t sequence,
                                    uint8_t record[SCALCAL_RECORD_SIZE]) {
  int k;
  if (!cal || !record) return SCALCAL_E_ARGUMENT;
  if (cal->model != SCALCAL_MODEL_BIAS3 && cal->model != SCALCAL_MODEL_AXIS6 && cal->model != SCALCAL_MODEL_PAPER9)
    return SCALCAL_E_ARGUMENT;
  memset(record, 0, SCALCAL_RECORD_SIZE);
  put_u32(record, SCALCAL_RECORD_MAGIC);
  record[4] = SCALCAL_RECORD_VERSION & 0xFF, record[5] = SCALCAL_RECORD_VERSION >> 8;
  record[6] = SCALCAL_RECORD_SIZE & 0xFF, record[7] = SCALCAL_RECORD_SIZE >> 8;
  record[8] = (uint8_t)cal->model;
  record[9] = cal->magnitude_auto ? 1 : 0;
  record[10] = (uint8_t)(cal->positions > 0xFFFF ? 0xFF : cal->positions & 0xFF);
  record[11] = (uint8_t)(cal->positions > 0xFFFF ? 0xFF : cal->positions >> 8);
  put_u32(record + 12, cal->samples);
  for (k = 0; k < 3; ++k) put_f32(record + 16 + 4 * k, cal->offset[k]);
  for (k = 0; k < 9; ++k) put_f32(record + 28 + 4 * k, cal->matrix[k / 3][k % 3]);
  put_f32(record + 64, cal->magnitude);
  put_f32(record + 68, cal->nominal_gain);
  for (k = 0; k < 3; ++k) {
    put_f32(record + 72 + 4 * k, cal->bias_std[k]);
    put_f32(record + 84 + 4 * k, cal->scale_deviation_std[k]);
    put_f32(record + 96 + 4 * k, cal->nonorthogonality_std[k]);
  }
  put_f32(record + 108, cal->noise);
  put_f32(record + 112, cal->residual_rms);
  put_u32(record + 116, sequence);
  put_u32(record + 124, scalcal_crc32(record, SCALCAL_RECORD_SIZE - 4));
  return SCALCAL_OK;
}

scalcal_status scalcal_record_read(const uint8_t record[SCALCAL_RECORD_SIZE], scalcal_calibration* cal,
                                   uint32_t* sequence) {
  scalcal_real offset[3], matrix[9];
  scalcal_calibration out;
  scalcal_status s;
  int k;
  if (!record || !cal) return SCALCAL_E_ARGUMENT;
  if (get_u32(record) != SCALCAL_RECORD_MAGIC || (record[4] | record[5] << 8) != SCALCAL_RECORD_VERSION ||
      (record[6] | record[7] << 8) != SCALCAL_RECORD_SIZE ||
      get_u32(record + 124) != scalcal_crc32(record, SCALCAL_RECORD_SIZE - 4))
    return SCALCAL_E_RECORD;
  if (record[8] != 3 && record[8] != 6 && record[8] != 9) return SCALCAL_E_RECORD;
  for (k = 0; k < 3; ++k) offset[k] = get_f32(record + 16 + 4 * k);
  for (k = 0; k < 9; ++k) matrix[k] = get_f32(record + 28 + 4 * k);
  s = scalcal_calibration_from_matrix(&out, (scalcal_model)record[8], offset, matrix, get_f32(record + 64),
                                      record[9] & 1, get_f32(record + 68));
  if (s != SCALCAL_OK) return s;
  for (k = 0; k < 3; ++k) {
    out.bias_std[k] = get_f32(record + 72 + 4 * k);
    out.scale_deviation_std[k] = get_f32(record + 84 + 4 * k);
    out.nonorthogonality_std[k] = get_f32(record + 96 + 4 * k);
  }
  out.noise = get_f32(record + 108);
  out.residual_rms = get_f32(record + 112);
  out.positions = (uint32_t)(record[10] | record[11] << 8);
  out.samples = get_u32(record + 12);
  if (sequence) *sequence = get_u32(record + 116);
  *cal = out;
  return SCALCAL_OK;
}

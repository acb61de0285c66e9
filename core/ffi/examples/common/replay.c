/*
 * The replay loop shared by the host and the Cortex-M4 example: trace in, bearing steps,
 * harness records out. Step by step it does what the harness's kernel does
 * (hil-sim/kernel/src/kernel.rs): settle 6 steps at the first sample, then advance every sample
 * by the nominal period 1/rate (0 for the first), compute the friction of that step, and record
 * force, cage angle, friction torque, power loss and its split, and each roller's load, films,
 * geometric approach and film sources.
 */
#include "replay.h"

#include <string.h>

#include "bearing.h"

enum {
  TRACE_HEADER_LEN = 64,
  TRACE_FLAG_TILT = 1,
  RECORD_LEN_MAX = 36,
  SETTLE_STEPS = 6, /* the core's SETTLE_STEPS: |dh|/h <= 1e-3 from a cold start */
};

static uint16_t le_u16(const uint8_t *p) { return (uint16_t)(p[0] | (p[1] << 8)); }

static uint32_t le_u32(const uint8_t *p) {
  return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
}

static float le_f32(const uint8_t *p) {
  uint32_t bits = le_u32(p);
  float value;
  memcpy(&value, &bits, sizeof value);
  return value;
}

static double le_f64(const uint8_t *p) {
  uint64_t bits = (uint64_t)le_u32(p) | ((uint64_t)le_u32(p + 4) << 32);
  double value;
  memcpy(&value, &bits, sizeof value);
  return value;
}

static int put_u16(FILE *f, uint16_t v) {
  uint8_t b[2] = {(uint8_t)v, (uint8_t)(v >> 8)};
  return fwrite(b, 1, 2, f) == 2 ? 0 : -1;
}

static int put_u32(FILE *f, uint32_t v) {
  uint8_t b[4] = {(uint8_t)v, (uint8_t)(v >> 8), (uint8_t)(v >> 16), (uint8_t)(v >> 24)};
  return fwrite(b, 1, 4, f) == 4 ? 0 : -1;
}

static int put_f32(FILE *f, float v) {
  uint32_t bits;
  memcpy(&bits, &v, sizeof bits);
  return put_u32(f, bits);
}

/* The storage of the bearing: static, sized and aligned for every target by the header. */
static _Alignas(BEARING_STORAGE_ALIGN) uint8_t storage[BEARING_STORAGE_SIZE];

/* One line naming the refused field, the value given and what is allowed. */
static void print_refusal(const BearingRefusal *r) {
  if (r->field[0] == '\0') return;
  fprintf(stderr, "  %s = %g is not allowed: ", r->field, (double)r->value);
  switch (r->allowed) {
    case BEARING_ALLOWED_POSITIVE: fprintf(stderr, "it must be finite and > 0\n"); break;
    case BEARING_ALLOWED_NON_NEGATIVE: fprintf(stderr, "it must be finite and >= 0\n"); break;
    case BEARING_ALLOWED_RANGE: fprintf(stderr, "it must lie in [%g, %g]\n", (double)r->min, (double)r->max); break;
    case BEARING_ALLOWED_LESS_THAN: fprintf(stderr, "it must be < %s = %g\n", r->other_field, (double)r->max); break;
    default: fprintf(stderr, "it must be finite\n"); break;
  }
}

static int refused(const char *what, BearingStatus status, BearingHandle *bearing) {
  fprintf(stderr, "%s: %s\n", what, bearing_error_message(status));
  BearingRefusal refusal;
  if (bearing != NULL && bearing_last_refusal(bearing, &refusal) == BEARING_STATUS_OK) print_refusal(&refusal);
  return 3;
}

int replay(FILE *trace, FILE *outputs, uint32_t max_steps, uint32_t film, replay_counter counter,
           uint32_t calibration, ReplaySummary *summary) {
  uint8_t header[TRACE_HEADER_LEN];
  if (fread(header, 1, sizeof header, trace) != sizeof header ||
      memcmp(header, "BRGTRACE", 8) != 0 || le_u16(header + 8) != 1) {
    fprintf(stderr, "trace: not a version-1 BRGTRACE file\n");
    return 2;
  }
  uint16_t flags = le_u16(header + 10);
  uint32_t count = le_u32(header + 12);
  double rate_hz = le_f64(header + 16);
  const char *bearing_id = (const char *)header + 24;   /* zero-padded, 16 bytes */
  const char *lubricant_id = (const char *)header + 40; /* zero-padded, 16 bytes */
  size_t record_len = (flags & TRACE_FLAG_TILT) ? 36 : 28;
  if ((flags & ~TRACE_FLAG_TILT) != 0 || !(rate_hz > 0.0) || strncmp(lubricant_id, "thesis_oil", 16) != 0) {
    fprintf(stderr, "trace: unknown flags, a rate that is not positive, or a lubricant other than thesis_oil\n");
    return 2;
  }
  uint32_t preset;
  if (strncmp(bearing_id, "hub_motor", 16) == 0) {
    preset = BEARING_PRESET_HUB_MOTOR;
  } else if (strncmp(bearing_id, "nu205", 16) == 0) {
    preset = BEARING_PRESET_NU205;
  } else {
    fprintf(stderr, "trace: unknown bearing %.16s\n", bearing_id);
    return 2;
  }

  BearingConfig config;
  BearingStatus status = bearing_preset(preset, &config);
  if (status != BEARING_STATUS_OK) return refused("bearing_preset", status, NULL);
  config.film = film;
  BearingHandle *bearing = NULL;
  BearingRefusal refusal;
  status = bearing_init(storage, sizeof storage, &config, &bearing, &refusal);
  if (status != BEARING_STATUS_OK) {
    fprintf(stderr, "bearing_init: %s\n", bearing_error_message(status));
    print_refusal(&refusal);
    return 3;
  }

  uint32_t steps = (max_steps != 0 && max_steps < count) ? max_steps : count;
  /* The harness's output header: magic, version 2, rollers, step count. */
  uint32_t rollers = config.roller_count;
  if (fwrite("BRGSTEPS", 1, 8, outputs) != 8 || put_u16(outputs, 2) || put_u16(outputs, (uint16_t)rollers) ||
      put_u32(outputs, steps)) {
    fprintf(stderr, "outputs: write failed\n");
    return 4;
  }

  /* The nominal period, rounded to f32 once, as the kernel does. */
  const float period_s = (float)(1.0 / rate_hz);
  static BearingOutput out; /* 1 KiB: static rather than on a small stack */
  uint32_t fewest = UINT32_MAX, most = 0, friction_fewest = UINT32_MAX, friction_most = 0;
  for (uint32_t index = 0; index < steps; ++index) {
    uint8_t record[RECORD_LEN_MAX];
    if (fread(record, 1, record_len, trace) != record_len) {
      fprintf(stderr, "trace: ends at record %u of %u\n", (unsigned)index, (unsigned)count);
      return 2;
    }
    /* time (f64) is not used: the bearing advances by the nominal period. */
    BearingState state = {
        .displacement_m = {le_f32(record + 12), le_f32(record + 16)},
        .velocity_m_s = {le_f32(record + 20), le_f32(record + 24)},
        .tilt_rad = {0.0f, 0.0f},
        .shaft_speed_rad_s = le_f32(record + 8),
    };
    if (flags & TRACE_FLAG_TILT) {
      state.tilt_rad[0] = le_f32(record + 28);
      state.tilt_rad[1] = le_f32(record + 32);
    }
    if (index == 0) {
      status = bearing_settle(bearing, &state, SETTLE_STEPS, &out);
      if (status != BEARING_STATUS_OK) return refused("bearing_settle", status, bearing);
    }
    const float dt_s = index == 0 ? 0.0f : period_s; /* the first sample defines the cage angle 0 */
    uint32_t start = counter ? counter() : 0;
    status = bearing_advance(bearing, &state, dt_s, &out);
    uint32_t counts = counter ? counter() - start : 0;
    if (status != BEARING_STATUS_OK) return refused("bearing_advance", status, bearing);
    if (counts < fewest) fewest = counts;
    if (counts > most) most = counts;
    /* The friction of this step, at its shaft speed, counted apart from the step. */
    start = counter ? counter() : 0;
    status = bearing_friction(bearing, state.shaft_speed_rad_s, &out);
    uint32_t friction_counts = counter ? counter() - start : 0;
    if (status != BEARING_STATUS_OK) return refused("bearing_friction", status, bearing);
    if (friction_counts < friction_fewest) friction_fewest = friction_counts;
    if (friction_counts > friction_most) friction_most = friction_counts;

    /* The record: counts (instructions of the step, SysTick: not read here, instructions of the
       friction call), F_x, F_y, cage angle, friction torque, power loss and its split into
       rolling, viscous and boundary, then per roller Q, h_in, h_out, geometric approach and
       the two film sources. */
    int bad = put_u32(outputs, counts) | put_u32(outputs, 0) | put_u32(outputs, friction_counts) |
              put_f32(outputs, out.force_n[0]) | put_f32(outputs, out.force_n[1]) |
              put_f32(outputs, out.cage_angle_rad) | put_f32(outputs, out.friction_torque_nm) |
              put_f32(outputs, out.power_loss_w);
    for (int k = 0; k < 3; ++k) bad |= put_f32(outputs, out.power_loss_split_w[k]);
    for (uint32_t j = 0; j < out.roller_count; ++j) {
      const BearingRollerOutput *r = &out.rollers[j];
      bad |= put_f32(outputs, r->load_n) | put_f32(outputs, r->central_film_in_m) |
             put_f32(outputs, r->central_film_out_m) | put_f32(outputs, r->geometric_approach_m);
      bad |= fputc(r->film_source_in, outputs) == EOF || fputc(r->film_source_out, outputs) == EOF;
    }
    if (bad) {
      fprintf(stderr, "outputs: write failed at step %u\n", (unsigned)index);
      return 4;
    }
  }

  /* The trailer: magic, status 0, no stack figures, the counter's calibration. */
  if (fwrite("BRGEND\0\0", 1, 8, outputs) != 8 || put_u32(outputs, 0) || put_u32(outputs, 0) ||
      put_u32(outputs, 0) || put_u32(outputs, calibration) || put_u32(outputs, 0)) {
    fprintf(stderr, "outputs: write failed\n");
    return 4;
  }
  summary->steps = steps;
  summary->rollers = rollers;
  summary->fewest_counts = steps ? fewest : 0;
  summary->most_counts = most;
  summary->friction_fewest_counts = steps ? friction_fewest : 0;
  summary->friction_most_counts = friction_most;
  return 0;
}

/*
 * Replays a binary bearing trace (hil-sim/kernel/src/wire.rs, docs/hil.md) through the bearing
 * library and writes every step's outputs in the HIL harness's output format
 * (hil-sim/kernel/src/outputs.rs), as hil-sim's firmware does: the same steps, the same records.
 */
#ifndef REPLAY_H
#define REPLAY_H

#include <stdint.h>
#include <stdio.h>

/* Reads a free-running counter (the M4 program's TIM2: instructions), or NULL for none. */
typedef uint32_t (*replay_counter)(void);

/* What a replay did. */
typedef struct ReplaySummary {
  uint32_t steps;              /* steps written */
  uint32_t rollers;            /* rollers per step */
  uint32_t fewest_counts;      /* counter ticks of the cheapest step (0 without a counter) */
  uint32_t most_counts;        /* of the dearest */
  uint32_t friction_fewest_counts; /* counter ticks of the cheapest bearing_friction call */
  uint32_t friction_most_counts;   /* of the dearest */
} ReplaySummary;

/*
 * Replays at most `max_steps` samples of `trace` (0: all) with the film model `film` (a
 * BearingFilm value), writing `outputs`; `calibration` goes into the trailer (the counter's
 * ticks for 1000 `nop`, 0 without a counter). Returns 0, or a non-zero code after printing why
 * to stderr.
 */
int replay(FILE *trace, FILE *outputs, uint32_t max_steps, uint32_t film, replay_counter counter,
           uint32_t calibration, ReplaySummary *summary);

#endif /* REPLAY_H */

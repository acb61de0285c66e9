/*
 * Host example of the bearing C library: replays a binary trace and writes the HIL harness's
 * output records.
 *
 *   replay-host TRACE OUTPUTS [MAX_STEPS]
 *
 * Build (core/ffi/tests/c_examples.rs does this):
 *   cargo build --release -p bearing-ffi
 *   cc -std=c11 -O2 -I core/ffi/include -I core/ffi/examples/common core/ffi/examples/host/main.c \
 *      core/ffi/examples/common/replay.c target/release/libbearing_ffi.a -lpthread -ldl -lm -o replay-host
 */
#include <stdio.h>
#include <stdlib.h>

#include "bearing.h"
#include "replay.h"

int main(int argc, char **argv) {
  if (argc < 3 || argc > 4) {
    fprintf(stderr, "usage: %s TRACE OUTPUTS [MAX_STEPS]\n", argv[0]);
    return 1;
  }
  uint32_t max_steps = argc == 4 ? (uint32_t)strtoul(argv[3], NULL, 10) : 0;
  FILE *trace = fopen(argv[1], "rb");
  if (trace == NULL) {
    fprintf(stderr, "cannot open %s\n", argv[1]);
    return 2;
  }
  /* Written whole or not at all: into OUTPUTS.part, renamed to OUTPUTS when complete. */
  char part[4096];
  if (snprintf(part, sizeof part, "%s.part", argv[2]) >= (int)sizeof part) {
    fprintf(stderr, "output path too long: %s\n", argv[2]);
    return 1;
  }
  FILE *outputs = fopen(part, "wb");
  if (outputs == NULL) {
    fprintf(stderr, "cannot create %s\n", part);
    return 4;
  }
  ReplaySummary summary;
  int code = replay(trace, outputs, max_steps, BEARING_FILM_INT, NULL, 0, &summary);
  fclose(trace);
  if (fclose(outputs) != 0 && code == 0) code = 4;
  if (code == 0 && rename(part, argv[2]) != 0) {
    fprintf(stderr, "cannot rename %s to %s\n", part, argv[2]);
    code = 4;
  }
  if (code != 0) remove(part);
  if (code == 0) {
    printf("%u steps of %u rollers; storage %zu of %d bytes, alignment %zu\n", (unsigned)summary.steps,
           (unsigned)summary.rollers, bearing_storage_size(), BEARING_STORAGE_SIZE, bearing_storage_align());
  }
  return code;
}

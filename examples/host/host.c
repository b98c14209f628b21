/* A minimal controller host in plain C: verify the signature of a program built by `ladderjit
 * compile` against a trusted public key and open it (ljverify.c), check its signed ABI version
 * and state size, and drive it with a scan loop and a simulated NC of its own. Uses only the
 * installed public headers (ladderjit/abi.h, ladderjit/program.h) and OpenSSL libcrypto.
 *
 *   host PROGRAM.so TRUSTED_KEY.pub TICKS STIMULUS_OUT PARAMS_OUT
 *
 * Made for examples/part_counter.stl: the NC runs a machining cycle (F2560.5 "cycle running")
 * of 8 + (cycle % 3) * 2 ticks, then pulses F2561.2 "program finished" for one tick and rests
 * 4 ticks. P20 = 3 parts per batch, P21 = 4 parts of tool life. Prints a CSV watch table (the
 * format of `ladderjit run --watch G2579,Y481,B0,D41`) and writes the inputs it applied as a
 * stimulus file and a params file, so a test can replay them on `ladderjit run --engine interp`. */
#include "ladderjit/abi.h"
#include "ladderjit/program.h"
#include "ljverify.h"

#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The exports this host uses (program.h). */
struct program {
  ljprog_u32_fn abi_version;
  char program[72]; /* the program hash of the signed trailer */
  ljprog_size_fn state_size;
  ljprog_reset_fn state_reset;
  ljprog_run_fn init;
  ljprog_run_fn tick;
};

static int load(const char *path, const char *key, struct program *p) {
  ljverify_meta meta;
  char err[512];
  void *h = ljverify_open(path, key, &meta, err, sizeof err);
  if (!h) {
    fprintf(stderr, "host: %s\n", err);
    return 0;
  }
  /* The signed trailer's word, not the .so's functions. */
  if (meta.abi != LJPROG_ABI_VERSION || meta.state_size != sizeof(lj_state)) {
    fprintf(stderr, "host: %s has ABI version %u (state %llu bytes), this host needs %u (%zu)\n",
            path, meta.abi, (unsigned long long)meta.state_size, LJPROG_ABI_VERSION,
            sizeof(lj_state));
    return 0;
  }
  /* POSIX guarantees the object pointer from dlsym converts to a function pointer. */
  *(void **)&p->abi_version = dlsym(h, "ljprog_abi_version");
  memcpy(p->program, meta.program, sizeof p->program);
  *(void **)&p->state_size = dlsym(h, "ljprog_state_size");
  *(void **)&p->state_reset = dlsym(h, "ljprog_state_reset");
  *(void **)&p->init = dlsym(h, "ljprog_init");
  *(void **)&p->tick = dlsym(h, "ljprog_tick");
  if (!p->abi_version || !p->state_size || !p->state_reset || !p->init || !p->tick) {
    fprintf(stderr, "host: %s is not a ladderjit program (symbols missing)\n", path);
    return 0;
  }
  return 1;
}

/* Write one input bit and log it in the stimulus file (`@TICK ADDR=VALUE`). */
static void set_f_bit(lj_state *s, FILE *stim, unsigned long tick, int index, int bit, int on) {
  int16_t mask = (int16_t)(1 << bit);
  if (((s->img.F[index] & mask) != 0) == on) return;
  s->img.F[index] = (int16_t)(on ? (s->img.F[index] | mask) : (s->img.F[index] & ~mask));
  fprintf(stim, "@%lu F%d.%d=%d\n", tick, index, bit, on);
}

int main(int argc, char **argv) {
  if (argc != 6) {
    fprintf(stderr, "usage: host PROGRAM.so TRUSTED_KEY.pub TICKS STIMULUS_OUT PARAMS_OUT\n");
    return 2;
  }
  struct program prog;
  if (!load(argv[1], argv[2], &prog)) return 2;
  ++argv; /* the remaining arguments as before the key was added */
  unsigned long ticks = strtoul(argv[2], NULL, 10);
  FILE *stim = fopen(argv[3], "w");
  FILE *params = fopen(argv[4], "w");
  lj_state *s = malloc(sizeof *s);
  if (!stim || !params || !s) {
    fprintf(stderr, "host: cannot open the output files\n");
    return 2;
  }
  fprintf(stderr, "host: program %s\n", prog.program);

  prog.state_reset(s); /* power-up: zero state, default watchdog */
  s->img.P[20] = 3;    /* parameters before init, like `ladderjit run --params` */
  s->img.P[21] = 4;
  fprintf(params, "P20=3\nP21=4\n");
  s->now_ms = 0;
  if (prog.init(s) != LJ_FAULT_NONE) fprintf(stderr, "host: init fault\n");

  printf("tick,G2579,Y481,B0,D41\n");
  unsigned long cycle = 0, phase = 0; /* ticks into the current cycle */
  for (unsigned long t = 0; t < ticks; ++t) {
    unsigned long run = 8 + (cycle % 3) * 2;
    set_f_bit(s, stim, t, 2560, 5, phase < run);  /* cycle running */
    set_f_bit(s, stim, t, 2561, 2, phase == run); /* program finished pulse */
    if (++phase == run + 5) {
      phase = 0;
      ++cycle;
    }
    s->now_ms = t; /* 1 ms period */
    if (prog.tick(s) != LJ_FAULT_NONE) fprintf(stderr, "host: tick %lu fault\n", t);
    printf("%lu,%d,%d,%d,%d\n", t, s->img.G[2579], s->img.Y[481], s->img.B[0], s->img.D[41]);
  }
  fclose(stim);
  fclose(params);
  free(s);
  return 0;
}

/* subnormal.h - the loops of bench/subnormal, compiled once per precision (subnormal_loops.c). */
#ifndef SUBNORMAL_H
#define SUBNORMAL_H

enum { LOOP_OLD_PARTICLE, LOOP_NEW_PARTICLE, LOOP_OLD_BATCH, LOOP_NEW_BATCH, LOOP_COUNT };

/* ns per particle-step of `loop` over `particles` particles for `steps` steps, the best of `repetitions`;
   velocities start subnormal (`subnormal` = 1) or around 1 m/s. */
double subnormal_measure_float(int loop, int subnormal, int particles, int steps, int repetitions);
double subnormal_measure_double(int loop, int subnormal, int particles, int steps, int repetitions);
const char *subnormal_loop_name(int loop);

#endif

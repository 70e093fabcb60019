/* bench/subnormal - what subnormal velocities cost a damped step, before and after the flush to zero.

   Run (from a build tree configured with -DMOTUS_BUILD_BENCH=ON):
       cmake --build build --target subnormal && build/bench/subnormal
   (--quick: a shorter run, for the smoke test.)

   Damping multiplies velocities by 0.99 every step; left alone they decay into the subnormal range and,
   without the flush, stay there for ever (0.99*v rounds back to v below 50 times the smallest subnormal).
   Each loop (see subnormal_loops.c) runs 4096 coasting particles for 200 steps from velocities that are
   subnormal or around 1 m/s, best of 15 runs, in float and double. The figure that matters is the ratio
   subnormal/normal of one loop, both measured in the same run: > 1 is the cost of the subnormals.
   "old" loops are copies of the step before the flush; "new" ones call motus.h. Speed is never a ctest
   assertion: this program only reports. Compiled with -O2 and without -ffast-math (which would set the
   CPU's flush-to-zero mode at start-up and hide the effect). */
#include "subnormal.h"

#include <stdio.h>
#include <string.h>

const char *subnormal_loop_name(int loop) {
    static const char *names[LOOP_COUNT] = {"old particle loop (copy, no flush)", "new particle loop (motus.h)",
                                            "old batch loop (copy, no flush)", "new motus_step (motus.h)"};
    return names[loop];
}

int main(int argc, char **argv) {
    const int quick = argc > 1 && strcmp(argv[1], "--quick") == 0;
    const int particles = quick ? 512 : 4096, steps = quick ? 20 : 200, repetitions = quick ? 2 : 15;
    int precision, loop;
    printf("ns per particle-step, %d particles, %d steps, best of %d\n", particles, steps, repetitions);
    printf("| precision | loop | normal v | subnormal v | subnormal / normal |\n|---|---|---|---|---|\n");
    for (precision = 0; precision < 2; ++precision)
        for (loop = 0; loop < LOOP_COUNT; ++loop) {
            double normal, subnormal;
            if (precision == 0) {
                normal = subnormal_measure_float(loop, 0, particles, steps, repetitions);
                subnormal = subnormal_measure_float(loop, 1, particles, steps, repetitions);
            } else {
                normal = subnormal_measure_double(loop, 0, particles, steps, repetitions);
                subnormal = subnormal_measure_double(loop, 1, particles, steps, repetitions);
            }
            if (normal <= 0 || subnormal <= 0) return 1;
            printf("| %s | %s | %.3f | %.3f | %.2f |\n", precision ? "double" : "float", subnormal_loop_name(loop),
                   normal, subnormal, subnormal / normal);
        }
    return 0;
}

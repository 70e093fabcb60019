/* The second translation unit, with main: see unit_a.c. */
#include "motus.h"

#include <stdio.h>

int compile_unit_a(void);

int main(void) {
    motus_particle p;
    int i, bad = compile_unit_a();
    motus_particle_init(&p, motus_v2(400, 300), 2);
    for (i = 0; i < 60; ++i) {
        motus_particle_clear_forces(&p);
        motus_particle_add_force(&p, motus_v2(100, 0));
        motus_particle_step(&p, MOTUS_R(1.0) / MOTUS_R(60.0));
    }
    /* x0 + a*t*(t + h)/2 = 400 + 25*(1 + 1/60) = 425.41667 */
    bad |= p.position.x < MOTUS_R(425.41) || p.position.x > MOTUS_R(425.42);
    printf("%s, sizeof(motus_real) = %d: x after 1 s = %.5f\n", bad ? "FAILED" : "ok", (int)sizeof(motus_real),
           (double)p.position.x);
    return bad;
}

/* The second translation unit, with main: motus.h without MOTUS_IMPLEMENTATION (declarations and inline
   functions only), calling the engine unit_a.c compiled. See unit_a.c. */
#include "motus.h"

#include <stdio.h>
#include <string.h>

int compile_unit_a(void);

int main(void) {
    motus_particle p, q;
    motus_scene scene;
    motus_state state = motus_state_of_particles(&q, 1);
    int i, bad = compile_unit_a();
    memset(&scene, 0, sizeof scene);
    motus_particle_init(&p, motus_v2(400, 300), 2);
    q = p;
    for (i = 0; i < 60; ++i) {
        motus_particle_clear_forces(&p);
        motus_particle_add_force(&p, motus_v2(100, 0));
        motus_particle_step(&p, MOTUS_R(1.0) / MOTUS_R(60.0));
        /* The same push through the engine (compiled in unit_a.c): the same bits. */
        motus_particle_clear_forces(&q);
        motus_particle_add_force(&q, motus_v2(100, 0));
        bad |= motus_step(&scene, &state, MOTUS_R(1.0) / MOTUS_R(60.0), NULL, 0) != MOTUS_OK;
    }
    /* x0 + a*t*(t + h)/2 = 400 + 25*(1 + 1/60) = 425.41667 */
    bad |= p.position.x < MOTUS_R(425.41) || p.position.x > MOTUS_R(425.42);
    bad |= memcmp(&p, &q, sizeof p) != 0;
    printf("%s, sizeof(motus_real) = %d: x after 1 s = %.5f (particle step and motus_step agree: %s)\n",
           bad ? "FAILED" : "ok", (int)sizeof(motus_real), (double)p.position.x,
           memcmp(&p, &q, sizeof p) == 0 ? "yes" : "no");
    return bad;
}

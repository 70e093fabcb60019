/* The second translation unit, with main: motus.h without MOTUS_IMPLEMENTATION (declarations and inline
   functions only), calling the engine unit_a.c compiled. See unit_a.c. */
#include "motus.h"

#include <stdio.h>
#include <string.h>

int compile_unit_a(void);

/* The README's 3D loop. Under tcc 0.9.27 a float motus_vec3 returned by a call was stored with 16 bytes
   into its 12-byte temporary: the two motus_v3 calls as arguments of bounce overwrote the loop counter
   with -5.0f's bits, and the loop never ended (see motus.h, "TCC"). The guard counts in static storage,
   out of the frame's reach. */
static int turns;
static int bounce_loop3(void) {
    /* as the README writes it: these locals, in this order, put the counter where the store landed */
    motus_real dt = MOTUS_R(1.0) / MOTUS_R(60.0);
    motus_particle3 ball;
    int bad = 0;
    motus_particle3_init(&ball, motus_v3(0, 10, 0), MOTUS_R(1.0));
    motus_particle3_add_force(&ball, motus_v3(0, MOTUS_R(-9.81), 0));
    for (int i = 0; i < 240; ++i) {
        if (++turns > 240) return 1;
        bad |= motus_particle3_step(&ball, dt) != MOTUS_OK;
        bad |= motus_particle3_bounce(&ball, motus_v3(-5, 0, -5), motus_v3(5, 20, 5), MOTUS_R(0.8)) != MOTUS_OK;
    }
    return bad | (turns != 240) | (ball.position.y < 0);
}

int main(void) {
    motus_particle p, q;
    motus_scene scene;
    motus_state state = motus_state_of_particles(&q, 1);
    int i, bad = compile_unit_a() | bounce_loop3();
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

/* What a consumer project writes: include motus.h, push a particle for one second, check where it is; then
   the same push through motus_step, the engine compiled in engine.c (linked with this file). */
#include <motus.h>

#include <stdio.h>
#include <string.h>

int main(void) {
    motus_particle p, q;
    motus_scene scene;
    motus_state state;
    int frame, ok;
    memset(&scene, 0, sizeof scene);
    if (motus_particle_init(&p, motus_v2(400, 300), 2) != MOTUS_OK) return 1;
    q = p;
    state = motus_state_of_particles(&q, 1);
    for (frame = 0; frame < 60; ++frame) {
        motus_particle_clear_forces(&p);
        motus_particle_add_force(&p, motus_v2(100, 0));
        motus_particle_step(&p, 1.0f / 60.0f);
        motus_particle_clear_forces(&q);
        motus_particle_add_force(&q, motus_v2(100, 0));
        if (motus_step(&scene, &state, 1.0f / 60.0f, NULL, 0) != MOTUS_OK) return 1;
    }
    ok = p.position.x > 425.41f && p.position.x < 425.42f && memcmp(&p, &q, sizeof p) == 0;
    printf("motus %s: x after 1 s = %.4f (expected 425.4167), motus_step: %.4f\n", MOTUS_VERSION_STRING,
           (double)p.position.x, (double)q.position.x);
    return ok ? 0 : 1;
}

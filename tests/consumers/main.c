/* What a consumer project writes: include motus.h, push a particle for one second, check where it is. */
#include <motus.h>

#include <stdio.h>

int main(void) {
    motus_particle p;
    int frame;
    if (motus_particle_init(&p, motus_v2(400, 300), 2) != MOTUS_OK) return 1;
    for (frame = 0; frame < 60; ++frame) {
        motus_particle_clear_forces(&p);
        motus_particle_add_force(&p, motus_v2(100, 0));
        motus_particle_step(&p, 1.0f / 60.0f);
    }
    printf("motus %s: x after 1 s = %.4f (expected 425.4167)\n", MOTUS_VERSION_STRING, (double)p.position.x);
    return (p.position.x > 425.41f && p.position.x < 425.42f) ? 0 : 1;
}

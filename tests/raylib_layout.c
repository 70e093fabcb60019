/* motus_vec2 has raylib's Vector2 layout (float build): checked at compile time against the real raylib.h,
   then at run time by passing motus positions to raylib's own vector code through a pointer cast. */
#include "motus.h"
#include "raylib.h"

#include <stddef.h>
#include <stdio.h>

typedef char size_matches[sizeof(motus_vec2) == sizeof(Vector2) ? 1 : -1];
typedef char x_matches[offsetof(motus_vec2, x) == offsetof(Vector2, x) ? 1 : -1];
typedef char y_matches[offsetof(motus_vec2, y) == offsetof(Vector2, y) ? 1 : -1];

int main(void) {
    motus_particle particles[2];
    const Vector2 *positions;
    motus_vec2 points[3];
    motus_particle_init(&particles[0], motus_v2(3, 4), 1);
    /* An array of motus_vec2 read as an array of Vector2, as a renderer would. */
    points[0] = motus_v2(1, 2);
    points[1] = motus_v2(3, 4);
    points[2] = motus_v2(5, 6);
    positions = (const Vector2 *)(const void *)points;
    if (positions[2].x != 5 || positions[2].y != 6) return 1;
    /* A motus position is accepted by raylib's collision code unchanged. */
    if (!CheckCollisionPointCircle(*(const Vector2 *)(const void *)&particles[0].position, positions[1], 0.5f)) return 1;
    (void)sizeof(size_matches), (void)sizeof(x_matches), (void)sizeof(y_matches);
    puts("motus_vec2 and raylib's Vector2 share their layout");
    return 0;
}

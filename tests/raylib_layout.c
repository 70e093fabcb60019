/* motus_vec2 has raylib's Vector2 layout (float build): checked at compile time against the real raylib.h,
   then at run time by copying an array of motus positions into raylib vectors byte for byte (memcpy: reading
   one struct type through a pointer to another breaks C's aliasing rules, even with the same layout). */
#include "motus.h"
#include "raylib.h"

#include <stddef.h>
#include <string.h>
#include <stdio.h>

typedef char size_matches[sizeof(motus_vec2) == sizeof(Vector2) ? 1 : -1];
typedef char x_matches[offsetof(motus_vec2, x) == offsetof(Vector2, x) ? 1 : -1];
typedef char y_matches[offsetof(motus_vec2, y) == offsetof(Vector2, y) ? 1 : -1];

int main(void) {
    motus_particle particle;
    Vector2 positions[3], position;
    motus_vec2 points[3];
    motus_particle_init(&particle, motus_v2(3, 4), 1);
    points[0] = motus_v2(1, 2);
    points[1] = motus_v2(3, 4);
    points[2] = motus_v2(5, 6);
    memcpy(positions, points, sizeof points); /* one copy for a whole array, as a renderer would */
    if (positions[2].x != 5 || positions[2].y != 6) return 1;
    memcpy(&position, &particle.position, sizeof position);
    if (!CheckCollisionPointCircle(position, positions[1], 0.5f)) return 1;
    (void)sizeof(size_matches), (void)sizeof(x_matches), (void)sizeof(y_matches);
    puts("motus_vec2 and raylib's Vector2 share their layout");
    return 0;
}

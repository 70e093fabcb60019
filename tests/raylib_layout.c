/* motus_vec2 and motus_vec3 have raylib's Vector2 and Vector3 layouts (float build): checked at compile time
   against the real raylib.h, then at run time by copying arrays of motus positions into raylib vectors byte
   for byte (memcpy: reading one struct type through a pointer to another breaks C's aliasing rules, even
   with the same layout). */
#include "motus.h"
#include "raylib.h"

#include <stddef.h>
#include <string.h>
#include <stdio.h>

typedef char size_matches[sizeof(motus_vec2) == sizeof(Vector2) ? 1 : -1];
typedef char x_matches[offsetof(motus_vec2, x) == offsetof(Vector2, x) ? 1 : -1];
typedef char y_matches[offsetof(motus_vec2, y) == offsetof(Vector2, y) ? 1 : -1];
typedef char size3_matches[sizeof(motus_vec3) == sizeof(Vector3) ? 1 : -1];
typedef char x3_matches[offsetof(motus_vec3, x) == offsetof(Vector3, x) ? 1 : -1];
typedef char y3_matches[offsetof(motus_vec3, y) == offsetof(Vector3, y) ? 1 : -1];
typedef char z3_matches[offsetof(motus_vec3, z) == offsetof(Vector3, z) ? 1 : -1];

int main(void) {
    motus_particle particle;
    motus_particle3 particle3;
    Vector2 positions[3], position;
    Vector3 positions3[3], position3;
    motus_vec2 points[3];
    motus_vec3 points3[3];
    motus_particle_init(&particle, motus_v2(3, 4), 1);
    motus_particle3_init(&particle3, motus_v3(4, 5, 6), 1);
    points[0] = motus_v2(1, 2);
    points[1] = motus_v2(3, 4);
    points[2] = motus_v2(5, 6);
    memcpy(positions, points, sizeof points); /* one copy for a whole array, as a renderer would */
    if (positions[2].x != 5 || positions[2].y != 6) return 1;
    memcpy(&position, &particle.position, sizeof position);
    if (!CheckCollisionPointCircle(position, positions[1], 0.5f)) return 1;

    points3[0] = motus_v3(1, 2, 3);
    points3[1] = motus_v3(4, 5, 6);
    points3[2] = motus_v3(7, 8, 9);
    memcpy(positions3, points3, sizeof points3);
    if (positions3[2].x != 7 || positions3[2].y != 8 || positions3[2].z != 9) return 1;
    memcpy(&position3, &particle3.position, sizeof position3);
    if (!CheckCollisionSpheres(position3, 0.25f, positions3[1], 0.25f)) return 1;
    if (CheckCollisionSpheres(position3, 0.25f, positions3[0], 0.25f)) return 1;

    (void)sizeof(size_matches), (void)sizeof(x_matches), (void)sizeof(y_matches);
    (void)sizeof(size3_matches), (void)sizeof(x3_matches), (void)sizeof(y3_matches), (void)sizeof(z3_matches);
    puts("motus_vec2 and motus_vec3 share raylib's Vector2 and Vector3 layouts");
    return 0;
}

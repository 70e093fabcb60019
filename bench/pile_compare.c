/* The README's comparison of the contact solver with and without its support sweeps: 2,000 balls (r = 0.5,
   restitution 0.2, friction 0.3) dropped in rows into a box under gravity 10, stepped at 60 Hz; every
   second it prints the kinetic energy over the potential energy they fell from, the largest overlap over
   the radius (motus_find_contacts) and the lowest ball; at the end the CPU time per step.

       gcc -O2 -std=c99 -Iinclude bench/pile_compare.c -o pile -lm
       gcc -O2 -std=c99 -Iinclude -DMOTUS_CONTACT_SUPPORT_SWEEPS=0 bench/pile_compare.c -o pile_plain -lm
       ./pile DIMS SUBSTEPS ITERATIONS STEPS      (defaults 2 4 4 600)

   Environment: E (restitution, 0.2), MU (friction, 0.3). */
#define MOTUS_IMPLEMENTATION
#define MOTUS_STATIC
#include "motus.h"

#include <math.h>
#include <string.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#define N 2000
static motus_real x[3][N], v[3][N];
static motus_contact_pair pairs[20 * N];

int main(int argc, char **argv) {
    const int dims = argc > 1 ? atoi(argv[1]) : 2, substeps = argc > 2 ? atoi(argv[2]) : 4;
    const int iterations = argc > 3 ? atoi(argv[3]) : 4, steps = argc > 4 ? atoi(argv[4]) : 600;
    const motus_real r = MOTUS_R(0.5), side = dims == 2 ? 40 : 12;
    const int per_row = (int)(side / (MOTUS_R(2.2) * r));
    motus_scene scene;
    motus_state state;
    double potential = 0;
    clock_t start;
    size_t bytes;
    void *scratch;
    int i, d, k;
    if (dims != 2 && dims != 3) return 2;
    memset(&scene, 0, sizeof scene);
    memset(&state, 0, sizeof state);
    scene.gravity = motus_v3(0, -10, 0);
    scene.bounds_min = motus_v3(0, 0, 0);
    scene.bounds_max = motus_v3(side, (motus_real)HUGE_VAL, side);
    scene.contacts.enabled = 1;
    scene.contacts.radius = r;
    scene.contacts.restitution = getenv("E") ? (motus_real)atof(getenv("E")) : MOTUS_R(0.2);
    scene.contacts.friction = getenv("MU") ? (motus_real)atof(getenv("MU")) : MOTUS_R(0.3);
    scene.contacts.iterations = iterations;
    scene.restitution = scene.contacts.restitution;
    scene.substeps = substeps;
    srand(1);
    for (i = 0; i < N; ++i) {
        const int column = i % per_row, layer = i / per_row;
        x[0][i] = r * MOTUS_R(1.1) + (motus_real)column * MOTUS_R(2.2) * r + (motus_real)(rand() % 100) * MOTUS_R(1e-3);
        if (dims == 2) {
            x[1][i] = r * MOTUS_R(1.1) + (motus_real)layer * MOTUS_R(2.2) * r + 5;
        } else {
            x[2][i] = r * MOTUS_R(1.1) + (motus_real)(layer % per_row) * MOTUS_R(2.2) * r;
            x[1][i] = r * MOTUS_R(1.1) + (motus_real)(layer / per_row) * MOTUS_R(2.2) * r + 5;
        }
        potential += 10.0 * ((double)x[1][i] - (double)r);
    }
    state.dimensions = dims;
    state.count = N;
    for (d = 0; d < 3; ++d) state.position[d] = x[d], state.velocity[d] = v[d];
    bytes = motus_scratch_size(&scene, &state);
    scratch = malloc(bytes);
    if (!scratch) return 1;
    start = clock();
    for (k = 1; k <= steps; ++k) {
        const motus_result result = motus_step(&scene, &state, MOTUS_R(1.0) / 60, scratch, bytes);
        if (result != MOTUS_OK) {
            printf("step %d: %s\n", k, motus_result_string(result));
            return 1;
        }
        if (k % 60 == 0) {
            double kinetic = 0, largest = 0, lowest = HUGE_VAL;
            int found = 0;
            for (i = 0; i < N; ++i) {
                for (d = 0; d < dims; ++d) kinetic += 0.5 * (double)v[d][i] * (double)v[d][i];
                if (x[1][i] < lowest) lowest = x[1][i];
            }
            motus_find_contacts(&scene, &state, scratch, bytes, pairs, 20 * N, &found);
            for (i = 0; i < found && i < 20 * N; ++i) {
                double d2 = 0, overlap;
                for (d = 0; d < dims; ++d) {
                    const double u = (double)x[d][pairs[i].a] - (double)x[d][pairs[i].b];
                    d2 += u * u;
                }
                overlap = 2 * (double)r - sqrt(d2);
                if (overlap > largest) largest = overlap;
            }
            printf("t %2d s: kinetic / initial potential %.3g, largest overlap %.4f r, %d overlapping pairs, "
                   "lowest %.4f\n", k / 60, kinetic / potential, largest / (double)r, found, lowest);
        }
    }
    printf("ms per step %.3f (CPU time)\n", 1000.0 * (double)(clock() - start) / CLOCKS_PER_SEC / steps);
    free(scratch);
    return 0;
}

/* The snippets of motus.h's >>usage section (and the README's), as written there, in one program: they must
   compile without a warning under -Wall -Wextra -Wpedantic -Werror and run. Keep in sync with >>usage. */
#define MOTUS_IMPLEMENTATION
#include "motus.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The textbook step on one particle. */
static motus_particle textbook(motus_real dt) {
    motus_particle ball;
    int frame;
    motus_particle_init(&ball, motus_v2(400, 300), 2);          // at the centre, 2 kg
    for (frame = 0; frame < 60; ++frame) {                       // every frame:
        motus_particle_clear_forces(&ball);
        motus_particle_add_force(&ball, motus_v2(100, 0));          // push right (N)
        motus_particle_step(&ball, dt);                              // v += F/m*dt; x += v*dt
        motus_particle_damp_per_step(&ball, 0.01f);                  // v *= 0.99, as the reference
    }
    return ball;
}

/* A scene over many particles. */
static motus_result many(motus_particle *balls, int count, motus_real dt) {
    motus_scene scene = {0};                        // zero: no forces, semi-implicit Euler, 1 kg each
    scene.gravity = motus_v3(0, 9.81f, 0);
    scene.method = MOTUS_RK4;
    motus_state state = motus_state_of_particles(balls, count);   // your motus_particle array, or:
    // state.dimensions = 3; state.count = n; state.position[0] = x; ... (one array per component)
    motus_result r = motus_step(&scene, &state, dt, NULL, 0);
    if (r != MOTUS_OK) fprintf(stderr, "motus: %s\n", motus_result_string(r));
    return r;
}

/* The README's parallel_for snippet, run serially: a pile stepped through it has the bits of one without. */
typedef struct my_pool_type { int threads; } my_pool_type;
static my_pool_type my_pool;
static void my_parallel_for(void *pool, motus_task_function task, void *task_context, int task_count) {
    /* your job system: e.g. one contiguous range per thread, the calling thread included, then wait for
       all. Run serially, this is the whole of a correct one (and what a pool of one thread does): */
    (void)pool;
    task(task_context, 0, task_count);
}

/* Collisions (the README's and >>usage's snippet): balls that pile up on the floor of a box; on_threads:
   through the parallel_for above. */
static motus_result pile(motus_particle *balls, int count, motus_real dt, int on_threads) {
    motus_scene scene = {0};
    motus_state state = motus_state_of_particles(balls, count);
    motus_result r = MOTUS_OK;
    int frame;
    scene.contacts.enabled = 1;
    scene.contacts.radius = 8;              /* or state.radius = radii: one per particle */
    scene.contacts.restitution = 0.3f;      /* between particles; the walls use scene.restitution */
    scene.contacts.friction = 0.3f;
    scene.gravity = motus_v3(0, 500, 0);    /* raylib: y grows downwards */
    scene.bounds_min = motus_v3(0, 0, 0);
    scene.bounds_max = motus_v3(800, 450, 0);
    size_t bytes = motus_scratch_size(&scene, &state);   /* the grid and the contact list live here */
    void *scratch = malloc(bytes);
    if (on_threads) {
        scene.parallel_for = my_parallel_for;
        scene.parallel_context = &my_pool;                  /* whatever my_parallel_for receives as pool */
    }
    for (frame = 0; frame < 300 && r == MOTUS_OK; ++frame) r = motus_step(&scene, &state, dt, scratch, bytes);
    free(scratch);
    return r;
}

/* The README's 3D snippet, one frame. */
static motus_particle3 fall_3d(motus_real dt) {
    motus_particle3 ball;
    motus_particle3_init(&ball, motus_v3(0, 10, 0), 1.0f);
    motus_particle3_add_force(&ball, motus_v3(0, -9.81f, 0));          /* gravity on 1 kg, added once */
    motus_particle3_step(&ball, dt);
    motus_particle3_bounce(&ball, motus_v3(-5, 0, -5), motus_v3(5, 20, 5), 0.8f);
    return ball;
}

/* The README's fixed-step clock, over frames whose first is raylib's 0 (no step: the ball is drawn where it
   is, from a `previous` set before the first frame) and one a 0.5 s hitch. */
static const float frame_times[] = {0, 1.0f / 60, 1.0f / 30, 0.5f, 1.0f / 60};
static int frame_index;
static float GetFrameTime(void) { return frame_times[frame_index++ % 5]; } /* raylib's, here scripted */
static int clock_frames(void) {
    motus_particle ball;
    int frame, bad = 0;
    motus_particle_init(&ball, motus_v2(400, 300), 2);
    ball.velocity = motus_v2(60, 0);
    motus_clock clock;
    motus_clock_init(&clock, 1.0f / 60, 0);            /* 0: at most MOTUS_CLOCK_DEFAULT_MAX_STEPS (8) a frame */
    motus_vec2 previous = ball.position;               /* the position a step before the newest */
    for (frame = 0; frame < 5; ++frame) {
        /* every frame */
        int steps;
        motus_clock_advance(&clock, GetFrameTime(), &steps);
        for (int i = 0; i < steps; ++i) { previous = ball.position; motus_particle_step(&ball, 1.0f / 60); }
        motus_vec2 drawn = motus_vec2_lerp(previous, ball.position, motus_clock_alpha(&clock)); /* between steps */
        bad |= !(drawn.x >= previous.x && drawn.x <= ball.position.x && drawn.y == 300);
    }
    /* 0 + 1 + 2 + 8 (the hitch's 30 steps, capped) + 1 = 12 steps of 1 px at 60 px/s */
    bad |= !(ball.position.x > 411.99f && ball.position.x < 412.01f);
    return bad;
}

/* The README's tether snippet, the mouse at (600, 200): the balls end on it. */
static int GetMouseX(void) { return 600; } /* raylib's, here a mouse that does not move */
static int GetMouseY(void) { return 200; }
static motus_result follow_the_mouse(motus_particle *balls, int count, motus_real dt) {
    motus_scene scene = {0};
    motus_state state = motus_state_of_particles(balls, count);
    motus_result r = MOTUS_OK;
    int frame;
    for (frame = 0; frame < 600 && r == MOTUS_OK; ++frame) {
        scene.tether = motus_v3(GetMouseX(), GetMouseY(), 0);   /* every frame: the spring's fixed end */
        scene.tether_stiffness = 20;                            /* N/m: w = sqrt(k/m) rad/s */
        scene.linear_drag = 2;                                  /* 1/s: settles instead of orbiting for ever */
        r = motus_step(&scene, &state, dt, NULL, 0);
    }
    return r;
}

int main(void) {
    motus_particle ball = textbook(1.0f / 60.0f), balls[3];
    int i, bad = 0;
    for (i = 0; i < 3; ++i) motus_particle_init(&balls[i], motus_v2((motus_real)i, 0), 1);
    bad |= !(ball.position.x > 400 && ball.position.x < 425.42f);
    bad |= many(balls, 3, 0.5f) != MOTUS_OK;
    bad |= balls[2].position.x != 2 || !(balls[2].position.y > 1.2f && balls[2].position.y < 1.3f); /* g t^2/2 */
    for (i = 0; i < 3; ++i) motus_particle_init(&balls[i], motus_v2(400, 100 + 20 * (motus_real)i), 1);
    bad |= pile(balls, 3, 1.0f / 60.0f, 0) != MOTUS_OK;
    bad |= balls[2].position.y != 450 - 8 || balls[2].velocity.y != 0; /* the lowest: at rest on the floor */
    bad |= !(balls[0].position.y < 450 - 8 - 31.9f);                      /* two balls up: on top, not inside */
    {
        motus_particle threaded[3];
        for (i = 0; i < 3; ++i) motus_particle_init(&threaded[i], motus_v2(400, 100 + 20 * (motus_real)i), 1);
        bad |= pile(threaded, 3, 1.0f / 60.0f, 1) != MOTUS_OK;
        bad |= memcmp(threaded, balls, sizeof threaded) != 0; /* the same bits as pile() */
    }
    {
        motus_particle3 dropped = fall_3d(1.0f / 60.0f);
        bad |= !(dropped.velocity.y < 0 && dropped.position.y < 10 && dropped.position.x == 0);
    }
    bad |= clock_frames();
    bad |= follow_the_mouse(balls, 3, 1.0f / 60.0f) != MOTUS_OK;
    for (i = 0; i < 3; ++i) /* 10 s at a decay rate of 1/s: within a px of the mouse */
        bad |= !(fabs((double)balls[i].position.x - 600) < 1 && fabs((double)balls[i].position.y - 200) < 1);
    printf("%s: the >>usage snippets compile and run (x = %.3f, y = %.4f)\n", bad ? "FAILED" : "ok",
           (double)ball.position.x, (double)balls[2].position.y);
    return bad;
}

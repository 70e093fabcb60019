/* Two translation units include motus.h and link into one program: this one compiles the engine
   (MOTUS_IMPLEMENTATION, extern functions), unit_b.c only the declarations and the inline functions, and
   calls the engine from there, so the link proves the stb-style implementation section is defined once and
   declared alike. This unit touches every public function so that the strict warning flags of the compile
   matrix see all of them. Also compiled as C++ (-x c++). Structs are zeroed with memset: `= {0}` warns in
   C++ under -Wextra (missing initializers). */
#define MOTUS_IMPLEMENTATION
/* <windows.h> (minwindef.h, MSVC and MinGW) defines near and far as nothing: a local of either name in the
   implementation would not compile after it (motus.h had three until 2026-11-27). */
#define near
#define far
#include "motus.h"
#undef near
#undef far

#include <string.h>

/* tcc has no vector extensions: the header must pick the one-particle-at-a-time kernels by itself. */
#if defined(__TINYC__) && MOTUS__VECTOR
#error "motus.h chose vector kernels under tcc"
#endif

int compile_unit_a(void);

static void count_calls(void *user_data, const motus_force_query *query) {
    (void)query;
    *(int *)user_data += 1;
}

/* A spring between two particles under gravity, with a callback, stepped with RK4 over SoA arrays. */
static int compile_springs(void) {
    motus_real x[2] = {0, 2}, y[2] = {1, 1}, vx[2] = {0, 0}, vy[2] = {0, 0};
    double scratch[256]; /* aligned for motus_real in both precisions */
    motus_spring spring;
    motus_scene scene;
    motus_state state;
    motus_check_report report;
    motus_real max_dt = 0;
    int calls = 0, substeps = 0, bad = 0;
    memset(&spring, 0, sizeof spring);
    memset(&scene, 0, sizeof scene);
    memset(&state, 0, sizeof state);
    spring.a = 0;
    spring.b = 1;
    spring.rest_length = 1;
    spring.stiffness = 10;
    scene.method = MOTUS_RK4;
    scene.gravity = motus_v3(0, MOTUS_R(-9.81), 0);
    scene.springs = &spring;
    scene.spring_count = 1;
    scene.force_callback = count_calls;
    scene.user_data = &calls;
    state.count = 2;
    state.position[0] = x;
    state.position[1] = y;
    state.velocity[0] = vx;
    state.velocity[1] = vy;
    bad |= motus_scene_check(&scene, 2, 2, &report) != MOTUS_OK;
    bad |= motus_state_check(&scene, &state, 0, 2, &report) != MOTUS_OK || report.index != -1;
    bad |= motus_scratch_size(&scene, &state) > sizeof scratch || motus_scratch_size(&scene, &state) == 0;
    bad |= motus_step(&scene, &state, MOTUS_R(0.5), scratch, sizeof scratch) != MOTUS_OK;
    bad |= calls != motus_method_evaluations(MOTUS_RK4) || motus_method_order(MOTUS_RK4) != 4;
    bad |= x[0] <= 0 || x[1] >= 2 || y[0] >= 1; /* the spring pulled them together; they fall */
    bad |= motus_step_range(&scene, &state, 0, 2, MOTUS_R(0.5)) != MOTUS_ERROR_UNSUPPORTED;
    /* k = 10 between two 1 kg particles: w^2 <= 20 (Gershgorin), RK4's limit 2.83/4.47 = 0.63 s. */
    bad |= motus_scene_max_stable_dt(&scene, &state, &max_dt, scratch, sizeof scratch) != MOTUS_OK;
    bad |= max_dt < MOTUS_R(0.6) || max_dt > MOTUS_R(0.7);
    bad |= motus_method_stability_limit(MOTUS_RK4) < 2;
    bad |= motus_max_stable_dt(MOTUS_RK4, 10, 1, &max_dt) != MOTUS_OK;
    bad |= motus_substeps_for(MOTUS_R(0.5), max_dt, MOTUS_R(0.9), &substeps) != MOTUS_OK || substeps != 1;
    bad |= motus_method_name(MOTUS_RK4) == NULL || motus_method_name(MOTUS_METHOD_COUNT) != NULL;
    scene.damping_per_step = 2;
    bad |= motus_scene_check(&scene, 2, 2, &report) != MOTUS_ERROR_INVALID_DAMPING;
    bad |= strcmp(report.field_name, "scene.damping_per_step") != 0;
    return bad;
}

/* Three 3D particles in structs (one immovable), gravity, damping per second and walls, stepped as two
   ranges; and one particle bounced by hand. */
static int compile_particles3(void) {
    motus_particle3 p[3];
    motus_scene scene;
    motus_state state = motus_state_of_particles3(p, 3);
    motus_check_report report;
    int bad = 0;
    memset(&scene, 0, sizeof scene);
    scene.gravity = motus_v3(0, MOTUS_R(-9.81), 0);
    scene.damping_per_second = MOTUS_R(0.5);
    scene.bounds_min = motus_v3(-10, -10, -10);
    scene.bounds_max = motus_v3(10, 10, 10);
    scene.restitution = MOTUS_R(0.5);
    bad |= motus_particle3_init(&p[0], motus_v3(0, 1, 0), 1) != MOTUS_OK;
    bad |= motus_particle3_init(&p[1], motus_v3(2, 1, 0), 2) != MOTUS_OK;
    bad |= motus_particle3_init_immovable(&p[2], motus_v3(6, 1, 0)) != MOTUS_OK;
    p[2].velocity = motus_v3(10, 0, 0);
    bad |= motus_particle3_add_force(&p[1], motus_v3(0, 0, 4)) != MOTUS_OK;
    bad |= motus_particles3_check(p, 3, &report) != MOTUS_OK;
    bad |= motus_step_range(&scene, &state, 0, 2, MOTUS_R(0.5)) != MOTUS_OK;
    bad |= motus_step_range(&scene, &state, 2, 1, MOTUS_R(0.5)) != MOTUS_OK;
    bad |= p[0].position.y >= 1 || p[1].position.z <= 0; /* falling; pushed along z */
    bad |= p[2].position.x != 9 || p[2].velocity.x != -5; /* immovable: drifts 1 past the wall, bounces back */
    bad |= motus_step_range(&scene, &state, 0, -1, 1) != MOTUS_ERROR_INVALID_COUNT;
    bad |= motus_particle3_step(&p[0], MOTUS_R(0.5)) != MOTUS_OK;
    bad |= motus_particle3_damp_per_step(&p[0], MOTUS_R(0.5)) != MOTUS_OK;
    bad |= motus_particle3_damp_per_second(&p[0], MOTUS_R(0.5), MOTUS_R(0.5)) != MOTUS_OK;
    bad |= motus_particle3_clear_forces(&p[1]) != MOTUS_OK || motus_particle3_check(&p[1]) != MOTUS_OK;
    bad |= motus_particle3_mass(&p[1]) != 2 || motus_particle3_mass(&p[2]) <= MOTUS_R(1e30);
    {
        motus_vec3 carry = motus_v3(0, 0, 0);
        bad |= motus_particle3_step_compensated(&p[1], &carry, MOTUS_R(0.5)) != MOTUS_OK;
    }
    p[0].position = motus_v3(12, 0, 0);
    p[0].velocity = motus_v3(4, 0, 0);
    bad |= motus_particle3_bounce(&p[0], motus_v3(-10, -10, -10), motus_v3(10, 10, 10), MOTUS_R(0.5)) != MOTUS_OK;
    bad |= p[0].position.x != 8 || p[0].velocity.x != -2;
    bad |= motus_vec3_length(motus_vec3_sub(motus_v3(3, 4, 0), motus_vec3_scale(motus_v3(0, 0, 1), 0))) != 5;
    bad |= motus_vec3_dot(motus_v3(1, 2, 3), motus_vec3_add(motus_v3(1, 1, 1), motus_v3(0, 0, 0))) != 6;
    bad |= !motus_vec3_is_finite(motus_vec3_lerp(motus_v3(0, 0, 0), motus_v3(1, 1, 1), MOTUS_R(0.5)));
    return bad;
}

int compile_unit_a(void) {
    motus_particle p, wall;
    motus_vec2 carry = motus_v2(0, 0);
    motus_clock clock;
    int bad = compile_springs() | compile_particles3(), steps = 0;
    bad |= motus_particle_init(&p, motus_v2(400, 300), 2) != MOTUS_OK;
    bad |= motus_particle_init_immovable(&wall, motus_v2(0, 0)) != MOTUS_OK;
    bad |= motus_particle_add_force(&p, motus_vec2_sub(motus_v2(100, 0), motus_v2(0, 0))) != MOTUS_OK;
    bad |= motus_particle_step(&p, MOTUS_R(0.5)) != MOTUS_OK; /* v = 25, x = 412.5 */
    bad |= motus_particle_damp_per_step(&p, MOTUS_R(0.5)) != MOTUS_OK;          /* v = 12.5 */
    bad |= motus_particle_damp_per_second(&p, 0, MOTUS_R(0.5)) != MOTUS_OK;     /* 0: nothing removed */
    bad |= motus_particle_clear_forces(&p) != MOTUS_OK;
    bad |= motus_particle_step_compensated(&p, &carry, 1) != MOTUS_OK; /* x += 12.5 */
    bad |= motus_particle_check(&p) != MOTUS_OK;
    bad |= p.position.x != 425 || p.velocity.x != MOTUS_R(12.5);
    bad |= motus_particle_bounce(&p, motus_v2(0, 0), motus_v2(420, 600), 1) != MOTUS_OK || p.position.x != 415;
    bad |= motus_particle_mass(&p) != 2 || motus_particle_mass(&wall) <= MOTUS_R(1e30);
    bad |= motus_vec2_length(motus_vec2_add(motus_v2(3, 0), motus_vec2_scale(motus_v2(0, 2), 2))) != 5;
    bad |= motus_vec2_dot(motus_v2(1, 2), motus_v2(3, 4)) != 11;
    bad |= motus_vec2_lerp(motus_v2(0, 0), motus_v2(2, 4), MOTUS_R(0.5)).y != 2;
    bad |= !motus_real_is_finite(1) || !motus_vec2_is_finite(motus_v2(1, 1));
    bad |= motus_result_string(MOTUS_ERROR_OVERFLOW)[0] == '\0';
    bad |= motus_clock_init(&clock, MOTUS_R(0.25), 0) != MOTUS_OK;
    bad |= motus_clock_advance(&clock, MOTUS_R(0.625), &steps) != MOTUS_OK || steps != 2;
    bad |= motus_clock_alpha(&clock) != MOTUS_R(0.5) || motus_clock_time(&clock) != 0.5;
    {
        motus_check_report report;
        motus_particle two[2];
        two[0] = p, two[1] = wall;
        two[1].velocity.y = (motus_real)NAN;
        bad |= motus_particles_check(two, 2, &report) != MOTUS_ERROR_NOT_FINITE;
        bad |= report.index != 1 || report.field != MOTUS_FIELD_VELOCITY || report.component != 1;
        bad |= strcmp(report.field_name, motus_field_name(MOTUS_FIELD_VELOCITY)) != 0;
    }
    return bad;
}

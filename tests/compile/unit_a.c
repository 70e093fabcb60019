/* Two translation units include motus.h and link into one program: every function is static inline, so
   nothing is defined twice. This unit touches every public function (the batch API included) so that the
   strict warning flags of the compile matrix see all of them. Also compiled as C++ (-x c++). */
#include "motus.h"

#include <string.h>

int compile_unit_a(void);

/* The stepper API: a spring between two particles under gravity, stepped with RK4. The desc is zeroed with
   memset: `= {0}` warns in C++ under -Wextra (missing initializers). */
static void count_calls(void *user_data, int count, const motus_vec2 *positions, const motus_vec2 *velocities,
                        motus_real time, motus_vec2 *forces) {
    (void)count, (void)positions, (void)velocities, (void)time, (void)forces;
    *(int *)user_data += 1;
}

static int compile_stepper(void) {
    motus_vec2 scratch[14]; /* RK4: 7 arrays for 2 particles */
    motus_particle particles[2];
    motus_spring spring;
    motus_forces forces;
    motus_stepper stepper;
    motus_stepper_desc desc;
    int calls = 0, bad = 0;
    memset(&spring, 0, sizeof spring);
    memset(&forces, 0, sizeof forces);
    memset(&desc, 0, sizeof desc);
    spring.a = 0;
    spring.b = 1;
    spring.rest_length = 1;
    spring.stiffness = 10;
    forces.gravity = motus_v2(0, MOTUS_R(-9.81));
    forces.springs = &spring;
    forces.spring_count = 1;
    forces.callback = count_calls;
    forces.user_data = &calls;
    desc.capacity = 2;
    desc.method = MOTUS_RK4;
    desc.scratch = scratch;
    desc.scratch_bytes = sizeof scratch;
    desc.flags = MOTUS_STEPPER_REUSE_FORCES;
    bad |= motus_stepper_scratch_size(MOTUS_RK4, 2) != sizeof scratch;
    bad |= motus_forces_check(&forces, 2) != MOTUS_OK;
    bad |= motus_stepper_init(&stepper, &desc) != MOTUS_OK;
    bad |= motus_particle_init(&particles[0], motus_v2(0, 0), 1) != MOTUS_OK;
    bad |= motus_particle_init(&particles[1], motus_v2(2, 0), 1) != MOTUS_OK;
    bad |= motus_stepper_step(&stepper, particles, 2, &forces, MOTUS_R(0.5)) != MOTUS_OK;
    bad |= calls != motus_method_evaluations(MOTUS_RK4, desc.flags) || motus_method_order(MOTUS_RK4) != 4;
    bad |= stepper.time != MOTUS_R(0.5) || particles[0].position.x <= 0; /* the spring pulled them together */
    {
        /* Stability limits and substepping: k = 10 between two 1 kg particles, w^2 = 20, RK4's limit
           2.83/4.47 = 0.63 s, so 0.5 s at safety 0.9 is one substep. */
        motus_real max_dt = 0;
        int substeps = 0, taken = 0;
        bad |= motus_method_stability_limit(MOTUS_RK4) < 2;
        bad |= motus_max_stable_dt(MOTUS_RK4, 10, 1, &max_dt) != MOTUS_OK;
        bad |= motus_stepper_max_stable_dt(&stepper, particles, 2, &forces, &max_dt) != MOTUS_OK;
        bad |= motus_substeps_for(MOTUS_R(0.5), max_dt, MOTUS_R(0.9), &substeps) != MOTUS_OK || substeps != 1;
        bad |= motus_stepper_step_substepped(&stepper, particles, 2, &forces, MOTUS_R(0.5), MOTUS_R(0.9), 8, &taken) !=
                   MOTUS_OK || taken != substeps;
    }
    motus_stepper_reset(&stepper);
    bad |= motus_method_name(MOTUS_RK4) == NULL || motus_method_name(MOTUS_METHOD_COUNT) != NULL;
    return bad;
}

/* The batch API: three particles in arrays (2D), a spring pushing into the force arrays, gravity, damping
   per second, per-particle masses (one immovable) and bounds, stepped as two ranges; and one particle
   bounced by hand. */
static int compile_batch(void) {
    motus_real x[3] = {0, 2, 5}, y[3] = {1, 1, 1}, vx[3] = {0, 0, 10}, vy[3] = {0, 0, 0};
    motus_real fx[3] = {0, 0, 0}, fy[3] = {0, 0, 0}, inverse_mass[3] = {1, 1, 0};
    motus_spring spring;
    motus_scene scene;
    motus_batch batch;
    motus_particle p;
    const char *field = NULL;
    int index = -1, bad = 0;
    memset(&spring, 0, sizeof spring);
    memset(&scene, 0, sizeof scene);
    memset(&batch, 0, sizeof batch);
    spring.a = 0;
    spring.b = 1;
    spring.rest_length = 1;
    spring.stiffness = 10;
    scene.has = MOTUS_HAS_GRAVITY | MOTUS_HAS_FORCES | MOTUS_HAS_PARTICLE_MASS | MOTUS_HAS_DAMPING_PER_SECOND |
                MOTUS_HAS_BOUNDS;
    scene.method = MOTUS_SEMI_IMPLICIT_EULER;
    scene.gravity[1] = MOTUS_R(-9.81);
    scene.damping = MOTUS_R(0.5);
    scene.bounds_min[0] = scene.bounds_min[1] = -10;
    scene.bounds_max[0] = scene.bounds_max[1] = 10;
    scene.restitution = MOTUS_R(0.5);
    batch.dimensions = 2;
    batch.position[0] = x;
    batch.position[1] = y;
    batch.velocity[0] = vx;
    batch.velocity[1] = vy;
    batch.force[0] = fx;
    batch.force[1] = fy;
    batch.inverse_mass = inverse_mass;
    bad |= motus_scene_check(&scene, &batch) != MOTUS_OK;
    bad |= motus_batch_check(&scene, &batch, 0, 3, &index, &field) != MOTUS_OK || field != NULL;
    {
        motus_check_report report;
        bad |= motus_batch_check_report(&scene, &batch, 0, 3, &report) != MOTUS_OK || report.index != -1;
    }
    /* d = x0 - x1 = -2: F = -k*d + k*L*d/|d| = 20 - 10 on particle 0, the opposite on particle 1 */
    bad |= motus_batch_add_spring_forces(&batch, 3, &spring, 1) != MOTUS_OK;
    bad |= fx[0] != 10 || fx[1] != -10;
    bad |= motus_batch_step(&scene, &batch, 0, 2, MOTUS_R(0.5)) != MOTUS_OK;
    bad |= motus_batch_step(&scene, &batch, 2, 1, MOTUS_R(0.5)) != MOTUS_OK;
    bad |= x[0] <= 0 || x[1] >= 2 || y[0] >= 1; /* pulled together, falling */
    bad |= x[2] != 10 || y[2] != 1;             /* immovable: 5 + 10*0.5 lands on the wall and stays */
    bad |= motus_batch_step(&scene, &batch, 0, -1, 1) != MOTUS_ERROR_INVALID_COUNT;
    bad |= motus_particle_init(&p, motus_v2(12, 0), 1) != MOTUS_OK;
    p.velocity = motus_v2(4, 0);
    bad |= motus_particle_bounce(&p, motus_v2(-10, -10), motus_v2(10, 10), MOTUS_R(0.5)) != MOTUS_OK;
    bad |= p.position.x != 8 || p.velocity.x != -2;
    return bad;
}

int compile_unit_a(void) {
    motus_particle p, wall;
    motus_real phi1, phi2;
    int bad = compile_stepper() | compile_batch();
    bad |= motus_particle_init(&p, motus_v2(400, 300), 2) != MOTUS_OK;
    bad |= motus_particle_init_immovable(&wall, motus_v2(0, 0)) != MOTUS_OK;
    bad |= motus_particle_add_force(&p, motus_vec2_sub(motus_v2(100, 0), motus_v2(0, 0))) != MOTUS_OK;
    bad |= motus_particle_step(&p, MOTUS_R(0.5)) != MOTUS_OK; /* v = 25, x = 412.5 */
    bad |= motus_particle_damp_per_step(&p, MOTUS_R(0.5)) != MOTUS_OK;
    bad |= motus_particle_damp_per_second(&p, 1, MOTUS_R(0.5)) != MOTUS_OK;
    bad |= motus_particle_clear_forces(&p) != MOTUS_OK;
    bad |= motus_particle_step_linear_drag(&p, 0, 1) != MOTUS_OK; /* x += 12.5 */
    bad |= motus_particle_check(&p) != MOTUS_OK;
    bad |= p.position.x != 425 || p.velocity.x != MOTUS_R(12.5);
    bad |= motus_particle_mass(&p) != 2 || motus_particle_mass(&wall) <= MOTUS_R(1e30);
    bad |= motus_vec2_length(motus_vec2_add(motus_v2(3, 0), motus_vec2_scale(motus_v2(0, 2), 2))) != 5;
    bad |= motus_vec2_dot(motus_v2(1, 2), motus_v2(3, 4)) != 11;
    bad |= !motus_real_is_finite(1) || !motus_vec2_is_finite(motus_v2(1, 1));
    bad |= motus_damping_per_second_from_per_step(1, 60) != 1;
    motus__drag_phi(0, &phi1, &phi2);
    bad |= phi1 != 1;
    bad |= motus_result_string(MOTUS_ERROR_OVERFLOW)[0] == '\0';
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

/* Two translation units include motus.h and link into one program: every function is static inline, so
   nothing is defined twice. This unit touches every public function so that the strict warning flags of the
   compile matrix see all of them. Also compiled as C++ (-x c++). */
#include "motus.h"

int compile_unit_a(void);

int compile_unit_a(void) {
    motus_particle p, wall;
    motus_real phi1, phi2;
    int bad = 0;
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
    return bad;
}

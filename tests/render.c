/* Render tests: the particle is stepped with motus, drawn off-screen through OSMesa the way the WSAD example
   draws it (a radius-5 circle on an 800x600 frame, one unit = one pixel), read back, and its centroid is
   checked against the closed form of the motion.

   Two checks per sampled frame:
   - the simulated state against the exact *discrete* closed form of the method, to rounding;
   - the rendered centroid against the *continuous* closed form x0 + v0*t + a*t^2/2 (or its drag
     counterpart), within PIXEL_TOLERANCE plus the method's known error. For semi-implicit Euler under a
     constant acceleration that error is exactly a*h*t/2 (the discrete form is x0 + v0*t + a*t*(t + h)/2);
     with damping it is the difference of the two closed forms, computed here in double.
   Each test writes a PNG of its trajectory (circles as drawn, green crosses at the continuous closed form)
   to MOTUS_RENDER_DIR. The exact drag stepper and the 3D projectile go through motus_step: this one-unit
   program compiles the engine (MOTUS_IMPLEMENTATION; not MOTUS_STATIC, under which the engine functions
   this file does not call warn -Wunused-function). */
#define MOTUS_IMPLEMENTATION
#include "motus.h"
#include "support/motus_canvas.h"
#include "support/motus_test.h"

#include <stdlib.h>
#include <string.h>

#ifndef MOTUS_RENDER_DIR
#define MOTUS_RENDER_DIR "."
#endif

#define WIDTH 800
#define HEIGHT 600
#define RADIUS 5.0
#define H (1.0 / 60.0)

/* How far the centroid of the drawn circle may sit from the centre it was drawn at. The canvas draws
   raylib's 36-gon with 4x4 samples per pixel; canvas_selftest measures the error over 1,000 random
   centres and phases (it measured 0.025 px at most for radius 5, 0.039 px over radii 2 to 12). The bound leaves room for
   a rasteriser that rounds differently, and is still 8 times finer than the 1/60 s method error the
   tests check (0.42 px after one second of the WSAD push). */
#define PIXEL_TOLERANCE 0.05

static motus_canvas frame_canvas, trail_canvas;
static int canvases_ready;
static double worst_centroid_error; /* |centroid - drawn centre|, over all frames of the run */

static int open_canvases(void) {
    if (canvases_ready) return 1;
    if (motus_canvas_create(&frame_canvas, WIDTH, HEIGHT) != 0) return 0;
    if (motus_canvas_create(&trail_canvas, WIDTH, HEIGHT) != 0) return 0;
    canvases_ready = 1;
    return 1;
}

static void start_trail(void) { motus_canvas_clear(&trail_canvas, 0, 0, 0); }

static void finish_trail(const char *name) {
    char path[512];
    snprintf(path, sizeof path, "%s/%s.png", MOTUS_RENDER_DIR, name);
    motus_canvas_read(&trail_canvas);
    ENSURE(motus_canvas_write_png(&trail_canvas, path) == 0);
    printf("  picture: %s\n", path);
}

/* Draw the particle alone on a black frame, as the example does, and return the rendered centroid. Also
   add it to the trail picture with a cross where the continuous closed form puts it. */
static void render(motus_vec2 position, double expected_x, double expected_y, double *x, double *y) {
    double area = 0;
    motus_canvas_clear(&frame_canvas, 0, 0, 0);
    motus_canvas_draw_circle(&frame_canvas, position.x, position.y, RADIUS, 255, 255, 255);
    motus_canvas_read(&frame_canvas);
    ENSURE(motus_canvas_centroid(&frame_canvas, 255, 255, 255, x, y, &area) == 0);
    /* The whole 36-gon (area 18 r^2 sin 10 deg) is on screen; sampling moves its edge by a fraction of a pixel. */
    ENSURE_NEAR(area, 3.1257 * RADIUS * RADIUS, 0.03 * 3.1257 * RADIUS * RADIUS);
    {
        double ex = *x - position.x, ey = *y - position.y, e = sqrt(ex * ex + ey * ey);
        if (e > worst_centroid_error) worst_centroid_error = e;
    }
    motus_canvas_draw_circle(&trail_canvas, position.x, position.y, RADIUS, 255, 255, 255);
    motus_canvas_draw_cross(&trail_canvas, expected_x, expected_y, 4, 0, 255, 0);
}

/* Float rounding of a state reached in `steps` steps: a few ulps of the coordinate per step. */
static double rounding(int steps, double magnitude) { return steps * 4.0 * MOTUS_REAL_EPSILON * (fabs(magnitude) + 1); }

typedef struct expectation {
    double discrete_x, discrete_y;     /* exact discrete closed form of the method */
    double continuous_x, continuous_y; /* exact solution of the differential equation */
} expectation;

/* The two checks of one sampled frame (see the top of the file), on the position as drawn (x, y). */
static void check_position(motus_vec2 position, int steps, expectation e) {
    double cx, cy;
    ENSURE_NEAR(position.x, e.discrete_x, rounding(steps, e.discrete_x));
    ENSURE_NEAR(position.y, e.discrete_y, rounding(steps, e.discrete_y));
    render(position, e.continuous_x, e.continuous_y, &cx, &cy);
    ENSURE_NEAR(cx, e.continuous_x, PIXEL_TOLERANCE + fabs(e.discrete_x - e.continuous_x));
    ENSURE_NEAR(cy, e.continuous_y, PIXEL_TOLERANCE + fabs(e.discrete_y - e.continuous_y));
}
static void check_frame(const motus_particle *p, int steps, expectation e) { check_position(p->position, steps, e); }

/* Constant acceleration a from x0, v0: semi-implicit Euler lands at x0 + v0*t + a*t*(t + h)/2. */
static expectation constant_acceleration(motus_vec2 x0, motus_vec2 v0, double ax, double ay, int steps) {
    expectation e;
    double t = steps * H;
    e.continuous_x = x0.x + v0.x * t + 0.5 * ax * t * t;
    e.continuous_y = x0.y + v0.y * t + 0.5 * ay * t * t;
    e.discrete_x = x0.x + v0.x * t + 0.5 * ax * t * (t + H);
    e.discrete_y = x0.y + v0.y * t + 0.5 * ay * t * (t + H);
    return e;
}

/* Push a particle of `mass` from x0 with velocity v0 and a constant force for `steps` frames, checking every
   `every` frames; returns the final particle. The force is cleared and re-added each frame, as the example
   does with a held key. */
static motus_particle push(motus_vec2 x0, motus_vec2 v0, double mass, motus_vec2 force, int steps, int every) {
    motus_particle p = {{0, 0}, {0, 0}, {0, 0}, 0};
    int n;
    ENSURE_EQ_INT(motus_particle_init(&p, x0, (motus_real)mass), MOTUS_OK);
    p.velocity = v0;
    for (n = 1; n <= steps; ++n) {
        motus_particle_clear_forces(&p);
        ENSURE_EQ_INT(motus_particle_add_force(&p, force), MOTUS_OK);
        ENSURE_EQ_INT(motus_particle_step(&p, (motus_real)H), MOTUS_OK);
        if (n % every == 0) check_frame(&p, n, constant_acceleration(x0, v0, force.x / mass, force.y / mass, n));
    }
    return p;
}

static void report(const char *name) {
    printf("  %s: largest |rendered centroid - drawn centre| so far %.4f px (tolerance %.2f px)\n", name,
           worst_centroid_error, PIXEL_TOLERANCE);
}

TEST(from_rest_under_constant_force) {
    /* D held for 1.5 s: a = 100/2 = 50 px/s^2, x = 400 + 25 t^2 = 456.25 at t = 1.5 (456.875 discrete). */
    motus_particle p = {{0, 0}, {0, 0}, {0, 0}, 0};
    if (!open_canvases()) { ENSURE(!"OSMesa canvas"); return; }
    start_trail();
    p = push(motus_v2(400, 300), motus_v2(0, 0), 2, motus_v2(100, 0), 90, 6);
    ENSURE_NEAR(p.position.x, 456.875, 1e-3);
    ENSURE(p.position.y == 300);
    finish_trail("from_rest_under_constant_force");
    report("from_rest_under_constant_force");
}

TEST(constant_velocity_without_force) {
    /* No force: x = x0 + v0*t exactly, for the method too (its error term is a*h*t/2 = 0). */
    motus_particle p = {{0, 0}, {0, 0}, {0, 0}, 0};
    if (!open_canvases()) { ENSURE(!"OSMesa canvas"); return; }
    start_trail();
    p = push(motus_v2(100, 500), motus_v2(240, -160), 2, motus_v2(0, 0), 150, 10);
    ENSURE_NEAR(p.position.x, 100 + 240 * 2.5, rounding(150, 700));
    ENSURE_NEAR(p.position.y, 500 - 160 * 2.5, rounding(150, 500));
    finish_trail("constant_velocity_without_force");
    report("constant_velocity_without_force");
}

TEST(twice_the_mass_half_the_displacement) {
    motus_particle light, heavy;
    double light_x, light_y, heavy_x, heavy_y, light_d, heavy_d;
    if (!open_canvases()) { ENSURE(!"OSMesa canvas"); return; }
    start_trail();
    light = push(motus_v2(200, 200), motus_v2(0, 0), 2, motus_v2(100, 0), 120, 10);
    heavy = push(motus_v2(200, 400), motus_v2(0, 0), 4, motus_v2(100, 0), 120, 10);
    render(light.position, light.position.x, light.position.y, &light_x, &light_y);
    render(heavy.position, heavy.position.x, heavy.position.y, &heavy_x, &heavy_y);
    light_d = light_x - 200;
    heavy_d = heavy_x - 200;
    /* Exact in the state; on pixels, each centroid may be off by PIXEL_TOLERANCE. */
    ENSURE_NEAR((heavy.position.x - 200) / (light.position.x - 200), 0.5, 1e-5);
    ENSURE_NEAR(heavy_d / light_d, 0.5, (PIXEL_TOLERANCE + 0.5 * PIXEL_TOLERANCE) / light_d);
    printf("  displacement after 2 s: mass 2 -> %.3f px, mass 4 -> %.3f px, ratio %.5f\n", light_d, heavy_d,
           heavy_d / light_d);
    finish_trail("twice_the_mass_half_the_displacement");
    report("twice_the_mass_half_the_displacement");
}

TEST(wsad_directions) {
    /* Each key alone for one second from the centre: 25*(1 + 1/60) px along its axis, nothing across it. */
    static const struct {
        char key;
        double x, y;
    } keys[4] = {{'W', 0, -1}, {'A', -1, 0}, {'S', 0, 1}, {'D', 1, 0}};
    int i;
    if (!open_canvases()) { ENSURE(!"OSMesa canvas"); return; }
    start_trail();
    for (i = 0; i < 4; ++i) {
        double cx, cy, along, across;
        motus_particle p = push(motus_v2(400, 300), motus_v2(0, 0), 2,
                                motus_v2((motus_real)(100 * keys[i].x), (motus_real)(100 * keys[i].y)), 60, 15);
        render(p.position, 400 + 25 * keys[i].x, 300 + 25 * keys[i].y, &cx, &cy);
        along = (cx - 400) * keys[i].x + (cy - 300) * keys[i].y;
        across = (cx - 400) * keys[i].y - (cy - 300) * keys[i].x;
        printf("  %c: %.3f px along, %.3f px across\n", keys[i].key, along, across);
        ENSURE_NEAR(along, 25.0 * (1 + H), PIXEL_TOLERANCE);
        ENSURE_NEAR(across, 0, PIXEL_TOLERANCE);
    }
    finish_trail("wsad_directions");
    report("wsad_directions");
}

/* The reference's damping: each frame v += a*h, x += v*h, then v *= d (motus_particle_damp_per_step(p, 1 - d):
   the argument is the fraction removed). With w the velocity after damping,
   w_n = w* + (w0 - w*) d^n where w* = d*a*h/(1 - d), and
   x_n = x0 + n*h*a*h/(1 - d) + h*(w0 - w*)*(1 - d^n)/(1 - d).
   The continuous model it discretises is linear drag with k = -ln(d)/h:
   x(t) = x0 + (a/k)*t + (v0 - a/k)*(1 - e^(-k*t))/k. */
static double damped_discrete(double x0, double w0, double a, double d, int n) {
    double w_star = d * a * H / (1 - d);
    return x0 + n * H * a * H / (1 - d) + H * (w0 - w_star) * (1 - pow(d, n)) / (1 - d);
}
static double drag_continuous(double x0, double v0, double a, double k, double t) {
    return x0 + (a / k) * t + (v0 - a / k) * (1 - exp(-k * t)) / k;
}

TEST(damping_per_step_matches_linear_drag) {
    const double d = 0.99, k = -log(d) / H, a = 50, v0 = -30;
    motus_particle p = {{0, 0}, {0, 0}, {0, 0}, 0};
    int n;
    if (!open_canvases()) { ENSURE(!"OSMesa canvas"); return; }
    start_trail();
    motus_particle_init(&p, motus_v2(300, 300), 2);
    p.velocity = motus_v2((motus_real)v0, 0);
    for (n = 1; n <= 180; ++n) {
        motus_particle_clear_forces(&p);
        motus_particle_add_force(&p, motus_v2(100, 0));
        ENSURE_EQ_INT(motus_particle_step(&p, (motus_real)H), MOTUS_OK);
        ENSURE_EQ_INT(motus_particle_damp_per_step(&p, (motus_real)(1 - d)), MOTUS_OK);
        if (n % 10 == 0) {
            expectation e;
            e.discrete_x = damped_discrete(300, v0, a, d, n);
            e.continuous_x = drag_continuous(300, v0, a, k, n * H);
            e.discrete_y = e.continuous_y = 300;
            check_frame(&p, n, e);
            /* The method's error is still first order in h: to leading order in k*h it is
               h/2 * (a*t + v0*(1 - e^(-k*t))), which is a*h*t/2 when starting from rest. */
            {
                double leading = 0.5 * H * (a * n * H + v0 * (1 - exp(-k * n * H)));
                ENSURE_NEAR(e.discrete_x - e.continuous_x, leading, 0.01 * fabs(leading) + 1e-3);
            }
        }
    }
    finish_trail("damping_per_step_matches_linear_drag");
    report("damping_per_step_matches_linear_drag");
}

/* One second at `rate` steps per second; `exact` picks the exact drag stepper (a scene of linear drag k
   stepped by MOTUS_EXACT_LINEAR_DRAG through motus_step), otherwise the reference's step + damp_per_step
   (1% removed). Returns the rendered centroid's x. */
static double one_second_at(int rate, int exact, double k, motus_particle *out) {
    motus_particle p = {{0, 0}, {0, 0}, {0, 0}, 0};
    motus_scene scene;
    motus_state state = motus_state_of_particles(&p, 1);
    double cx, cy;
    int n;
    memset(&scene, 0, sizeof scene);
    scene.method = MOTUS_EXACT_LINEAR_DRAG;
    scene.linear_drag = (motus_real)k;
    motus_particle_init(&p, motus_v2(100, (motus_real)(100 + rate)), 2);
    for (n = 0; n < rate; ++n) {
        motus_particle_clear_forces(&p);
        motus_particle_add_force(&p, motus_v2(100, 0));
        if (exact) {
            ENSURE_EQ_INT(motus_step(&scene, &state, MOTUS_R(1.0) / (motus_real)rate, NULL, 0), MOTUS_OK);
        } else {
            motus_particle_step(&p, MOTUS_R(1.0) / (motus_real)rate);
            motus_particle_damp_per_step(&p, MOTUS_R(0.01));
        }
    }
    render(p.position, drag_continuous(100, 0, 50, k, 1), 100 + rate, &cx, &cy);
    *out = p;
    return cx;
}

TEST(exact_drag_is_frame_rate_independent) {
    /* The same drag as 0.99 per frame at 60 Hz (k = 0.603/s). The exact stepper puts the particle on the
       continuous solution at 30, 60 and 144 steps per second; per-step damping does not. */
    const double k = -log(0.99) * 60, expected = drag_continuous(100, 0, 50, k, 1);
    const int rates[3] = {30, 60, 144};
    double exact_x[3], per_step_x[3];
    motus_particle p = {{0, 0}, {0, 0}, {0, 0}, 0};
    int i;
    if (!open_canvases()) { ENSURE(!"OSMesa canvas"); return; }
    start_trail();
    for (i = 0; i < 3; ++i) {
        exact_x[i] = one_second_at(rates[i], 1, k, &p);
        ENSURE_NEAR(p.position.x, expected, rounding(rates[i], expected));
        ENSURE_NEAR(exact_x[i], expected, PIXEL_TOLERANCE);
        per_step_x[i] = one_second_at(rates[i], 0, k, &p);
        printf("  %3d Hz: exact drag x = %.3f px, per-step 0.99 x = %.3f px (continuous %.3f)\n", rates[i],
               exact_x[i], per_step_x[i], expected);
    }
    /* Per-step damping keeps 0.99^30 = 74% of the speed per second at 30 Hz but 23% at 144 Hz: the
       particles end many pixels apart, which is what the per-second and exact forms exist to avoid. */
    ENSURE(per_step_x[0] - per_step_x[2] > 2.0);
    ENSURE_NEAR(exact_x[0], exact_x[2], 2 * PIXEL_TOLERANCE);
    finish_trail("exact_drag_is_frame_rate_independent");
    report("exact_drag_is_frame_rate_independent");
}

TEST(projectile_3d_drawn_in_the_xy_plane) {
    /* A 3D particle under gravity g = (0, 120, -90) px/s^2 thrown from (150, 450, 40) at (200, -260, 75) px/s,
       stepped by velocity Verlet through motus_step over a motus_particle3, and drawn with an orthographic
       projection onto the screen's x-y plane (z dropped). Under a constant acceleration velocity Verlet is
       exact to rounding: x(t) = x0 + v0*t + g*t^2/2 in all three components, so the discrete and continuous
       forms are one and the drawn centroid must sit on the closed form within PIXEL_TOLERANCE. */
    const double x0[3] = {150, 450, 40}, v0[3] = {200, -260, 75}, g[3] = {0, 120, -90};
    motus_particle3 p;
    motus_scene scene;
    motus_state state = motus_state_of_particles3(&p, 1);
    int n, k;
    if (!open_canvases()) { ENSURE(!"OSMesa canvas"); return; }
    start_trail();
    memset(&scene, 0, sizeof scene);
    scene.method = MOTUS_VELOCITY_VERLET;
    scene.gravity = motus_v3((motus_real)g[0], (motus_real)g[1], (motus_real)g[2]);
    ENSURE_EQ_INT(motus_particle3_init(&p, motus_v3((motus_real)x0[0], (motus_real)x0[1], (motus_real)x0[2]), 3),
                  MOTUS_OK);
    p.velocity = motus_v3((motus_real)v0[0], (motus_real)v0[1], (motus_real)v0[2]);
    for (n = 1; n <= 150; ++n) {
        ENSURE_EQ_INT(motus_step(&scene, &state, (motus_real)H, NULL, 0), MOTUS_OK);
        if (n % 10 == 0) {
            const double t = n * H;
            double exact[3];
            expectation e;
            for (k = 0; k < 3; ++k) exact[k] = x0[k] + v0[k] * t + 0.5 * g[k] * t * t;
            ENSURE_NEAR(p.position.z, exact[2], rounding(n, exact[2]));
            e.discrete_x = e.continuous_x = exact[0];
            e.discrete_y = e.continuous_y = exact[1];
            check_position(motus_v2(p.position.x, p.position.y), n, e); /* the projection: z dropped */
        }
    }
    /* After 2.5 s: x = 650, y = 450 - 650 + 375 = 175, z = 40 + 187.5 - 281.25 = -53.75. */
    ENSURE_NEAR(p.position.x, 650, rounding(150, 650));
    ENSURE_NEAR(p.position.y, 175, rounding(150, 450));
    ENSURE_NEAR(p.position.z, -53.75, rounding(150, 100));
    finish_trail("projectile_3d_drawn_in_the_xy_plane");
    report("projectile_3d_drawn_in_the_xy_plane");
}

static const motus_test_case TESTS[] = {
    TEST_CASE(from_rest_under_constant_force),
    TEST_CASE(constant_velocity_without_force),
    TEST_CASE(twice_the_mass_half_the_displacement),
    TEST_CASE(wsad_directions),
    TEST_CASE(damping_per_step_matches_linear_drag),
    TEST_CASE(exact_drag_is_frame_rate_independent),
    TEST_CASE(projectile_3d_drawn_in_the_xy_plane),
};

int main(int argc, char **argv) {
    int result = motus_test_main(argc, argv, TESTS, TEST_COUNT(TESTS));
    if (canvases_ready) {
        motus_canvas_destroy(&frame_canvas);
        motus_canvas_destroy(&trail_canvas);
    }
    return result;
}

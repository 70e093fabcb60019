/* Render tests of contacts (issue 12, item 6): two balls of equal mass collide head-on in a 2D scene with
   contacts on (one radius for both, the drawn one: the discs touch on screen when the balls touch), are
   stepped by motus_step at 1/60 s a frame, drawn off-screen through OSMesa as in tests/render.c (a 36-gon
   per ball on an 800x600 frame, one unit = one pixel; ball 1 white, ball 2 orange), read back, and each
   ball's centroid is found in the pixels of its colour.

   The closed form of a head-on collision of equal masses with restitution e, approach speeds u1, u2 along
   the line of centres:
       v1' = (1 - e)/2 u1 + (1 + e)/2 u2,   v2' = (1 + e)/2 u1 + (1 - e)/2 u2
   (e = 1: the velocities exchange; the centre of mass keeps (u1 + u2)/2 whatever e). The continuous motion
   is uniform before the contact time t_c = gap0/(u1 - u2) and uniform at v1', v2' from the touching
   positions after it.

   The discrete step resolves the contact at the end of the first frame n at which the balls touch or overlap
   (an approach faster than the restitution threshold, here 0: a collision): the velocities become v1', v2' and an overlap delta is
   projected out, half to each ball; the motion after it is uniform again. Its position differs from the
   continuous one by e*(u1 - u2)/2*(n*h - t_c) after the contact (derived in check_collision), so:
   - when the gap closes exactly at a frame (n*h = t_c) the discrete and continuous forms agree, and the
     drawn centroids must sit on the continuous closed form within PIXEL_TOLERANCE, before and after;
   - when it closes between frames, the state is checked against the discrete form to rounding and the
     centroid against the continuous one within PIXEL_TOLERANCE plus that known error, as tests/render.c
     does with a method's error.
   In every case the speeds read off the pixels (centroid displacement between two frames on one side of
   the contact, over the time between them) must match u1, u2 before and v1', v2' after within
   2*PIXEL_TOLERANCE / (time between the frames), and the pixels' centre of mass must move at (u1 + u2)/2.
   Each test writes a PNG of its trajectory (the balls as drawn every 10 frames, green crosses at the
   continuous closed form) to MOTUS_RENDER_DIR. */
#define MOTUS_IMPLEMENTATION
#define MOTUS_STATIC
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
#define FRAMES 180
/* As tests/render.c (where the bound is explained): canvas_selftest measures 0.025 px at most for radius 5. */
#define PIXEL_TOLERANCE 0.05

static motus_canvas frame_canvas, trail_canvas;
static int canvases_ready;
static double worst_centroid_error; /* |centroid - drawn centre|, over every ball of every frame */

static int open_canvases(void) {
    if (canvases_ready) return 1;
    if (motus_canvas_create(&frame_canvas, WIDTH, HEIGHT) != 0) return 0;
    if (motus_canvas_create(&trail_canvas, WIDTH, HEIGHT) != 0) return 0;
    canvases_ready = 1;
    return 1;
}

static const unsigned char COLOUR[2][3] = {{255, 255, 255}, {255, 160, 0}};

/* Draw both balls on a black frame and return each one's rendered centroid (the samples of its colour). */
static void render(const motus_particle *balls, double centroid[2][2]) {
    int i;
    motus_canvas_clear(&frame_canvas, 0, 0, 0);
    for (i = 0; i < 2; ++i)
        motus_canvas_draw_circle(&frame_canvas, balls[i].position.x, balls[i].position.y, RADIUS, COLOUR[i][0],
                                 COLOUR[i][1], COLOUR[i][2]);
    motus_canvas_read(&frame_canvas);
    for (i = 0; i < 2; ++i) {
        double area = 0, ex, ey, e;
        ENSURE(motus_canvas_centroid(&frame_canvas, COLOUR[i][0], COLOUR[i][1], COLOUR[i][2], &centroid[i][0],
                                     &centroid[i][1], &area) == 0);
        /* Each whole 36-gon is on screen (area 18 r^2 sin 10 deg = 3.1257 r^2), not hidden by the other. */
        ENSURE_NEAR(area, 3.1257 * RADIUS * RADIUS, 0.03 * 3.1257 * RADIUS * RADIUS);
        ex = centroid[i][0] - balls[i].position.x, ey = centroid[i][1] - balls[i].position.y;
        e = sqrt(ex * ex + ey * ey);
        if (e > worst_centroid_error) worst_centroid_error = e;
    }
}

/* One head-on collision: the balls on the line through `centre` along the unit vector (nx, ny), ball i at
   coordinate s0[i] on it with speed u[i] along it (s0[0] < s0[1], u[0] > u[1]: they approach). */
typedef struct collision {
    const char *name;
    double e;
    double centre_x, centre_y, nx, ny;
    double s0[2], u[2];
} collision;

/* What the closed forms say at frame n: the coordinate along the line, continuous and discrete. */
typedef struct closed_form {
    double contact_time; /* t_c = gap0 / (u1 - u2) */
    int contact_frame;   /* the first frame at which the balls touch or overlap */
    double overlap;      /* projected out at that frame, half to each ball */
    double v[2];         /* after the contact */
} closed_form;

static closed_form closed_form_of(const collision *c) {
    closed_form f;
    const double gap0 = c->s0[1] - c->s0[0] - 2 * RADIUS, approach = c->u[0] - c->u[1];
    int n;
    f.contact_time = gap0 / approach;
    for (n = 0; gap0 - approach * n * H > 0; ++n) continue;
    f.contact_frame = n;
    f.overlap = approach * n * H - gap0 > 0 ? approach * n * H - gap0 : 0;
    f.v[0] = (1 - c->e) / 2 * c->u[0] + (1 + c->e) / 2 * c->u[1];
    f.v[1] = (1 + c->e) / 2 * c->u[0] + (1 - c->e) / 2 * c->u[1];
    return f;
}
static double continuous_at(const collision *c, const closed_form *f, int i, double t) {
    if (t <= f->contact_time) return c->s0[i] + c->u[i] * t;
    return c->s0[i] + c->u[i] * f->contact_time + f->v[i] * (t - f->contact_time);
}
static double discrete_at(const collision *c, const closed_form *f, int i, int n) {
    const double push = (i == 0 ? -0.5 : 0.5) * f->overlap;
    if (n < f->contact_frame) return c->s0[i] + c->u[i] * n * H;
    return c->s0[i] + c->u[i] * f->contact_frame * H + push + f->v[i] * (n - f->contact_frame) * H;
}

static void check_collision(const collision *c) {
    const closed_form f = closed_form_of(c);
    motus_particle balls[2];
    motus_scene scene;
    motus_state state;
    unsigned char scratch[4096];
    double centroid[FRAMES + 1][2][2], worst_state = 0, worst_pixel = 0;
    char path[512];
    int n, i;
    if (!open_canvases()) { ENSURE(!"OSMesa canvas"); return; }
    motus_canvas_clear(&trail_canvas, 0, 0, 0);

    memset(&scene, 0, sizeof scene); /* semi-implicit Euler, no forces, no walls */
    scene.contacts.enabled = 1;
    scene.contacts.radius = (motus_real)RADIUS;
    scene.contacts.restitution = (motus_real)c->e;
    for (i = 0; i < 2; ++i) {
        ENSURE_EQ_INT(motus_particle_init(&balls[i],
                                          motus_v2((motus_real)(c->centre_x + c->s0[i] * c->nx),
                                                   (motus_real)(c->centre_y + c->s0[i] * c->ny)), 2),
                      MOTUS_OK);
        balls[i].velocity = motus_v2((motus_real)(c->u[i] * c->nx), (motus_real)(c->u[i] * c->ny));
    }
    state = motus_state_of_particles(balls, 2);
    ENSURE(motus_scratch_size(&scene, &state) <= sizeof scratch);
    printf("  %s: e = %.2f, u = (%.1f, %.1f) px/s; contact at t = %.4f s, frame %d; closed form v' = (%.1f, %.1f)\n",
           c->name, c->e, c->u[0], c->u[1], f.contact_time, f.contact_frame, f.v[0], f.v[1]);

    for (n = 0; n <= FRAMES; ++n) {
        if (n > 0) ENSURE_EQ_INT(motus_step(&scene, &state, (motus_real)H, scratch, sizeof scratch), MOTUS_OK);
        /* drawn every 5 frames, at the contact and the frame after it, and where the speeds are read below */
        if (!(n % 5 == 0 || n - f.contact_frame == 0 || n - f.contact_frame == 1 || n - f.contact_frame == 20 ||
              n - f.contact_frame == -20))
            continue;
        render(balls, centroid[n]);
        for (i = 0; i < 2; ++i) {
            const double s_discrete = discrete_at(c, &f, i, n), s_continuous = continuous_at(c, &f, i, n * H);
            const double method_error = fabs(s_discrete - s_continuous);
            const double px = balls[i].position.x, py = balls[i].position.y;
            const double ex = c->centre_x + s_continuous * c->nx, ey = c->centre_y + s_continuous * c->ny;
            /* the state on the discrete form: float rounding of ~700 px over 180 steps, and of the projection */
            const double rounding = (n + 2) * 2.0 * MOTUS_REAL_EPSILON * 1000;
            const double ds = hypot(px - (c->centre_x + s_discrete * c->nx), py - (c->centre_y + s_discrete * c->ny));
            const double dp = hypot(centroid[n][i][0] - ex, centroid[n][i][1] - ey);
            ENSURE_NEAR(ds, 0, rounding);
            ENSURE_NEAR(dp, 0, PIXEL_TOLERANCE + method_error);
            if (ds > worst_state) worst_state = ds;
            if (dp - method_error > worst_pixel) worst_pixel = dp - method_error;
            /* after the contact the method error is e*(u1 - u2)/2 * (n_c*h - t_c): the discrete ball moved at u
               for n_c*h - t_c too long, then was pushed back by half the overlap (u1 - u2)*(n_c*h - t_c) */
            ENSURE(method_error <= fabs(c->e * (c->u[0] - c->u[1]) / 2 * (f.contact_frame * H - f.contact_time)) + 1e-9);
            if (n % 10 == 0 || n == f.contact_frame) {
                motus_canvas_draw_circle(&trail_canvas, px, py, RADIUS, COLOUR[i][0], COLOUR[i][1], COLOUR[i][2]);
                motus_canvas_draw_cross(&trail_canvas, ex, ey, 4, 0, 255, 0);
            }
        }
        /* the centre of mass of the pixels moves at (u1 + u2)/2, contact or not (equal and opposite) */
        {
            const double mid = (c->s0[0] + c->s0[1]) / 2 + (c->u[0] + c->u[1]) / 2 * n * H;
            ENSURE_NEAR((centroid[n][0][0] + centroid[n][1][0]) / 2, c->centre_x + mid * c->nx, PIXEL_TOLERANCE);
            ENSURE_NEAR((centroid[n][0][1] + centroid[n][1][1]) / 2, c->centre_y + mid * c->ny, PIXEL_TOLERANCE);
        }
    }
    /* the balls touch at the contact frame, and the discs do not overlap after it */
    ENSURE(f.contact_frame > 20 && f.contact_frame + 40 < FRAMES);

    /* Speeds read off the pixels: before the contact from frames 0 and contact-20, after it from contact+20 and
       the last; along the line of centres. */
    {
        const int a0 = 0, a1 = f.contact_frame - 20, b0 = f.contact_frame + 20, b1 = FRAMES;
        for (i = 0; i < 2; ++i) {
            const double before = ((centroid[a1][i][0] - centroid[a0][i][0]) * c->nx +
                                   (centroid[a1][i][1] - centroid[a0][i][1]) * c->ny) / ((a1 - a0) * H);
            const double after = ((centroid[b1][i][0] - centroid[b0][i][0]) * c->nx +
                                  (centroid[b1][i][1] - centroid[b0][i][1]) * c->ny) / ((b1 - b0) * H);
            printf("  ball %d on pixels: %.3f px/s before (closed form %.1f), %.3f px/s after (closed form %.3f)\n",
                   i + 1, before, c->u[i], after, f.v[i]);
            ENSURE_NEAR(before, c->u[i], 2 * PIXEL_TOLERANCE / ((a1 - a0) * H));
            ENSURE_NEAR(after, f.v[i], 2 * PIXEL_TOLERANCE / ((b1 - b0) * H));
        }
    }
    printf("  largest |state - discrete form| %.2e px; largest |centroid - continuous form| beyond the method's "
           "error %.4f px (tolerance %.2f px); largest |centroid - drawn centre| so far %.4f px\n",
           worst_state, worst_pixel, PIXEL_TOLERANCE, worst_centroid_error);
    snprintf(path, sizeof path, "%s/%s.png", MOTUS_RENDER_DIR, c->name);
    motus_canvas_read(&trail_canvas);
    ENSURE(motus_canvas_write_png(&trail_canvas, path) == 0);
    printf("  picture: %s\n", path);
}

/* The speeds are chosen so that each frame's displacement is a short binary fraction (2.5 px, -1.5 px, ...):
   the float state then follows the closed form to a few ulps, and the line of centres at the contact is
   exact to rounding (a generic one in float is off by ~1e-4 rad, which turns 0.02 px/s of the approach into
   the tangent and drifts the balls by ~0.03 px in a second, most of the pixel tolerance). The start is at
   odd sub-pixel offsets (.37, .21), so the discs are sampled at generic phases of the pixel grid. */

/* Ball 1 from x = 200.37 at 150 px/s, ball 2 from x = 570.37 at -90 px/s: the gap of 360 px closes at 4 px a
   frame, exactly at frame 90 (t = 1.5 s, the balls touching at x = 425.37 and 435.37); then they exchange
   their velocities. */
TEST(head_on_equal_masses_exchange_velocities) {
    const collision c = {"head_on_equal_masses_exchange_velocities", 1, 0.37, 300.21, 1, 0, {200, 570}, {150, -90}};
    check_collision(&c);
}

/* Restitution 0.5 along a diagonal (the line of centres along (0.8, 0.6)), u = (150, -75) px/s: the gap of
   360 px closes at 3.75 px a frame, exactly at frame 96; v1' = 0.25*150 - 0.75*75 = -18.75 px/s,
   v2' = 0.75*150 - 0.25*75 = 93.75 px/s (relative speed 225 -> 112.5). */
TEST(head_on_restitution_half_on_a_diagonal) {
    const collision c = {"head_on_restitution_half_on_a_diagonal", 0.5, 400.37, 300.21, 0.8, 0.6, {-185, 185},
                         {150, -75}};
    check_collision(&c);
}

/* The gap (362 px at 4 px a frame) closes half-way between frames 90 and 91: the discrete contact is resolved
   at the end of frame 91 with an overlap of 2 px projected out, which puts each ball e*(u1 - u2)/2*h/2 = 0.5 px
   (e = 0.5) from the continuous form after the contact; the speeds on the pixels are still v1', v2'. */
TEST(head_on_between_two_frames) {
    const collision c = {"head_on_between_two_frames", 0.5, 0.37, 300.21, 1, 0, {200, 572}, {150, -90}};
    check_collision(&c);
}

static const motus_test_case TESTS[] = {
    TEST_CASE(head_on_equal_masses_exchange_velocities),
    TEST_CASE(head_on_restitution_half_on_a_diagonal),
    TEST_CASE(head_on_between_two_frames),
};

int main(int argc, char **argv) {
    int result = motus_test_main(argc, argv, TESTS, TEST_COUNT(TESTS));
    if (canvases_ready) {
        motus_canvas_destroy(&frame_canvas);
        motus_canvas_destroy(&trail_canvas);
    }
    return result;
}

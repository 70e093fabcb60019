/*
 * canvas_selftest - measures how precisely motus_canvas reproduces the
 * position of a drawn circle, and checks image orientation.
 *
 * Usage: canvas_selftest [out.png]   (default: canvas_selftest.png)
 *
 * A circle of radius 5 (white on black) is drawn at a 16 x 16 grid of
 * sub-pixel offsets in [0,1)^2, at a 32 x 32 grid of phases within one
 * sample pitch and at random positions all over an 800x600 canvas; the
 * centroid of the rendered circle is compared with the true centre.  The statistics are printed for plain rasterisation (ss = 1) and
 * for supersampling, and for radii 3, 5 and 10.  Exit status is nonzero if,
 * for the default canvas (MOTUS_CANVAS_DEFAULT_SS) and radius 5, the largest
 * centroid error exceeds MAX_CENTROID_ERROR_PX (or, for radii 3 and 10,
 * MAX_CENTROID_ERROR_ANY_R_PX), or if any orientation/area check fails.
 */
#include "motus_canvas.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Bounds enforced for the default canvas (ss = 4), centroid over samples.
   Measured worst cases (llvmpipe, Mesa 22.3): 0.025 px at r = 5, 0.029 px
   at r = 3, 0.015 px at r = 10; a dense scan of r = 2..12 in steps of 0.5
   peaks at 0.039 px (r = 3.5).  Plain rasterisation (ss = 1): 0.27 px. */
#define MAX_CENTROID_ERROR_PX 0.03     /* r = 5                    */
#define MAX_CENTROID_ERROR_ANY_R_PX 0.05  /* every radius measured  */

#define GRID 16            /* sub-pixel offsets per axis               */
#define PHASES 32          /* phases per axis within one sample pitch  */
#define RANDOM_BATCHES 3   /* frames filled with random positions      */

typedef struct {
    double max_r, max_x, max_y, sum2;
    long n;
} err_stats;

static void stats_add(err_stats *s, double dx, double dy)
{
    double e2 = dx * dx + dy * dy;
    if (sqrt(e2) > s->max_r) s->max_r = sqrt(e2);
    if (fabs(dx) > s->max_x) s->max_x = fabs(dx);
    if (fabs(dy) > s->max_y) s->max_y = fabs(dy);
    s->sum2 += e2;
    s->n += 1;
}

static double stats_rms(const err_stats *s)
{
    return s->n > 0 ? sqrt(s->sum2 / (double)s->n) : 0.0;
}

/* Deterministic xorshift64* in [0, 1). */
static unsigned long long rng_state = 0x9E3779B97F4A7C15ULL;
static double rng_uniform(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (double)((rng_state * 2685821657736338717ULL) >> 11) *
           (1.0 / 9007199254740992.0);
}

/* Coverage-weighted centroid of the box-filtered pixels (red channel as
   weight) over pixels [px0, px1) x [py0, py1). */
static int pixel_weighted_centroid(const motus_canvas *c, int px0, int py0,
                                   int px1, int py1, double *x, double *y)
{
    double w = 0.0, sx = 0.0, sy = 0.0;
    int i, j;
    for (j = py0; j < py1; ++j) {
        for (i = px0; i < px1; ++i) {
            const unsigned char *p = motus_canvas_pixel(c, i, j);
            double v = p ? p[0] / 255.0 : 0.0;
            w += v;
            sx += v * (i + 0.5);
            sy += v * (j + 0.5);
        }
    }
    if (w <= 0.0) return 1;
    *x = sx / w;
    *y = sy / w;
    return 0;
}

typedef struct {
    err_stats samples;   /* exact-colour centroid over samples (the API)   */
    err_stats pixels;    /* intensity-weighted centroid of filtered pixels */
    double area_min, area_max;
    long missing;
} measurement;

/* Draw circles of `radius` on a width x height canvas, one circle per
   square cell so they never touch, and measure every centroid.  Centres,
   relative to a cell's origin:
     - GRID x GRID offsets (a/GRID, b/GRID) from the cell's central integer
       point (sub-pixel positions in [0,1)^2);
     - PHASES x PHASES offsets in [0, 1/ss)^2 from that point: the sample
       lattice has period 1/ss, so this scans every phase of the centre
       relative to the samples and finds the worst case;
     - RANDOM_BATCHES full canvases of uniformly random positions. */
static int measure(int ss, int width, int height, double radius,
                   measurement *m)
{
    motus_canvas c;
    int cell = (int)ceil(4.0 * radius);
    int cols, rows, ncells, npos, k, start;
    double margin = radius + 1.5;
    double *dx, *dy;

    memset(m, 0, sizeof *m);
    m->area_min = 1e300;
    if (cell < 12) cell = 12;
    cols = width / cell;
    rows = height / cell;
    ncells = cols * rows;
    npos = GRID * GRID + PHASES * PHASES + RANDOM_BATCHES * ncells;
    dx = (double *)malloc(sizeof(double) * (size_t)npos);
    dy = (double *)malloc(sizeof(double) * (size_t)npos);
    if (dx == NULL || dy == NULL || motus_canvas_create_ss(&c, width, height,
                                                           ss) != 0) {
        free(dx);
        free(dy);
        return 1;
    }
    for (k = 0; k < GRID * GRID; ++k) {
        dx[k] = cell / 2 + (double)(k % GRID) / GRID;
        dy[k] = cell / 2 + (double)(k / GRID) / GRID;
    }
    for (k = 0; k < PHASES * PHASES; ++k) {
        dx[GRID * GRID + k] = cell / 2 + (double)(k % PHASES) / (PHASES * ss);
        dy[GRID * GRID + k] = cell / 2 + (double)(k / PHASES) / (PHASES * ss);
    }
    for (k = GRID * GRID + PHASES * PHASES; k < npos; ++k) {
        dx[k] = margin + rng_uniform() * (cell - 2.0 * margin);
        dy[k] = margin + rng_uniform() * (cell - 2.0 * margin);
    }

    for (start = 0; start < npos; start += ncells) {
        int count = npos - start < ncells ? npos - start : ncells;
        motus_canvas_clear(&c, 0, 0, 0);
        for (k = 0; k < count; ++k)
            motus_canvas_draw_circle(&c, (k % cols) * cell + dx[start + k],
                                     (k / cols) * cell + dy[start + k],
                                     radius, 255, 255, 255);
        if (motus_canvas_read(&c) != 0) {
            m->missing += count;
            continue;
        }
        for (k = 0; k < count; ++k) {
            int ix = (k % cols) * cell, iy = (k / cols) * cell;
            double tx = ix + dx[start + k], ty = iy + dy[start + k];
            double cx, cy, area;
            if (motus_canvas_centroid_in(&c, ix, iy, ix + cell, iy + cell,
                                         255, 255, 255, &cx, &cy,
                                         &area) != 0) {
                m->missing += 1;
                continue;
            }
            stats_add(&m->samples, cx - tx, cy - ty);
            if (area < m->area_min) m->area_min = area;
            if (area > m->area_max) m->area_max = area;
            if (pixel_weighted_centroid(&c, ix, iy, ix + cell, iy + cell,
                                        &cx, &cy) == 0)
                stats_add(&m->pixels, cx - tx, cy - ty);
        }
    }
    free(dx);
    free(dy);
    motus_canvas_destroy(&c);
    return 0;
}

static int is_colour(const unsigned char *p, int r, int g, int b)
{
    return p != NULL && p[0] == r && p[1] == g && p[2] == b;
}

/* Orientation and drawing checks; writes a trajectory-style picture. */
static int picture_checks(const char *png_path)
{
    motus_canvas c;
    int fails = 0, i;
    double x, y, area;

    if (motus_canvas_create(&c, 800, 600) != 0)
        return 1;
    printf("renderer: %s\n", motus_canvas_renderer(&c));

    motus_canvas_clear(&c, 0, 0, 0);
    /* trajectory: a projectile arc, circles in changing colour, no clear */
    for (i = 0; i <= 30; ++i) {
        double t = i / 30.0;
        double px = 100.0 + 600.0 * t;
        double py = 500.0 - 800.0 * t + 800.0 * t * t;
        unsigned char red = (unsigned char)(255 - 200 * t);
        unsigned char blue = (unsigned char)(55 + 200 * t);
        motus_canvas_draw_circle(&c, px, py, 5.0, red, 80, blue);
        motus_canvas_draw_cross(&c, px, py, 8.0, 0, 255, 0);
    }
    motus_canvas_draw_line(&c, 20.0, 580.0, 780.0, 580.0, 1.0, 128, 128, 128);
    /* orientation markers: red near the top-left (y = 100 must appear near
       the top of the PNG), yellow near the bottom-right */
    motus_canvas_draw_circle(&c, 100.0, 100.0, 20.0, 255, 0, 0);
    motus_canvas_draw_circle(&c, 740.0, 520.0, 20.0, 255, 255, 0);
    if (motus_canvas_read(&c) != 0) {
        motus_canvas_destroy(&c);
        return 1;
    }

    if (!is_colour(motus_canvas_pixel(&c, 100, 100), 255, 0, 0)) {
        fprintf(stderr, "FAIL: pixel (100,100) is not red\n");
        fails++;
    }
    if (!is_colour(motus_canvas_pixel(&c, 100, 520), 0, 0, 0) ||
        !is_colour(motus_canvas_pixel(&c, 740, 100), 0, 0, 0)) {
        fprintf(stderr, "FAIL: mirrored marker positions are not black\n");
        fails++;
    }
    if (!is_colour(motus_canvas_pixel(&c, 740, 520), 255, 255, 0)) {
        fprintf(stderr, "FAIL: pixel (740,520) is not yellow\n");
        fails++;
    }
    if (motus_canvas_centroid(&c, 255, 0, 0, &x, &y, &area) != 0 ||
        fabs(x - 100.0) > 0.05 || fabs(y - 100.0) > 0.05) {
        fprintf(stderr, "FAIL: red centroid (%g, %g), want (100, 100)\n",
                x, y);
        fails++;
    }
    if (motus_canvas_centroid(&c, 1, 2, 3, &x, &y, &area) == 0) {
        fprintf(stderr, "FAIL: centroid of an absent colour succeeded\n");
        fails++;
    }
    /* the grey line covers y in [579.5, 580.5): rows 579 and 580 half each,
       so its centroid is at y = 580 */
    if (motus_canvas_centroid(&c, 128, 128, 128, &x, &y, &area) != 0 ||
        fabs(y - 580.0) > 0.01 || fabs(area - 760.0) > 2.0) {
        fprintf(stderr, "FAIL: line centroid y %g area %g\n", y, area);
        fails++;
    }
    if (motus_canvas_write_png(&c, png_path) != 0)
        fails++;
    else
        printf("wrote %s\n", png_path);
    motus_canvas_destroy(&c);
    return fails;
}

int main(int argc, char **argv)
{
    static const int ss_list[] = {1, 2, 4, 8};
    static const double radii[] = {3.0, 5.0, 10.0};
    const char *png = argc > 1 ? argv[1] : "canvas_selftest.png";
    const double poly_area_r1 = 18.0 * sin(10.0 * 3.14159265358979323846 / 180.0);
    int fails = 0;
    size_t si, ri;

    fails += picture_checks(png);

    printf("centroid error |centroid - centre| in px (%dx%d offsets, "
           "%dx%d phases, %d random frames)\n", GRID, GRID, PHASES, PHASES,
           RANDOM_BATCHES);
    printf("%2s %5s %6s | %-32s | %-17s | %s\n", "ss", "r", "n",
           "samples, exact colour (API)", "filtered pixels",
           "area px^2 (polygon)");
    printf("%2s %5s %6s | %8s %7s %7s %7s | %8s %8s |\n", "", "", "",
           "max", "rms", "max|dx|", "max|dy|", "max", "rms");
    for (si = 0; si < sizeof ss_list / sizeof ss_list[0]; ++si) {
        for (ri = 0; ri < sizeof radii / sizeof radii[0]; ++ri) {
            int ss = ss_list[si];
            double r = radii[ri];
            /* ss = 8 costs 8 x 8 samples per pixel: use a smaller canvas */
            int w = ss >= 8 ? 400 : 800, h = ss >= 8 ? 300 : 600;
            measurement m;
            if (r > 5.0 && ss >= 8) { w = 800; h = 640; }
            if (measure(ss, w, h, r, &m) != 0) {
                fails++;
                continue;
            }
            printf("%2d %5.1f %6ld | %8.4f %7.4f %7.4f %7.4f | %8.4f %8.4f | "
                   "%.2f..%.2f (%.2f)\n",
                   ss, r, m.samples.n, m.samples.max_r,
                   stats_rms(&m.samples), m.samples.max_x, m.samples.max_y,
                   m.pixels.max_r, stats_rms(&m.pixels), m.area_min,
                   m.area_max, poly_area_r1 * r * r);
            if (m.missing > 0) {
                fprintf(stderr, "FAIL: %ld circles not found\n", m.missing);
                fails++;
            }
            if (ss == MOTUS_CANVAS_DEFAULT_SS &&
                m.samples.max_r > MAX_CENTROID_ERROR_ANY_R_PX) {
                fprintf(stderr, "FAIL: r = %g: max centroid error %.4f px > "
                        "%.4f px\n", r, m.samples.max_r,
                        MAX_CENTROID_ERROR_ANY_R_PX);
                fails++;
            }
            if (ss == MOTUS_CANVAS_DEFAULT_SS && r == 5.0) {
                double want = poly_area_r1 * r * r;
                if (m.samples.max_r > MAX_CENTROID_ERROR_PX) {
                    fprintf(stderr, "FAIL: max centroid error %.4f px > "
                            "%.4f px\n", m.samples.max_r,
                            MAX_CENTROID_ERROR_PX);
                    fails++;
                }
                if (fabs(m.area_min - want) > 0.05 * want ||
                    fabs(m.area_max - want) > 0.05 * want) {
                    fprintf(stderr, "FAIL: area outside 5%% of %.2f\n", want);
                    fails++;
                }
            }
        }
    }
    printf("bounds for ss=%d: %.3f px (r=5), %.3f px (any r): %s\n",
           MOTUS_CANVAS_DEFAULT_SS, MAX_CENTROID_ERROR_PX,
           MAX_CENTROID_ERROR_ANY_R_PX, fails ? "FAIL" : "PASS");
    return fails ? 1 : 0;
}

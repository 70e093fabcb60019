/*
 * motus_canvas - off-screen renderer for headless tests (OSMesa + stb).
 * See motus_canvas.h.
 */
#include "motus_canvas.h"

#include <GL/osmesa.h>
#include <GL/gl.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* stb_image_write is compiled in here with static linkage, so it cannot
   clash with another copy in the test program; no -lstb is needed.  Only
   stbi_write_png is used: silence warnings about the other static functions
   in case the header is not found as a system header. */
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#endif
#include <stb/stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

#define MC_PI 3.14159265358979323846

static void mc_zero(motus_canvas *c)
{
    c->width = c->height = 0;
    c->ss = 0;
    c->sample_width = c->sample_height = 0;
    c->ctx = NULL;
    c->target = NULL;
    c->samples = NULL;
    c->pixels = NULL;
}

/* Make the canvas's context current on this thread and (re)establish the
   2D state: raylib-like projection with y down, no blending/dither. */
static int mc_bind(motus_canvas *c)
{
    OSMesaContext ctx = (OSMesaContext)c->ctx;
    if (ctx == NULL)
        return 1;
    if (OSMesaGetCurrentContext() != ctx) {
        if (!OSMesaMakeCurrent(ctx, c->target, GL_UNSIGNED_BYTE,
                               c->sample_width, c->sample_height)) {
            fprintf(stderr, "motus_canvas: OSMesaMakeCurrent failed\n");
            return 1;
        }
    }
    glViewport(0, 0, c->sample_width, c->sample_height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    /* Logical (x, y) -> window (x*ss, (height - y)*ss). */
    glOrtho(0.0, (double)c->width, (double)c->height, 0.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_DITHER);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_POLYGON_SMOOTH);
    glDisable(GL_LINE_SMOOTH);
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_LIGHTING);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    return 0;
}

int motus_canvas_create(motus_canvas *c, int width, int height)
{
    return motus_canvas_create_ss(c, width, height, MOTUS_CANVAS_DEFAULT_SS);
}

int motus_canvas_create_ss(motus_canvas *c, int width, int height, int ss)
{
    OSMesaContext ctx;
    size_t nsamples;

    mc_zero(c);
    if (width <= 0 || height <= 0 || ss <= 0 || ss > 64 ||
        width > 32768 / ss || height > 32768 / ss) {
        fprintf(stderr, "motus_canvas: bad size %dx%d (ss %d)\n",
                width, height, ss);
        return 1;
    }
    c->width = width;
    c->height = height;
    c->ss = ss;
    c->sample_width = width * ss;
    c->sample_height = height * ss;
    nsamples = (size_t)c->sample_width * (size_t)c->sample_height;

    c->target = (unsigned char *)calloc(nsamples, 4);
    c->samples = (unsigned char *)calloc(nsamples, 4);
    c->pixels = (unsigned char *)calloc((size_t)width * (size_t)height, 4);
    if (c->target == NULL || c->samples == NULL || c->pixels == NULL) {
        fprintf(stderr, "motus_canvas: out of memory for %dx%d (ss %d)\n",
                width, height, ss);
        motus_canvas_destroy(c);
        return 1;
    }

    /* RGBA8 colour buffer, no depth/stencil/accum. Compatibility profile. */
    ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    if (ctx == NULL) {
        fprintf(stderr, "motus_canvas: OSMesaCreateContextExt failed\n");
        motus_canvas_destroy(c);
        return 1;
    }
    c->ctx = (void *)ctx;
    if (!OSMesaMakeCurrent(ctx, c->target, GL_UNSIGNED_BYTE,
                           c->sample_width, c->sample_height)) {
        fprintf(stderr,
                "motus_canvas: OSMesaMakeCurrent failed for %dx%d samples\n",
                c->sample_width, c->sample_height);
        motus_canvas_destroy(c);
        return 1;
    }
    if (mc_bind(c) != 0) {
        motus_canvas_destroy(c);
        return 1;
    }
    motus_canvas_clear(c, 0, 0, 0);
    return 0;
}

void motus_canvas_destroy(motus_canvas *c)
{
    if (c == NULL)
        return;
    if (c->ctx != NULL) {
        OSMesaContext ctx = (OSMesaContext)c->ctx;
        if (OSMesaGetCurrentContext() == ctx)
            OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
        OSMesaDestroyContext(ctx);
    }
    free(c->target);
    free(c->samples);
    free(c->pixels);
    mc_zero(c);
}

const char *motus_canvas_renderer(motus_canvas *c)
{
    const char *s;
    if (mc_bind(c) != 0)
        return "";
    s = (const char *)glGetString(GL_RENDERER);
    return s != NULL ? s : "";
}

void motus_canvas_clear(motus_canvas *c,
                        unsigned char r, unsigned char g, unsigned char b)
{
    if (mc_bind(c) != 0)
        return;
    glClearColor(r / 255.0f, g / 255.0f, b / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
}

void motus_canvas_draw_circle(motus_canvas *c, double cx, double cy,
                              double radius,
                              unsigned char r, unsigned char g,
                              unsigned char b)
{
    const int n = MOTUS_CANVAS_CIRCLE_SEGMENTS;
    int i;
    if (mc_bind(c) != 0)
        return;
    if (radius <= 0.0)
        radius = 0.1; /* as raylib */
    glColor4ub(r, g, b, 255);
    glBegin(GL_TRIANGLE_FAN);
    glVertex2d(cx, cy);
    for (i = 0; i <= n; ++i) {
        /* i == n repeats vertex 0 exactly, closing the fan without a gap */
        double a = 2.0 * MC_PI * (double)(i % n) / (double)n;
        glVertex2d(cx + cos(a) * radius, cy + sin(a) * radius);
    }
    glEnd();
}

void motus_canvas_draw_line(motus_canvas *c, double x0, double y0,
                            double x1, double y1, double thickness,
                            unsigned char r, unsigned char g,
                            unsigned char b)
{
    double dx = x1 - x0, dy = y1 - y0;
    double len = sqrt(dx * dx + dy * dy);
    double nx, ny;
    if (mc_bind(c) != 0 || len <= 0.0 || thickness <= 0.0)
        return;
    nx = -dy / len * 0.5 * thickness;
    ny = dx / len * 0.5 * thickness;
    glColor4ub(r, g, b, 255);
    glBegin(GL_TRIANGLE_STRIP);
    glVertex2d(x0 + nx, y0 + ny);
    glVertex2d(x0 - nx, y0 - ny);
    glVertex2d(x1 + nx, y1 + ny);
    glVertex2d(x1 - nx, y1 - ny);
    glEnd();
}

void motus_canvas_draw_cross(motus_canvas *c, double x, double y,
                             double half_size,
                             unsigned char r, unsigned char g,
                             unsigned char b)
{
    motus_canvas_draw_line(c, x - half_size, y, x + half_size, y, 1.0,
                           r, g, b);
    motus_canvas_draw_line(c, x, y - half_size, x, y + half_size, 1.0,
                           r, g, b);
}

int motus_canvas_read(motus_canvas *c)
{
    const int sw = c->sample_width, sh = c->sample_height, ss = c->ss;
    const size_t row = (size_t)sw * 4;
    unsigned char *tmp;
    unsigned *acc;
    int x, y, k;

    if (mc_bind(c) != 0)
        return 1;
    glFinish();
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glReadBuffer(GL_FRONT);
    glReadPixels(0, 0, sw, sh, GL_RGBA, GL_UNSIGNED_BYTE, c->samples);
    if (glGetError() != GL_NO_ERROR) {
        fprintf(stderr, "motus_canvas: glReadPixels failed\n");
        return 1;
    }

    /* GL row 0 is the bottom; flip so that row 0 is the top. */
    tmp = (unsigned char *)malloc(row);
    if (tmp == NULL) {
        fprintf(stderr, "motus_canvas: out of memory\n");
        return 1;
    }
    for (y = 0; y < sh / 2; ++y) {
        unsigned char *a = c->samples + (size_t)y * row;
        unsigned char *b = c->samples + (size_t)(sh - 1 - y) * row;
        memcpy(tmp, a, row);
        memcpy(a, b, row);
        memcpy(b, tmp, row);
    }
    free(tmp);

    /* Box-filter ss x ss samples into each pixel (rounded mean). */
    acc = (unsigned *)calloc((size_t)c->width * 3, sizeof *acc);
    if (acc == NULL) {
        fprintf(stderr, "motus_canvas: out of memory\n");
        return 1;
    }
    for (y = 0; y < c->height; ++y) {
        unsigned n = (unsigned)(ss * ss);
        unsigned char *out = c->pixels + (size_t)y * c->width * 4;
        memset(acc, 0, (size_t)c->width * 3 * sizeof *acc);
        for (k = 0; k < ss; ++k) {
            const unsigned char *in =
                c->samples + (size_t)(y * ss + k) * row;
            for (x = 0; x < sw; ++x) {
                unsigned *a = acc + (size_t)(x / ss) * 3;
                a[0] += in[4 * x + 0];
                a[1] += in[4 * x + 1];
                a[2] += in[4 * x + 2];
            }
        }
        for (x = 0; x < c->width; ++x) {
            out[4 * x + 0] = (unsigned char)((acc[3 * x + 0] + n / 2) / n);
            out[4 * x + 1] = (unsigned char)((acc[3 * x + 1] + n / 2) / n);
            out[4 * x + 2] = (unsigned char)((acc[3 * x + 2] + n / 2) / n);
            out[4 * x + 3] = 255;
        }
    }
    free(acc);
    return 0;
}

int motus_canvas_centroid_in(const motus_canvas *c,
                             double x0, double y0, double x1, double y1,
                             unsigned char r, unsigned char g,
                             unsigned char b,
                             double *x, double *y, double *area)
{
    const double ss = (double)c->ss;
    long i0, i1, j0, j1, i, j;
    double n = 0.0, sx = 0.0, sy = 0.0;

    /* Samples whose centre (i + 0.5)/ss lies in [x0, x1):
       i >= x0*ss - 0.5 and i < x1*ss - 0.5. */
    i0 = (long)ceil(x0 * ss - 0.5);
    i1 = (long)ceil(x1 * ss - 0.5);
    j0 = (long)ceil(y0 * ss - 0.5);
    j1 = (long)ceil(y1 * ss - 0.5);
    if (i0 < 0) i0 = 0;
    if (j0 < 0) j0 = 0;
    if (i1 > c->sample_width) i1 = c->sample_width;
    if (j1 > c->sample_height) j1 = c->sample_height;

    for (j = j0; j < j1; ++j) {
        const unsigned char *p =
            c->samples + ((size_t)j * (size_t)c->sample_width + (size_t)i0) * 4;
        long rown = 0;
        double rowsx = 0.0;
        for (i = i0; i < i1; ++i, p += 4) {
            if (p[0] == r && p[1] == g && p[2] == b) {
                ++rown;
                rowsx += (double)i;
            }
        }
        if (rown > 0) {
            n += (double)rown;
            sx += rowsx;
            sy += (double)rown * (double)j;
        }
    }

    if (n == 0.0) {
        if (x) *x = 0.0;
        if (y) *y = 0.0;
        if (area) *area = 0.0;
        return 1;
    }
    if (x) *x = (sx / n + 0.5) / ss;
    if (y) *y = (sy / n + 0.5) / ss;
    if (area) *area = n / (ss * ss);
    return 0;
}

int motus_canvas_centroid(const motus_canvas *c,
                          unsigned char r, unsigned char g, unsigned char b,
                          double *x, double *y, double *area)
{
    return motus_canvas_centroid_in(c, 0.0, 0.0, (double)c->width,
                                    (double)c->height, r, g, b, x, y, area);
}

const unsigned char *motus_canvas_pixel(const motus_canvas *c, int x, int y)
{
    if (c->pixels == NULL || x < 0 || y < 0 || x >= c->width ||
        y >= c->height)
        return NULL;
    return c->pixels + ((size_t)y * (size_t)c->width + (size_t)x) * 4;
}

int motus_canvas_write_png(const motus_canvas *c, const char *path)
{
    if (c->pixels == NULL ||
        !stbi_write_png(path, c->width, c->height, 4, c->pixels,
                        c->width * 4)) {
        fprintf(stderr, "motus_canvas: cannot write PNG '%s'\n", path);
        return 1;
    }
    return 0;
}

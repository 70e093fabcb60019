/*
 * motus_canvas - tiny off-screen renderer for headless motus tests.
 *
 * Renders with legacy fixed-function OpenGL into an OSMesa (Mesa llvmpipe)
 * context, reads the image back and measures it.  Test support code only;
 * not part of the motus library.
 *
 * Coordinates are raylib-2D screen coordinates: origin at the top-left
 * corner, x to the right, y down, 1 unit = 1 pixel.  Pixel (i, j) covers
 * [i, i+1) x [j, j+1); its centre is (i + 0.5, j + 0.5).  Every function
 * that takes or returns a position uses this one frame.
 *
 * Supersampling: the canvas renders at ss x ss samples per pixel (default
 * MOTUS_CANVAS_DEFAULT_SS).  Sample (si, sj) of the read-back image covers
 * a 1/ss x 1/ss square; its centre is ((si + 0.5)/ss, (sj + 0.5)/ss).
 * Centroids are computed over the samples; the image written as PNG (and
 * returned by motus_canvas_pixel) is the ss x ss box-filtered average.
 *
 * Usage:
 *     motus_canvas c;
 *     if (motus_canvas_create(&c, 800, 600) != 0) return 1;
 *     motus_canvas_clear(&c, 0, 0, 0);
 *     motus_canvas_draw_circle(&c, x, y, 5.0, 255, 255, 255);
 *     motus_canvas_read(&c);                  (required before measuring)
 *     motus_canvas_centroid(&c, 255, 255, 255, &cx, &cy, &area);
 *     motus_canvas_write_png(&c, "out.png");
 *     motus_canvas_destroy(&c);
 *
 * Build: motus_canvas.c needs `pkg-config --cflags --libs osmesa` and -lm.
 * PNG writing uses the stb_image_write implementation compiled into
 * motus_canvas.c from <stb/stb_image_write.h> (Debian libstb-dev); no -lstb.
 *
 * Threads: a canvas must be used from one thread at a time.  Each call makes
 * the canvas's OSMesa context current on the calling thread, so several
 * canvases may be used alternately from the same thread.
 */
#ifndef MOTUS_CANVAS_H
#define MOTUS_CANVAS_H

#ifdef __cplusplus
extern "C" {
#endif

/* Samples per pixel along each axis used by motus_canvas_create. */
#define MOTUS_CANVAS_DEFAULT_SS 4

/* Number of straight segments of a circle, as raylib's DrawCircleV. */
#define MOTUS_CANVAS_CIRCLE_SEGMENTS 36

/* Plain struct so it can live on the stack; treat the fields as read-only. */
typedef struct motus_canvas {
    int width, height;        /* logical size in pixels                     */
    int ss;                   /* samples per pixel along each axis          */
    int sample_width;         /* width  * ss                                */
    int sample_height;        /* height * ss                                */
    void *ctx;                /* OSMesaContext                              */
    unsigned char *target;    /* OSMesa colour buffer (GL order, bottom-up) */
    unsigned char *samples;   /* read-back samples, RGBA, row 0 = top       */
    unsigned char *pixels;    /* box-filtered image, RGBA, row 0 = top      */
} motus_canvas;

/* Create a width x height canvas with MOTUS_CANVAS_DEFAULT_SS supersampling.
   Returns 0 on success; otherwise prints a message to stderr, leaves *c in a
   state that motus_canvas_destroy accepts, and returns nonzero. */
int  motus_canvas_create(motus_canvas *c, int width, int height);
/* Same with an explicit supersampling factor ss >= 1 (1 = plain pixels). */
int  motus_canvas_create_ss(motus_canvas *c, int width, int height, int ss);
void motus_canvas_destroy(motus_canvas *c);

/* GL_RENDERER string of the canvas's context (e.g. "llvmpipe (...)"). */
const char *motus_canvas_renderer(motus_canvas *c);

/* Fill the whole canvas with an opaque colour. */
void motus_canvas_clear(motus_canvas *c,
                        unsigned char r, unsigned char g, unsigned char b);

/* Filled circle drawn the way raylib's DrawCircleV draws it: a fan of
   MOTUS_CANVAS_CIRCLE_SEGMENTS triangles around (cx, cy), vertices at
   angles k*10 degrees, so it is a regular 36-gon inscribed in the circle
   (area 18 r^2 sin(10 deg) = 3.1257 r^2; its centroid is exactly (cx, cy)). */
void motus_canvas_draw_circle(motus_canvas *c, double cx, double cy,
                              double radius,
                              unsigned char r, unsigned char g,
                              unsigned char b);

/* Straight line from (x0, y0) to (x1, y1) drawn as a filled rectangle
   `thickness` pixels wide (no caps). */
void motus_canvas_draw_line(motus_canvas *c, double x0, double y0,
                            double x1, double y1, double thickness,
                            unsigned char r, unsigned char g,
                            unsigned char b);

/* "+" marker centred on (x, y): two 1-pixel-thick lines of half-length
   `half_size`.  Meant for expected positions next to drawn circles. */
void motus_canvas_draw_cross(motus_canvas *c, double x, double y,
                             double half_size,
                             unsigned char r, unsigned char g,
                             unsigned char b);

/* Finish rendering and read the image back (samples and pixels).  Call it
   after drawing and before any centroid/pixel/PNG call.  Returns 0. */
int  motus_canvas_read(motus_canvas *c);

/* Centroid of all samples whose colour is exactly (r, g, b), in pixel
   coordinates.  *area receives the matched area in square pixels (number of
   matched samples / ss^2).  Any output pointer may be NULL.  Returns 0, or
   nonzero (outputs set to 0) if no sample matches. */
int  motus_canvas_centroid(const motus_canvas *c,
                           unsigned char r, unsigned char g, unsigned char b,
                           double *x, double *y, double *area);

/* Same, restricted to samples whose centres lie in [x0, x1) x [y0, y1). */
int  motus_canvas_centroid_in(const motus_canvas *c,
                              double x0, double y0, double x1, double y1,
                              unsigned char r, unsigned char g,
                              unsigned char b,
                              double *x, double *y, double *area);

/* RGBA of pixel (x, y) of the box-filtered image (row 0 = top), or NULL if
   outside the canvas.  Edge pixels of shapes are blends of colours. */
const unsigned char *motus_canvas_pixel(const motus_canvas *c, int x, int y);

/* Write the box-filtered image as an RGBA PNG.  Returns 0 on success,
   nonzero with a message to stderr otherwise. */
int  motus_canvas_write_png(const motus_canvas *c, const char *path);

#ifdef __cplusplus
}
#endif

#endif /* MOTUS_CANVAS_H */

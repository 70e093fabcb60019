/* orbits.c - one orbit integrated by six motus methods side by side, with their errors and their cost.

   An 800x600 window at 60 FPS. The eccentric Kepler orbit (mu = 1, a = 1, e = 0.5, period T = 2 pi, starting
   at periapsis; bench/problems.h's kepler_eccentric) is integrated once per method: one motus_scene with an
   attractor (attractor_strength = mu at the origin), its scene.method set to each method in turn, and
   motus_step on each method's particle with the same step. The hollow white
   circle is the exact position, from Kepler's equation. Every frame each method takes one step of
   dt = T/120 of simulated time, so an orbit takes two seconds on screen, whatever the frame rate.

   What to look for at that step (try UP and DOWN):
   - explicit Euler (red) gains energy at every periapsis passage, spirals out and escapes within a few
     orbits; an arrow at the edge of the view then shows where it went;
   - semi-implicit Euler (orange, motus's default) and velocity Verlet (green) are symplectic: their energy
     error stays bounded (a few percent, a fraction of a percent) but their orbits precess, so they drift
     ahead of or behind the exact position;
   - RK4 (blue), Forest-Ruth (purple) and McLachlan's method (pink) stay on the hollow circle, drawn as
     circles one inside the other; the legend tells them apart (McLachlan's is the closest at 5 force
     evaluations a step, Forest-Ruth's 3 and RK4's 4).
   The legend gives each method's order, force evaluations per step, position error (a = 1 is the orbit's
   semi-major axis), relative energy error (E - E0)/|E0| and the time one step takes, measured here on this
   machine (a moving average; a timing, not a property of the method).

   Keys: SPACE pauses, R starts the orbit again (keeping the step), UP doubles the step, DOWN halves it,
   Escape quits.

   Options, as the WSAD example's, so that a script can drive it without a person:
     --frames N         stop after N frames (default: run until the window is closed or Escape)
     --fixed-dt         accepted and ignored: the simulation already takes one fixed step per frame, so runs
                        are reproducible without it
     --screenshot FILE  save the last frame as a PNG
   On exit it prints the run (frames; steps and simulated time since the start or the last R; whether it ended
   paused) and one line per method with its final errors, its drawing colour and its measured cost, e.g.
     method=rk4 order=4 evals=4 position_error=3.095e-03 energy_error=-5.980e-05 us_per_step=0.263 rgb=102,191,255
   us_per_step is a measurement (it varies from run to run); every other number is reproducible. */
#define MOTUS_IMPLEMENTATION /* this file compiles the engine: motus_step */
#include "motus.h"
#include "raylib.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WINDOW_WIDTH 800
#define WINDOW_HEIGHT 600
#define ORBIT_PI 3.14159265358979323846
#define ECCENTRICITY 0.5
#define KEPLER_PERIOD (2 * ORBIT_PI) /* a = 1, mu = 1: T = 2 pi sqrt(a^3/mu) */
#define DEFAULT_STEPS_PER_ORBIT 120    /* dt = T/120: an orbit in 120 frames, 2 s at 60 FPS */
#define MIN_STEPS_PER_ORBIT 15
#define MAX_STEPS_PER_ORBIT 1920
#define TRAIL_LENGTH 90     /* steps of trail kept per method */
#define TIMING_REPEATS 32   /* steps timed together, so the clock's own cost is small against theirs */

/* Layout. The orbit is drawn between the top bar and the legend; tests/example_orbits.sh looks for each
   method's colour above LEGEND_TOP. */
#define TOP_BAR_HEIGHT 36
#define LEGEND_TOP 424
#define PIXELS_PER_UNIT 200.0f
/* The ellipse's centre is at x = -a*e, so the attractor (a focus) sits right of the view's centre. */
#define ATTRACTOR_X (WINDOW_WIDTH / 2 + PIXELS_PER_UNIT * (float)ECCENTRICITY)
#define ATTRACTOR_Y ((TOP_BAR_HEIGHT + LEGEND_TOP) / 2)

#define BACKGROUND CLITERAL(Color){12, 12, 18, 255}
#define PANEL CLITERAL(Color){24, 24, 34, 255}
#define RULE CLITERAL(Color){58, 58, 74, 255}
#define TEXT_DIM CLITERAL(Color){150, 150, 165, 255}
#define TEXT_BRIGHT CLITERAL(Color){225, 225, 235, 255}

typedef struct method_style {
    motus_method method;
    Color colour;
    float radius; /* RK4, Forest-Ruth and McLachlan sit on the same spot: drawn one inside the other */
} method_style;

static const method_style STYLES[] = {
    {MOTUS_EXPLICIT_EULER, {230, 41, 55, 255}, 5},
    {MOTUS_SEMI_IMPLICIT_EULER, {255, 161, 0, 255}, 5},
    {MOTUS_VELOCITY_VERLET, {0, 228, 48, 255}, 5},
    {MOTUS_RK4, {102, 191, 255, 255}, 8},
    {MOTUS_FOREST_RUTH, {200, 122, 255, 255}, 5.5f},
    {MOTUS_MCLACHLAN4, {255, 109, 194, 255}, 3},
};
#define METHOD_COUNT ((int)(sizeof STYLES / sizeof STYLES[0]))

typedef struct orbiter {
    const method_style *style;
    motus_particle particle;
    motus_vec2 trail[TRAIL_LENGTH]; /* ring buffer, newest at trail_head - 1 */
    int trail_head, trail_count;
    double us_per_step; /* moving average of the measured time per step */
    motus_result last_result;
} orbiter;

typedef struct simulation {
    motus_scene scene; /* the attractor; scene.method is set to each orbiter's method before its step */
    double start_energy;
    orbiter orbiters[METHOD_COUNT];
    int steps_per_orbit; /* dt = T/steps_per_orbit */
    double time;         /* simulated seconds: the sum of the steps taken, each as motus_real */
    long steps;
    int paused;
    long paused_frames;
} simulation;

/* ---- the orbit: a = 1, e = 0.5, mu = 1, from periapsis (0.5, 0) moving +y; everything in double ---- */
typedef struct orbit_state {
    double x, y, vx, vy;
} orbit_state;

/* The exact state at time t: mean anomaly M = t (mean motion 1), Kepler's equation E - e sin E = M solved by
   Newton's method to rounding. */
static orbit_state kepler_exact(double t) {
    const double e = ECCENTRICITY, b = sqrt(1 - e * e), m = fmod(t, 2 * ORBIT_PI);
    double E = m, r;
    int i;
    orbit_state s;
    for (i = 0; i < 50; ++i) {
        const double step = (E - e * sin(E) - m) / (1 - e * cos(E));
        E -= step;
        if (fabs(step) < 1e-16) break;
    }
    r = 1 - e * cos(E);
    s.x = cos(E) - e;
    s.y = b * sin(E);
    s.vx = -sin(E) / r; /* dE/dt = 1/r */
    s.vy = b * cos(E) / r;
    return s;
}

/* Energy per unit mass, kinetic + potential (-mu/r); -1/2 on this orbit. */
static double kepler_energy(const motus_particle *p) {
    const double x = p->position.x, y = p->position.y, vx = p->velocity.x, vy = p->velocity.y;
    return 0.5 * (vx * vx + vy * vy) - 1.0 / sqrt(x * x + y * y);
}

typedef struct options {
    long frames; /* 0: no limit */
    const char *screenshot;
} options;

static int parse_options(int argc, char **argv, options *out) {
    int i;
    memset(out, 0, sizeof *out);
    for (i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--frames") == 0 && i + 1 < argc) {
            char *end;
            out->frames = strtol(argv[++i], &end, 10);
            if (*end != '\0' || out->frames < 0) return 0;
        } else if (strcmp(argv[i], "--screenshot") == 0 && i + 1 < argc) {
            out->screenshot = argv[++i];
        } else if (strcmp(argv[i], "--fixed-dt") == 0) {
            /* nothing to do: every frame already steps a fixed dt */
        } else {
            return 0;
        }
    }
    return 1;
}

/* motus_method_name is NULL only for a value out of range; printf must not be handed that. */
static const char *method_name(motus_method method) {
    const char *name = motus_method_name(method);
    return name ? name : "?";
}

static motus_real step_size(const simulation *sim) { return (motus_real)(KEPLER_PERIOD / sim->steps_per_orbit); }

/* Every particle back at periapsis, trails and clock cleared; the step is kept. */
static int simulation_reset(simulation *sim) {
    const orbit_state start = kepler_exact(0);
    motus_check_report report;
    motus_result result;
    int i;
    sim->time = 0;
    sim->steps = 0;
    for (i = 0; i < METHOD_COUNT; ++i) {
        orbiter *o = &sim->orbiters[i];
        o->style = &STYLES[i];
        motus_particle_init(&o->particle, motus_v2((motus_real)start.x, (motus_real)start.y), 1);
        o->particle.velocity = motus_v2((motus_real)start.vx, (motus_real)start.vy);
        o->trail_head = o->trail_count = 0;
        o->last_result = MOTUS_OK;
    }
    result = motus_scene_check(&sim->scene, 2, 1, &report);
    if (result != MOTUS_OK) {
        fprintf(stderr, "orbits: %s: %s\n", report.field_name, motus_result_string(result));
        return 0;
    }
    /* The energy of the particle as stored (in motus_real), so that the error shown is what the method
       changed, not the rounding of the starting state. */
    sim->start_energy = kepler_energy(&sim->orbiters[0].particle);
    return 1;
}

static int simulation_init(simulation *sim) {
    memset(sim, 0, sizeof *sim);
    sim->scene.attractor = motus_v3(0, 0, 0);
    sim->scene.attractor_strength = 1; /* mu */
    sim->steps_per_orbit = DEFAULT_STEPS_PER_ORBIT;
    return simulation_reset(sim);
}

/* One step of the orbiter's method: the shared scene with its method, over a state of its one particle. */
static void orbiter_step(orbiter *o, motus_scene *scene, motus_real dt) {
    motus_particle copy = o->particle;
    const motus_state state = motus_state_of_particles(&o->particle, 1);
    const motus_state timing_state = motus_state_of_particles(&copy, 1);
    double start, measured;
    int k;
    motus_result result;

    scene->method = o->style->method;
    /* The cost: the same step on a copy, TIMING_REPEATS times between two clock readings. */
    start = GetTime();
    for (k = 0; k < TIMING_REPEATS; ++k) motus_step(scene, &timing_state, dt, NULL, 0);
    measured = (GetTime() - start) * 1e6 / TIMING_REPEATS;
    o->us_per_step = o->us_per_step == 0 ? measured : o->us_per_step + 0.05 * (measured - o->us_per_step);

    result = motus_step(scene, &state, dt, NULL, 0);
    if (result != MOTUS_OK && result != o->last_result) /* say it once, not every frame */
        fprintf(stderr, "orbits: %s: %s\n", method_name(o->style->method), motus_result_string(result));
    o->last_result = result;

    o->trail[o->trail_head] = o->particle.position;
    o->trail_head = (o->trail_head + 1) % TRAIL_LENGTH;
    if (o->trail_count < TRAIL_LENGTH) ++o->trail_count;
}

static void simulation_step(simulation *sim) {
    const motus_real dt = step_size(sim);
    int i;
    for (i = 0; i < METHOD_COUNT; ++i) orbiter_step(&sim->orbiters[i], &sim->scene, dt);
    sim->time += (double)dt;
    ++sim->steps;
}

static orbit_state exact_state(const simulation *sim) { return kepler_exact(sim->time); }

static double position_error(const simulation *sim, const orbiter *o) {
    orbit_state exact = exact_state(sim);
    return hypot((double)o->particle.position.x - exact.x, (double)o->particle.position.y - exact.y);
}

/* (E - E0)/|E0|: positive when the method added energy. */
static double energy_error(const simulation *sim, const orbiter *o) {
    return (kepler_energy(&o->particle) - sim->start_energy) / fabs(sim->start_energy);
}

static void handle_keys(simulation *sim) {
    if (IsKeyPressed(KEY_SPACE)) sim->paused = !sim->paused;
    if (IsKeyPressed(KEY_R)) simulation_reset(sim);
    if (IsKeyPressed(KEY_UP) && sim->steps_per_orbit > MIN_STEPS_PER_ORBIT) sim->steps_per_orbit /= 2;
    if (IsKeyPressed(KEY_DOWN) && sim->steps_per_orbit < MAX_STEPS_PER_ORBIT) sim->steps_per_orbit *= 2;
}

/* ---- drawing ------------------------------------------------------------------------------------ */

/* Orbit units (y up) to pixels (y down). */
static Vector2 to_screen(double x, double y) {
    Vector2 p;
    p.x = ATTRACTOR_X + PIXELS_PER_UNIT * (float)x;
    p.y = ATTRACTOR_Y - PIXELS_PER_UNIT * (float)y;
    return p;
}

static void draw_triangle(Vector2 a, Vector2 b, Vector2 c, Color colour) {
    /* raylib culls triangles not given counter-clockwise on screen (y down: negative cross product). */
    if ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) > 0) {
        Vector2 t = b;
        b = c;
        c = t;
    }
    DrawTriangle(a, b, c, colour);
}

/* A particle outside the view: an arrow on the view's edge, on the line from the attractor, and how far. */
static void draw_off_view_marker(Vector2 p, double distance, Color colour) {
    const float margin = 16, left = margin, right = WINDOW_WIDTH - margin;
    const float top = TOP_BAR_HEIGHT + margin, bottom = LEGEND_TOP - margin;
    float dx = p.x - ATTRACTOR_X, dy = p.y - ATTRACTOR_Y, t = 1e30f, length;
    Vector2 tip, base, side;
    if (dx > 0) t = fminf(t, (right - ATTRACTOR_X) / dx);
    if (dx < 0) t = fminf(t, (left - ATTRACTOR_X) / dx);
    if (dy > 0) t = fminf(t, (bottom - ATTRACTOR_Y) / dy);
    if (dy < 0) t = fminf(t, (top - ATTRACTOR_Y) / dy);
    length = sqrtf(dx * dx + dy * dy);
    if (length == 0 || t >= 1e30f) return;
    tip.x = ATTRACTOR_X + dx * t;
    tip.y = ATTRACTOR_Y + dy * t;
    dx /= length, dy /= length;
    base.x = tip.x - 14 * dx, base.y = tip.y - 14 * dy;
    side.x = -dy * 7, side.y = dx * 7;
    draw_triangle(tip, (Vector2){base.x + side.x, base.y + side.y}, (Vector2){base.x - side.x, base.y - side.y},
                  colour);
    DrawText(TextFormat("r = %.1f", distance), (int)(base.x - 44 * dx - 18), (int)(base.y - 22 * dy - 5), 10,
             colour);
}

static void draw_orbits(const simulation *sim) {
    const orbit_state exact = exact_state(sim);
    const Vector2 attractor = to_screen(0, 0);
    int i, j;

    /* The exact orbit, faintly: an ellipse with semi-axes a and b = a*sqrt(1 - e^2), centred at (-a*e, 0). */
    DrawEllipseLinesV(to_screen(-ECCENTRICITY, 0), PIXELS_PER_UNIT,
                      PIXELS_PER_UNIT * (float)sqrt(1 - ECCENTRICITY * ECCENTRICITY), RULE);
    DrawCircleV(attractor, 13, ColorAlpha(CLITERAL(Color){255, 236, 170, 255}, 0.18f));
    DrawCircleV(attractor, 7, CLITERAL(Color){255, 236, 170, 255});

    for (i = 0; i < METHOD_COUNT; ++i) { /* trails: older is fainter */
        const orbiter *o = &sim->orbiters[i];
        for (j = 1; j < o->trail_count; ++j) {
            const motus_vec2 a = o->trail[(o->trail_head - o->trail_count + j - 1 + TRAIL_LENGTH) % TRAIL_LENGTH];
            const motus_vec2 b = o->trail[(o->trail_head - o->trail_count + j + TRAIL_LENGTH) % TRAIL_LENGTH];
            const float age = (float)j / (float)o->trail_count;
            DrawLineEx(to_screen(a.x, a.y), to_screen(b.x, b.y), 2, ColorAlpha(o->style->colour, 0.75f * age * age));
        }
    }
    for (i = 0; i < METHOD_COUNT; ++i) {
        const orbiter *o = &sim->orbiters[i];
        const Vector2 p = to_screen(o->particle.position.x, o->particle.position.y);
        const float r = o->style->radius;
        if (p.x < -r || p.x > WINDOW_WIDTH + r || p.y < TOP_BAR_HEIGHT - r || p.y > LEGEND_TOP + r)
            draw_off_view_marker(p, hypot(o->particle.position.x, o->particle.position.y), o->style->colour);
        else
            DrawCircleV(p, r, o->style->colour);
    }
    DrawRing(to_screen(exact.x, exact.y), 9.5f, 11.5f, 0, 360, 40, WHITE);
}

static void draw_top_bar(const simulation *sim) {
    const char *status = TextFormat("dt = T/%d = %.4f s per frame    t = %.2f T", sim->steps_per_orbit,
                                    (double)step_size(sim), sim->time / KEPLER_PERIOD);
    DrawRectangle(0, 0, WINDOW_WIDTH, TOP_BAR_HEIGHT, PANEL);
    DrawLine(0, TOP_BAR_HEIGHT, WINDOW_WIDTH, TOP_BAR_HEIGHT, RULE);
    DrawText("motus orbits", 14, 9, 20, TEXT_BRIGHT);
    DrawText(status, 168, 9, 20, TEXT_DIM);
    if (sim->paused) DrawText("PAUSED", WINDOW_WIDTH - 14 - MeasureText("PAUSED", 20), 9, 20, GOLD);
}

static void draw_legend(const simulation *sim) {
    enum { NAME = 40, ORDER = 262, EVALS = 318, POSITION = 392, ENERGY = 530, COST = 680, ROW = 22 };
    const int header = LEGEND_TOP + 8, first_row = LEGEND_TOP + 24, help = WINDOW_HEIGHT - 16;
    const char *exact = "exact position (Kepler's equation)";
    const int exact_x = WINDOW_WIDTH - 14 - MeasureText(exact, 10);
    int i;
    DrawRectangle(0, LEGEND_TOP, WINDOW_WIDTH, WINDOW_HEIGHT - LEGEND_TOP, PANEL);
    DrawLine(0, LEGEND_TOP, WINDOW_WIDTH, LEGEND_TOP, RULE);
    DrawText("method", NAME, header, 10, TEXT_DIM);
    DrawText("order", ORDER, header, 10, TEXT_DIM);
    DrawText("evals/step", EVALS, header, 10, TEXT_DIM);
    DrawText("position error (a = 1)", POSITION, header, 10, TEXT_DIM);
    DrawText("energy error dE/|E0|", ENERGY, header, 10, TEXT_DIM);
    DrawText("us/step, measured", COST, header, 10, TEXT_DIM);
    for (i = 0; i < METHOD_COUNT; ++i) {
        const orbiter *o = &sim->orbiters[i];
        const motus_method m = o->style->method;
        const int y = first_row + i * ROW;
        DrawCircle(NAME - 18, y + 9, 6, o->style->colour);
        DrawText(method_name(m), NAME, y, 20, o->style->colour);
        DrawText(TextFormat("%d", motus_method_order(m)), ORDER + 10, y, 20, TEXT_BRIGHT);
        DrawText(TextFormat("%d", motus_method_evaluations(m)), EVALS + 20, y, 20, TEXT_BRIGHT);
        DrawText(TextFormat("%.1e", position_error(sim, o)), POSITION, y, 20, TEXT_BRIGHT);
        DrawText(TextFormat("%+.1e", energy_error(sim, o)), ENERGY, y, 20, TEXT_BRIGHT);
        DrawText(TextFormat("%.3f", o->us_per_step), COST, y, 20, TEXT_BRIGHT);
    }
    DrawText("SPACE pause    R restart    UP/DOWN step x2 / x0.5    ESC quit", NAME, help, 10, TEXT_DIM);
    DrawRing((Vector2){(float)exact_x - 10, (float)help + 4}, 4, 5.5f, 0, 360, 20, WHITE);
    DrawText(exact, exact_x, help, 10, TEXT_DIM);
}

static void draw(const simulation *sim) {
    ClearBackground(BACKGROUND);
    draw_orbits(sim); /* first: the bars drawn after cover whatever leaves the view */
    draw_top_bar(sim);
    draw_legend(sim);
}

int main(int argc, char **argv) {
    static simulation sim; /* static: the trails make it a few kilobytes */
    options opts;
    long frame;
    int i;

    if (!parse_options(argc, argv, &opts)) {
        fprintf(stderr, "usage: %s [--frames N] [--fixed-dt] [--screenshot FILE]\n", argv[0]);
        return 2;
    }
    if (!simulation_init(&sim)) return 1;

    SetTraceLogLevel(LOG_WARNING);
    InitWindow(WINDOW_WIDTH, WINDOW_HEIGHT, "motus - orbits");
    if (!IsWindowReady()) {
        fprintf(stderr, "orbits: could not open a window (no display? try xvfb-run)\n");
        return 1;
    }
    SetTargetFPS(60);

    for (frame = 0; !WindowShouldClose() && (opts.frames == 0 || frame < opts.frames); ++frame) {
        handle_keys(&sim);
        if (sim.paused)
            ++sim.paused_frames;
        else
            simulation_step(&sim);
        BeginDrawing();
        draw(&sim);
        EndDrawing();
    }

    if (opts.screenshot) {
        /* As in wsad.c: draw the last frame into an off-screen texture and save that. */
        RenderTexture2D target = LoadRenderTexture(WINDOW_WIDTH, WINDOW_HEIGHT);
        Image image;
        BeginTextureMode(target);
        draw(&sim);
        EndTextureMode();
        image = LoadImageFromTexture(target.texture);
        ImageFlipVertical(&image); /* OpenGL textures are stored bottom-up */
        if (!ExportImage(image, opts.screenshot)) fprintf(stderr, "orbits: could not write %s\n", opts.screenshot);
        UnloadImage(image);
        UnloadRenderTexture(target);
    }
    CloseWindow();

    printf("frames=%ld steps=%ld paused=%d paused_frames=%ld steps_per_orbit=%d dt=%.6f time=%.4f orbits=%.3f\n",
           frame, sim.steps, sim.paused, sim.paused_frames, sim.steps_per_orbit, (double)step_size(&sim), sim.time,
           sim.time / KEPLER_PERIOD);
    for (i = 0; i < METHOD_COUNT; ++i) {
        const orbiter *o = &sim.orbiters[i];
        const motus_method m = o->style->method;
        printf("method=%s order=%d evals=%d position_error=%.3e energy_error=%.3e us_per_step=%.3f rgb=%d,%d,%d\n",
               method_name(m), motus_method_order(m), motus_method_evaluations(m), position_error(&sim, o),
               energy_error(&sim, o), o->us_per_step, o->style->colour.r, o->style->colour.g, o->style->colour.b);
    }
    return 0;
}

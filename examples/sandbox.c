/* sandbox.c - thousands of coloured particles stepped by motus_step, with gravity, wind, random kicks and
   damping you switch on and off, and any of motus's integrators.

   The reference program's follow-up ideas ("add more particles and draw each with a different colour, and
   let them move randomly"; "collisions at the edges of the screen"; "add gravity to let particles fall and
   wind that blows particles to the side"), written with motus_step: an 800x600 window at 60 FPS and
   5000 particles (--particles N) in static arrays, one array per component (x[], y[], vx[], vy[], ...),
   handed to motus as a motus_state. Each particle has its own colour, a mass between 0.5 and 2 (drawn as
   its size) and starts at a random place with a random velocity; a small seeded generator of this file
   makes the start and the random kicks, so a run with the same options is the same run. One unit of length
   is one pixel; y grows downwards.

   Every frame the motus_scene (and the state's force array) is rebuilt from what is switched on; a term
   left zero costs nothing:
     G  gravity, 300 px/s^2 down             scene.gravity
     W  wind, a force of 200 N to the right   state.force (the force arrays): a force, not an acceleration,
                                              so light particles blow away faster than heavy ones, while
                                              gravity pulls every one alike
     K  random kicks, up to 400 N each way    state.force too: a new random force every frame
     D  damping, 50% of the speed removed     scene.damping_per_second
        per second
     C  collisions: the particles are balls   scene.contacts (enabled, friction 0.3, restitution 0.3) and
        of their drawn size that bounce off    state.radius (each one's drawn radius); the window's edges
        one another and come to rest in a      become walls the balls rest against at their radius, keeping
        pile on the floor                      30% of the speed; motus_step then needs scratch memory
                                              (motus_scratch_size bytes, allocated here when it grows)
     T  tether: every particle on a spring    scene.tether (the pointer, each frame) and tether_stiffness, with
        to the mouse pointer, the swarm       scene.linear_drag to calm the swirl: springs of rest length 0
        swirls in and gathers there           that couple nothing (no scratch). Not with exact_linear_drag,
                                              which takes no tether (the HUD says so; the drag stays)
     M  the next integrator                   scene.method (semi-implicit Euler first; all nine take this scene)
     R  reset: every particle back where it started (the same seeded start)
   and always: each particle's own mass (state.inverse_mass) and the window's edges, where particles bounce
   and keep 90% of their speed (scene.bounds_min/max, scene.restitution; 30% with collisions). With neither wind nor kicks
   state.force is NULL and the force arrays are not read. The HUD lights the scene's terms that are on, names
   the method and shows the time the one motus_step call for all particles took each frame, measured here on
   this machine (a moving average; a timing, not a property of motus; with few particles it is mostly the
   cost of a call made once a frame, between drawings, with cold caches).

   The step is a fixed dt = 1/60 s per frame, whatever the measured frame time: the motion depends on the
   number of frames only, so a run under a virtual X server (Xvfb), slow or not, ends where a real one does.

   Keys: G, W, K, D, C, T toggle, M cycles the method, R resets (see above); Escape quits.
   Options, so that a script can drive it without a person (defaults: the interactive program):
     --frames N            stop after N frames (default: run until the window is closed or Escape)
     --particles N         how many, 1 to 65536 (default 5000)
     --seed N              the random generator's seed (default 1)
     --gravity on|off      the toggles' first state (defaults: gravity off, wind off, random on, damping off)
     --wind on|off
     --random on|off
     --damping on|off
     --collisions on|off   (default off)
     --tether on|off       (default off; the point is the mouse pointer, clamped to the window)
     --method NAME         the first method, by motus_method_name ("rk4"; default semi_implicit_euler)
     --screenshot FILE     save the last frame as a PNG
   On exit it prints one line: the scene it ended with (its terms that are on, and the method), how many key
   presses changed something, how many resets and steps since the last, how many particles are inside the
   window (all of them: they bounce) and how many are drawn whole inside it (their disc within 0.01 px of the
   window), their mean position and velocity and root-mean-square speed, and the overlaps between the balls
   as drawn (found by motus_find_contacts whether collisions are on or not): how many pairs are in contact
   (overlapping or within 1% of touching), the largest overlap in px and as a share of the smaller radius of
   its pair, e.g.
     frames=300 particles=5000 scene=gravity|bounds|state.force|state.inverse_mass method=semi_implicit_euler
     gravity=1 wind=0 random=1 damping=0 collisions=0 tether=0 tether_x=400.0 tether_y=300.0 toggles=0
     resets=0 steps=300 inside=5000 whole=5000
     mean_x=... rms_speed=... overlaps=2716 max_overlap=8.102 overlap_ratio=1.000 us_per_step=40.5 fps=59.9
   (one line; tether_x/y: the point of the last frame). us_per_step (the moving average of the motus_step
   call) and fps (frames over the wall-clock time of the run, drawing included; at most 60, the target) are measurements; every other number is the
   same on every run with the same options. */
#define MOTUS_IMPLEMENTATION /* this file compiles the engine: motus_step */
#include "motus.h"
#include "raylib.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WINDOW_WIDTH 800
#define WINDOW_HEIGHT 600
#define DT (1.0f / 60.0f)        /* s per frame, fixed */
#define DEFAULT_PARTICLES 5000
#define MAX_PARTICLES 65536
#define GRAVITY 300.0f           /* px/s^2, down */
#define WIND 200.0f              /* N to the right, on every particle */
#define KICK 400.0f              /* N: each random kick's components are uniform in [-KICK, KICK] */
#define DAMPING_PER_SECOND 0.5f  /* fraction of the speed removed per second when damping is on */
#define RESTITUTION 0.9f         /* speed kept through a bounce */
#define CONTACT_RESTITUTION 0.3f /* with collisions: speed kept through a bounce, between balls and on the walls */
#define CONTACT_FRICTION 0.3f    /* with collisions: Coulomb coefficient between balls and on the walls */
#define CONTACT_SUBSTEPS 2       /* with collisions: a pile 40 balls deep at 300 px/s^2 rests within 10% of a
                                    radius at 2 substeps (1: about 20%); see >>contacts in motus.h */
#define TETHER_STIFFNESS 6.0f   /* N/px: a 1 kg particle swings about the pointer with a period of 2.6 s */
#define TETHER_DRAG 1.2f        /* 1/s: linear drag with the tether, so that the swarm gathers (underdamped) */
#define MIN_MASS 0.5f
#define MAX_MASS 2.0f
#define MAX_SPEED 120.0f         /* px/s: each starting velocity component is uniform in [-MAX_SPEED, MAX_SPEED] */
/* Radius 2.5 px at the lightest, 4.5 px at the heaviest; the walls sit a largest radius inside the window,
   so that every dot is drawn whole and touches the edge where it bounces. */
#define RADIUS_OF_MASS(m) (1.833f + 1.333f * (m))
#define MAX_RADIUS RADIUS_OF_MASS(MAX_MASS)
#define TIMING_SMOOTHING 0.05 /* weight of a new measurement in the moving average, after the first 20 */

/* Layout: translucent bars over the particles. */
#define TOP_BAR_HEIGHT 84
#define FLAGS_TOP 48    /* the scene's terms: two rows of six columns */
#define FLAG_ROW 18
#define FLAG_LEFT 96
#define FLAG_COLUMN 116
#define FLAG_COLUMNS 6
#define BOTTOM_BAR_HEIGHT 26
#define BACKGROUND CLITERAL(Color){10, 10, 16, 255}
#define PANEL CLITERAL(Color){22, 22, 32, 215}
#define RULE CLITERAL(Color){58, 58, 74, 255}
#define TEXT_DIM CLITERAL(Color){135, 135, 155, 255}
#define TEXT_BRIGHT CLITERAL(Color){225, 225, 235, 255}
#define LIT CLITERAL(Color){120, 235, 140, 255}
#define LIT_BACK CLITERAL(Color){30, 72, 42, 255}

/* Cache-line aligned: motus takes any alignment; this only spares its kernels the unaligned loads at the
   start. GCC and Clang spelling; C99 has no _Alignas. */
#if defined(__GNUC__) || defined(__clang__)
#define ALIGNED64 __attribute__((aligned(64)))
#else
#define ALIGNED64
#endif

/* The particles: one array per component (a motus_state points into them). */
static float position_x[MAX_PARTICLES] ALIGNED64, position_y[MAX_PARTICLES] ALIGNED64;
static float velocity_x[MAX_PARTICLES] ALIGNED64, velocity_y[MAX_PARTICLES] ALIGNED64;
static float force_x[MAX_PARTICLES] ALIGNED64, force_y[MAX_PARTICLES] ALIGNED64;
static float inverse_mass[MAX_PARTICLES] ALIGNED64;
static float radius[MAX_PARTICLES];
static Color colour[MAX_PARTICLES];

typedef struct toggles {
    int gravity, wind, random, damping, collisions, tether;
    motus_method method;
    long presses; /* key presses that changed something (R included) */
} toggles;

typedef struct options {
    long frames; /* 0: no limit */
    int particles;
    unsigned long seed;
    toggles start;
    const char *screenshot;
} options;

typedef struct sandbox {
    int count;
    unsigned long seed;
    toggles on;
    motus_vec3 tether_point; /* the mouse pointer in the window, px (the centre until it moves) */
    Vector2 pointer_start;   /* where the pointer was when the window opened (raylib knows from frame 1) */
    int pointer_polls, pointer_moved;
    motus_scene scene; /* rebuilt from `on` every frame */
    motus_state state; /* the arrays; state.force set only while a force is on */
    double us_per_step; /* moving average of the measured motus_step time */
    long steps_timed;
    long resets, steps; /* steps: since the start or the last reset */
    motus_result last_result;
    unsigned long long random_state;
    Texture2D dot; /* a white disc with a soft edge, tinted per particle */
    void *scratch; /* motus_step's working memory with collisions on (grown when motus_scratch_size asks more) */
    size_t scratch_bytes;
} sandbox;

/* ---- a small random generator: PCG32 (O'Neill 2014), 64-bit LCG state, permuted 32-bit output ---- */
static unsigned random_next(unsigned long long *state) {
    unsigned long long old = *state;
    unsigned xorshifted, rotation;
    *state = old * 6364136223846793005ull + 1442695040888963407ull;
    xorshifted = (unsigned)(((old >> 18) ^ old) >> 27);
    rotation = (unsigned)(old >> 59);
    return (xorshifted >> rotation) | (xorshifted << ((32u - rotation) & 31u));
}
/* Uniform in [lo, hi): the top 24 bits, which a float holds exactly. */
static float random_range(unsigned long long *state, float lo, float hi) {
    return lo + (hi - lo) * (float)(random_next(state) >> 8) * (1.0f / 16777216.0f);
}
static void random_seed(unsigned long long *state, unsigned long long seed) {
    *state = 0;
    random_next(state);
    *state += seed;
    random_next(state);
}

/* ---- options -------------------------------------------------------------------------------------- */
static int parse_switch(const char *text, int *out) {
    if (strcmp(text, "on") == 0) *out = 1;
    else if (strcmp(text, "off") == 0) *out = 0;
    else return 0;
    return 1;
}

static int parse_options(int argc, char **argv, options *out) {
    int i;
    memset(out, 0, sizeof *out);
    out->particles = DEFAULT_PARTICLES;
    out->seed = 1;
    out->start.random = 1;
    out->start.method = MOTUS_SEMI_IMPLICIT_EULER;
    for (i = 1; i < argc; ++i) {
        const char *name = argv[i], *value = i + 1 < argc ? argv[i + 1] : NULL;
        char *end;
        if (!value) return 0;
        ++i;
        if (strcmp(name, "--frames") == 0) {
            out->frames = strtol(value, &end, 10);
            if (*end != '\0' || out->frames < 0) return 0;
        } else if (strcmp(name, "--particles") == 0) {
            long n = strtol(value, &end, 10);
            if (*end != '\0' || n < 1 || n > MAX_PARTICLES) return 0;
            out->particles = (int)n;
        } else if (strcmp(name, "--seed") == 0) {
            out->seed = strtoul(value, &end, 10);
            if (*end != '\0') return 0;
        } else if (strcmp(name, "--screenshot") == 0) {
            out->screenshot = value;
        } else if (strcmp(name, "--method") == 0) {
            int m;
            for (m = 0; m < MOTUS_METHOD_COUNT && strcmp(motus_method_name((motus_method)m), value) != 0; ++m) {}
            if (m == MOTUS_METHOD_COUNT) return 0;
            out->start.method = (motus_method)m;
        } else if (!((strcmp(name, "--gravity") == 0 && parse_switch(value, &out->start.gravity)) ||
                     (strcmp(name, "--wind") == 0 && parse_switch(value, &out->start.wind)) ||
                     (strcmp(name, "--random") == 0 && parse_switch(value, &out->start.random)) ||
                     (strcmp(name, "--damping") == 0 && parse_switch(value, &out->start.damping)) ||
                     (strcmp(name, "--collisions") == 0 && parse_switch(value, &out->start.collisions)) ||
                     (strcmp(name, "--tether") == 0 && parse_switch(value, &out->start.tether)))) {
            return 0;
        }
    }
    return 1;
}

/* ---- the simulation ------------------------------------------------------------------------------- */
/* Every particle at its seeded start: the same places, velocities, masses and colours on every reset. */
static void sandbox_place(sandbox *s) {
    int i;
    random_seed(&s->random_state, s->seed);
    for (i = 0; i < s->count; ++i) {
        const float mass = random_range(&s->random_state, MIN_MASS, MAX_MASS);
        position_x[i] = random_range(&s->random_state, MAX_RADIUS, WINDOW_WIDTH - MAX_RADIUS);
        position_y[i] = random_range(&s->random_state, MAX_RADIUS, WINDOW_HEIGHT - MAX_RADIUS);
        velocity_x[i] = random_range(&s->random_state, -MAX_SPEED, MAX_SPEED);
        velocity_y[i] = random_range(&s->random_state, -MAX_SPEED, MAX_SPEED);
        force_x[i] = force_y[i] = 0;
        inverse_mass[i] = 1.0f / mass;
        radius[i] = RADIUS_OF_MASS(mass);
        colour[i] = ColorFromHSV(random_range(&s->random_state, 0, 360), random_range(&s->random_state, 0.55f, 0.9f),
                                 1.0f);
    }
    s->steps = 0;
}

static void sandbox_init(sandbox *s, const options *opts) {
    memset(s, 0, sizeof *s);
    s->count = opts->particles;
    s->seed = opts->seed;
    s->on = opts->start;
    s->on.presses = 0;
    s->tether_point = motus_v3(WINDOW_WIDTH * 0.5f, WINDOW_HEIGHT * 0.5f, 0);
    sandbox_place(s);
}

/* The scene as the toggles say: a term left zero is work not done. */
static motus_scene scene_from(const toggles *on, motus_vec3 tether_point) {
    motus_scene scene;
    memset(&scene, 0, sizeof scene); /* zero: no forces */
    scene.method = on->method;
    if (on->gravity) scene.gravity = motus_v3(0, GRAVITY, 0);
    if (on->damping) scene.damping_per_second = DAMPING_PER_SECOND;
    if (on->tether) {
        /* F = -k*(x - pointer) on every particle, calmed by a linear drag; the exact method takes no tether
           (motus_step would refuse the scene: MOTUS_ERROR_UNSUPPORTED), so it steps the drag alone */
        scene.linear_drag = TETHER_DRAG;
        if (on->method != MOTUS_EXACT_LINEAR_DRAG) {
            scene.tether = tether_point;
            scene.tether_stiffness = TETHER_STIFFNESS;
        }
    }
    scene.bounds_min = motus_v3(MAX_RADIUS, MAX_RADIUS, 0);
    scene.bounds_max = motus_v3(WINDOW_WIDTH - MAX_RADIUS, WINDOW_HEIGHT - MAX_RADIUS, 0);
    scene.restitution = RESTITUTION;
    if (on->collisions) {
        /* Balls of their drawn radius (state.radius): the walls are the window's edges, which each ball
           touches at its own radius; restitution_threshold 0 is motus's automatic one (a few frames of
           gravity), below which a contact does not bounce, so that the pile comes to rest. */
        scene.contacts.enabled = 1;
        scene.substeps = CONTACT_SUBSTEPS;
        scene.contacts.restitution = CONTACT_RESTITUTION;
        scene.contacts.friction = CONTACT_FRICTION;
        scene.bounds_min = motus_v3(0, 0, 0);
        scene.bounds_max = motus_v3(WINDOW_WIDTH, WINDOW_HEIGHT, 0);
        scene.restitution = CONTACT_RESTITUTION;
    }
    return scene;
}

/* The arrays as a motus_state: the force arrays only while a force is on (NULL: none to read). */
static motus_state state_from(const sandbox *s) {
    motus_state state;
    memset(&state, 0, sizeof state);
    state.dimensions = 2;
    state.count = s->count;
    state.position[0] = position_x;
    state.position[1] = position_y;
    state.velocity[0] = velocity_x;
    state.velocity[1] = velocity_y;
    if (s->on.wind || s->on.random) {
        state.force[0] = force_x;
        state.force[1] = force_y;
    }
    state.inverse_mass = inverse_mass;
    if (s->on.collisions) state.radius = radius;
    return state;
}

/* This frame's force on each particle: the wind plus a new random kick. */
static void fill_forces(sandbox *s) {
    const float wind = s->on.wind ? WIND : 0.0f;
    int i;
    if (s->on.random) {
        for (i = 0; i < s->count; ++i) {
            force_x[i] = wind + random_range(&s->random_state, -KICK, KICK);
            force_y[i] = random_range(&s->random_state, -KICK, KICK);
        }
    } else {
        for (i = 0; i < s->count; ++i) {
            force_x[i] = wind;
            force_y[i] = 0;
        }
    }
}

static void handle_keys(sandbox *s) {
    if (IsKeyPressed(KEY_G)) s->on.gravity = !s->on.gravity, ++s->on.presses;
    if (IsKeyPressed(KEY_W)) s->on.wind = !s->on.wind, ++s->on.presses;
    if (IsKeyPressed(KEY_K)) s->on.random = !s->on.random, ++s->on.presses;
    if (IsKeyPressed(KEY_D)) s->on.damping = !s->on.damping, ++s->on.presses;
    if (IsKeyPressed(KEY_C)) s->on.collisions = !s->on.collisions, ++s->on.presses;
    if (IsKeyPressed(KEY_T)) s->on.tether = !s->on.tether, ++s->on.presses;
    if (IsKeyPressed(KEY_M)) s->on.method = (motus_method)((s->on.method + 1) % MOTUS_METHOD_COUNT), ++s->on.presses;
    if (IsKeyPressed(KEY_R)) sandbox_place(s), ++s->resets, ++s->on.presses;
    /* the tether's point: the pointer, once it has moved from where it was when the window opened (so that
       a scripted run that never moves it keeps the centre, wherever the X server put the pointer) */
    const Vector2 mouse = GetMousePosition();
    if (s->pointer_polls < 2) s->pointer_start = mouse, ++s->pointer_polls;
    else if (mouse.x != s->pointer_start.x || mouse.y != s->pointer_start.y) s->pointer_moved = 1;
    if (s->pointer_moved) {
        s->tether_point.x = mouse.x < 0 ? 0 : mouse.x > WINDOW_WIDTH ? WINDOW_WIDTH : mouse.x;
        s->tether_point.y = mouse.y < 0 ? 0 : mouse.y > WINDOW_HEIGHT ? WINDOW_HEIGHT : mouse.y;
    }
}

/* Room for motus_step's scratch: none without collisions; with them, motus_scratch_size bytes (the contacts'
   grid and pair list), allocated here once it grows, never in the step. Returns 0 if it cannot be had. */
static int ensure_scratch(sandbox *s, const motus_scene *scene, const motus_state *state) {
    const size_t bytes = motus_scratch_size(scene, state);
    void *grown;
    if (bytes == (size_t)-1) return 0;
    if (bytes <= s->scratch_bytes) return 1;
    grown = realloc(s->scratch, bytes); /* malloc's alignment suits any motus_real */
    if (!grown) return 0;
    s->scratch = grown, s->scratch_bytes = bytes;
    return 1;
}

static void sandbox_step(sandbox *s) {
    double start, us;
    motus_result result;
    s->scene = scene_from(&s->on, s->tether_point);
    s->state = state_from(s);
    if (s->state.force[0]) fill_forces(s);
    if (!ensure_scratch(s, &s->scene, &s->state)) {
        fprintf(stderr, "sandbox: no memory for motus_step's scratch\n");
        exit(1);
    }

    start = GetTime();
    result = motus_step(&s->scene, &s->state, DT, s->scratch, s->scratch_bytes);
    ++s->steps;
    us = (GetTime() - start) * 1e6;
    /* The plain mean of the first measurements, so that the first (cold caches, first touch of the arrays'
       pages) does not linger; then an exponential moving average. */
    ++s->steps_timed;
    s->us_per_step += (s->steps_timed < 20 ? 1.0 / s->steps_timed : TIMING_SMOOTHING) * (us - s->us_per_step);

    if (result != MOTUS_OK && result != s->last_result) /* say it once, not every frame */
        fprintf(stderr, "sandbox: motus_step: %s\n", motus_result_string(result));
    s->last_result = result;
}

/* ---- drawing -------------------------------------------------------------------------------------- */
/* The terms of the scene and state the sandbox can switch on (and the ones it never does, shown unlit). */
#define TERM_COUNT 11
static void scene_terms(const motus_scene *scene, const motus_state *state, const char *names[TERM_COUNT],
                        int on[TERM_COUNT]) {
    static const char *const NAMES[TERM_COUNT] = {"gravity", "linear_drag", "quadratic_drag", "damping_per_step",
                                                  "damping_per_second", "attractor", "bounds", "state.force",
                                                  "state.inverse_mass", "contacts", "tether"};
    int i;
    for (i = 0; i < TERM_COUNT; ++i) names[i] = NAMES[i];
    on[0] = scene->gravity.x != 0 || scene->gravity.y != 0;
    on[1] = scene->linear_drag != 0;
    on[2] = scene->quadratic_drag != 0;
    on[3] = scene->damping_per_step != 0;
    on[4] = scene->damping_per_second != 0;
    on[5] = scene->attractor_strength != 0;
    on[6] = scene->bounds_min.x != 0 || scene->bounds_min.y != 0 || scene->bounds_max.x != 0 ||
            scene->bounds_max.y != 0;
    on[7] = state->force[0] != NULL;
    on[8] = state->inverse_mass != NULL;
    on[9] = scene->contacts.enabled != 0; /* with state.radius */
    on[10] = scene->tether_stiffness != 0;
}

/* "gravity|bounds|state.inverse_mass", or "none". */
static void terms_text(const motus_scene *scene, const motus_state *state, char *text, size_t size) {
    const char *names[TERM_COUNT];
    int on[TERM_COUNT], i;
    scene_terms(scene, state, names, on);
    text[0] = '\0';
    for (i = 0; i < TERM_COUNT; ++i) {
        if (!on[i]) continue;
        if (text[0]) strncat(text, "|", size - strlen(text) - 1);
        strncat(text, names[i], size - strlen(text) - 1);
    }
    if (!text[0]) snprintf(text, size, "none");
}

static Texture2D make_dot(void) {
    enum { SIZE = 32 };
    const float centre = (SIZE - 1) * 0.5f, edge = SIZE * 0.5f - 1;
    Image image = GenImageColor(SIZE, SIZE, BLANK);
    Texture2D texture;
    int x, y;
    for (y = 0; y < SIZE; ++y) {
        for (x = 0; x < SIZE; ++x) { /* full inside, fading over the outer two pixels */
            const float dx = x - centre, dy = y - centre, alpha = (edge - sqrtf(dx * dx + dy * dy)) * 0.5f;
            if (alpha > 0) ImageDrawPixel(&image, x, y, ColorAlpha(WHITE, alpha > 1 ? 1 : alpha));
        }
    }
    texture = LoadTextureFromImage(image);
    SetTextureFilter(texture, TEXTURE_FILTER_BILINEAR);
    UnloadImage(image);
    return texture;
}

static void draw_particles(const sandbox *s) {
    const float scale = 1.0f / (float)s->dot.width;
    int i;
    for (i = 0; i < s->count; ++i) {
        Vector2 corner;
        corner.x = position_x[i] - radius[i];
        corner.y = position_y[i] - radius[i];
        DrawTextureEx(s->dot, corner, 0, 2 * radius[i] * scale, colour[i]);
    }
}

static void draw_hud(const sandbox *s) {
    const char *timing = TextFormat("motus_step: %.1f us per frame", s->us_per_step);
    const char *note = "for all particles, measured here (moving average)";
    const int help_y = WINDOW_HEIGHT - BOTTOM_BAR_HEIGHT + 8;
    const char *names[TERM_COUNT];
    int on[TERM_COUNT];
    struct {
        const char *key, *what;
        int on;
    } keys[6];
    int i, x;

    DrawRectangle(0, 0, WINDOW_WIDTH, TOP_BAR_HEIGHT, PANEL);
    DrawLine(0, TOP_BAR_HEIGHT, WINDOW_WIDTH, TOP_BAR_HEIGHT, RULE);
    DrawText("motus sandbox", 14, 9, 20, TEXT_BRIGHT);
    DrawText(TextFormat("%d particles", s->count), 176, 9, 20, TEXT_DIM);
    DrawText(timing, WINDOW_WIDTH - 14 - MeasureText(timing, 20), 9, 20, TEXT_BRIGHT);
    DrawText(note, WINDOW_WIDTH - 14 - MeasureText(note, 10), 29, 10, TEXT_DIM);

    /* The method, then the terms a scene can have, in two rows of columns; the ones this frame's has are lit. */
    DrawText(TextFormat("[M] method: %s", motus_method_name(s->scene.method)), 14, 31, 10, LIT);
    DrawText("terms:", 14, FLAGS_TOP, 10, TEXT_DIM);
    DrawText("lit = on", 14, FLAGS_TOP + FLAG_ROW, 10, TEXT_DIM);
    scene_terms(&s->scene, &s->state, names, on);
    for (i = 0; i < TERM_COUNT; ++i) {
        const int width = MeasureText(names[i], 10);
        const int fx = FLAG_LEFT + (i % FLAG_COLUMNS) * FLAG_COLUMN, fy = FLAGS_TOP + (i / FLAG_COLUMNS) * FLAG_ROW;
        if (on[i]) {
            Rectangle pill;
            pill.x = (float)fx - 5, pill.y = (float)fy - 4, pill.width = (float)width + 10, pill.height = 17;
            DrawRectangleRounded(pill, 0.5f, 6, LIT_BACK);
        }
        DrawText(names[i], fx, fy, 10, on[i] ? LIT : TEXT_DIM);
    }

    keys[0].key = "G", keys[0].what = "gravity", keys[0].on = s->on.gravity;
    keys[1].key = "W", keys[1].what = "wind", keys[1].on = s->on.wind;
    keys[2].key = "K", keys[2].what = "random kicks", keys[2].on = s->on.random;
    keys[3].key = "D", keys[3].what = "damping", keys[3].on = s->on.damping;
    keys[4].key = "C", keys[4].what = "collisions", keys[4].on = s->on.collisions;
    keys[5].key = "T", keys[5].what = "tether to the mouse", keys[5].on = s->on.tether;
    DrawRectangle(0, WINDOW_HEIGHT - BOTTOM_BAR_HEIGHT, WINDOW_WIDTH, BOTTOM_BAR_HEIGHT, PANEL);
    DrawLine(0, WINDOW_HEIGHT - BOTTOM_BAR_HEIGHT, WINDOW_WIDTH, WINDOW_HEIGHT - BOTTOM_BAR_HEIGHT, RULE);
    x = 14;
    for (i = 0; i < 6; ++i) {
        const char *label = TextFormat("[%s] %s %s", keys[i].key, keys[i].what, keys[i].on ? "on" : "off");
        DrawText(label, x, help_y, 10, keys[i].on ? LIT : TEXT_DIM);
        x += MeasureText(label, 10) + 14;
    }
    if (s->on.tether && s->scene.tether_stiffness == 0) /* the exact method: no tether */
        DrawText("exact_linear_drag takes no tether: drag only", 14, TOP_BAR_HEIGHT + 6, 10, TEXT_BRIGHT);
    DrawText("[R] reset    ESC quit", WINDOW_WIDTH - 14 - MeasureText("[R] reset    ESC quit", 10), help_y, 10,
             TEXT_DIM);
}

static void draw(const sandbox *s) {
    ClearBackground(BACKGROUND);
    draw_particles(s);
    draw_hud(s);
}

/* ---- the run -------------------------------------------------------------------------------------- */
typedef struct overlaps {
    long pairs;          /* pairs of balls (of their drawn radius) that overlap, -1 if they could not be found */
    double largest;      /* px */
    double largest_share; /* of the smaller radius of the pair */
} overlaps;

/* The balls as drawn that are in contact now (overlapping or within 1% of touching), by motus_find_contacts
   (the step's broadphase; the scene and state as with collisions on, whatever the toggles say). */
static overlaps find_overlaps(sandbox *s) {
    overlaps o = {-1, 0, 0};
    toggles colliding = s->on;
    motus_scene scene;
    motus_state state;
    motus_contact_pair *pairs;
    int capacity = 4 * s->count, found = 0, k;
    colliding.collisions = 1;
    scene = scene_from(&colliding, s->tether_point);
    state = state_from(s);
    state.radius = radius;
    for (;;) {
        pairs = (motus_contact_pair *)malloc((size_t)capacity * sizeof *pairs);
        if (!pairs || !ensure_scratch(s, &scene, &state) ||
            motus_find_contacts(&scene, &state, s->scratch, s->scratch_bytes, pairs, capacity, &found) != MOTUS_OK) {
            free(pairs);
            return o;
        }
        if (found <= capacity) break;
        free(pairs); /* more than room: again with room for all */
        capacity = found;
    }
    o.pairs = found;
    for (k = 0; k < found; ++k) {
        const int a = pairs[k].a, b = pairs[k].b;
        const double dx = (double)position_x[b] - position_x[a], dy = (double)position_y[b] - position_y[a];
        const double depth = (double)radius[a] + radius[b] - sqrt(dx * dx + dy * dy);
        const double smaller = radius[a] < radius[b] ? radius[a] : radius[b];
        if (depth > o.largest) o.largest = depth;
        if (depth / smaller > o.largest_share) o.largest_share = depth / smaller;
    }
    free(pairs);
    return o;
}

static void print_summary(sandbox *s, long frames, double seconds) {
    double sum_x = 0, sum_y = 0, sum_vx = 0, sum_vy = 0, sum_v2 = 0;
    const double slack = 0.01; /* px: a ball resting on a wall touches it to rounding */
    char terms[200];
    int i, inside = 0, whole = 0;
    overlaps o = find_overlaps(s);
    for (i = 0; i < s->count; ++i) {
        const double x = position_x[i], y = position_y[i], r = radius[i];
        if (x >= 0 && x <= WINDOW_WIDTH && y >= 0 && y <= WINDOW_HEIGHT) ++inside;
        if (x - r >= -slack && x + r <= WINDOW_WIDTH + slack && y - r >= -slack && y + r <= WINDOW_HEIGHT + slack)
            ++whole;
        sum_x += x;
        sum_y += y;
        sum_vx += velocity_x[i];
        sum_vy += velocity_y[i];
        sum_v2 += (double)velocity_x[i] * velocity_x[i] + (double)velocity_y[i] * velocity_y[i];
    }
    terms_text(&s->scene, &s->state, terms, sizeof terms);
    printf("frames=%ld particles=%d scene=%s method=%s gravity=%d wind=%d random=%d damping=%d collisions=%d "
           "tether=%d tether_x=%.1f tether_y=%.1f toggles=%ld resets=%ld steps=%ld inside=%d whole=%d mean_x=%.3f mean_y=%.3f mean_vx=%.3f mean_vy=%.3f "
           "rms_speed=%.3f overlaps=%ld max_overlap=%.4f overlap_ratio=%.5f us_per_step=%.3f fps=%.1f\n",
           frames, s->count, terms, motus_method_name(s->scene.method), s->on.gravity, s->on.wind, s->on.random,
           s->on.damping, s->on.collisions, s->on.tether, s->tether_point.x, s->tether_point.y, s->on.presses, s->resets, s->steps, inside, whole, sum_x / s->count,
           sum_y / s->count, sum_vx / s->count, sum_vy / s->count, sqrt(sum_v2 / s->count), o.pairs, o.largest,
           o.largest_share, s->us_per_step, seconds > 0 ? frames / seconds : 0.0);
}

int main(int argc, char **argv) {
    static sandbox s;
    options opts;
    long frame;
    double started;

    if (!parse_options(argc, argv, &opts)) {
        fprintf(stderr,
                "usage: %s [--frames N] [--particles N] [--seed N] [--gravity on|off] [--wind on|off]\n"
                "       [--random on|off] [--damping on|off] [--collisions on|off] [--tether on|off] [--method NAME]\n"
                "       [--screenshot FILE]\n",
                argv[0]);
        return 2;
    }
    sandbox_init(&s, &opts);
    s.scene = scene_from(&s.on, s.tether_point); /* what the HUD and the summary show if no frame runs */
    s.state = state_from(&s);

    SetTraceLogLevel(LOG_WARNING);
    InitWindow(WINDOW_WIDTH, WINDOW_HEIGHT, "motus - sandbox");
    if (!IsWindowReady()) {
        fprintf(stderr, "sandbox: could not open a window (no display? try xvfb-run)\n");
        return 1;
    }
    SetTargetFPS(60);
    s.dot = make_dot();

    started = GetTime();
    for (frame = 0; !WindowShouldClose() && (opts.frames == 0 || frame < opts.frames); ++frame) {
        handle_keys(&s);
        sandbox_step(&s);
        BeginDrawing();
        draw(&s);
        EndDrawing();
    }
    started = GetTime() - started; /* the run's seconds, for fps */

    if (opts.screenshot) {
        /* As in wsad.c: draw the last frame into an off-screen texture and save that. */
        RenderTexture2D target = LoadRenderTexture(WINDOW_WIDTH, WINDOW_HEIGHT);
        Image image;
        BeginTextureMode(target);
        draw(&s);
        EndTextureMode();
        image = LoadImageFromTexture(target.texture);
        ImageFlipVertical(&image); /* OpenGL textures are stored bottom-up */
        /* Opaque RGB: the translucent bars and the dots' soft edges blend into the texture's alpha too. */
        ImageFormat(&image, PIXELFORMAT_UNCOMPRESSED_R8G8B8);
        if (!ExportImage(image, opts.screenshot)) fprintf(stderr, "sandbox: could not write %s\n", opts.screenshot);
        UnloadImage(image);
        UnloadRenderTexture(target);
    }
    UnloadTexture(s.dot);
    CloseWindow();

    print_summary(&s, frame, started);
    free(s.scratch);
    return 0;
}

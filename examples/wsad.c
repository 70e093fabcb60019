/* wsad.c - one particle pushed around with W/A/S/D, written with motus.

   The reference program of motus: an 800x600 window at 60 FPS, a particle of mass 2 at the centre. Each
   frame the force is cleared, each held key adds a force of 100 up/left/down/right, the particle takes one
   semi-implicit Euler step of the frame's duration, 1% of its velocity is removed (v *= 0.99), and a label
   next to it shows its force, velocity, position and mass. One unit of length is one pixel; y grows downwards.

   Options, so that a script can drive it without a person (the defaults are the interactive program):
     --frames N         stop after N frames (default: run until the window is closed or Escape)
     --fixed-dt         step exactly 1/60 s per frame instead of the measured frame time (reproducible runs)
     --autopilot        hold D for the first 60 frames, then S for 30, instead of waiting for a player
     --screenshot FILE  save the last frame as a PNG
   On exit it prints the particle's final state.
   It needs only the include: the particle functions are inline (no MOTUS_IMPLEMENTATION). */
#include "motus.h"
#include "raylib.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WINDOW_WIDTH 800
#define WINDOW_HEIGHT 600
#define STRENGTH 100.0f /* newtons per held key */
#define DAMPING 0.01f   /* fraction of the velocity removed per frame: frame-rate dependent, as in the reference */
#define MASS 2.0f
#define PARTICLE_RADIUS 5.0f

typedef struct options {
    long frames; /* 0: no limit */
    int fixed_dt;
    int autopilot;
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
            out->fixed_dt = 1;
        } else if (strcmp(argv[i], "--autopilot") == 0) {
            out->autopilot = 1;
        } else {
            return 0;
        }
    }
    return 1;
}

/* Which way the player pushes this frame, as in the reference's HandleInputs. */
static void handle_inputs(motus_particle *particle, long frame, int autopilot) {
    int up = IsKeyDown(KEY_W), left = IsKeyDown(KEY_A), down = IsKeyDown(KEY_S), right = IsKeyDown(KEY_D);
    if (autopilot) {
        right = right || frame < 60;
        down = down || (frame >= 60 && frame < 90);
    }
    if (up) motus_particle_add_force(particle, motus_v2(0, -STRENGTH));
    if (left) motus_particle_add_force(particle, motus_v2(-STRENGTH, 0));
    if (down) motus_particle_add_force(particle, motus_v2(0, STRENGTH));
    if (right) motus_particle_add_force(particle, motus_v2(STRENGTH, 0));
}

static void describe(const motus_particle *particle, char *text, size_t size) {
    snprintf(text, size, "force=(%.2f, %.2f)\nvelocity=(%.2f, %.2f)\nposition=(%.2f, %.2f)\nmass=%.2f",
             (double)particle->force.x, (double)particle->force.y, (double)particle->velocity.x,
             (double)particle->velocity.y, (double)particle->position.x, (double)particle->position.y,
             (double)motus_particle_mass(particle));
}

static void draw(const motus_particle *particle) {
    char text[256];
    Vector2 centre;
    centre.x = particle->position.x; /* motus_vec2 and Vector2 share their layout; spelled out for clarity */
    centre.y = particle->position.y;
    DrawCircleV(centre, PARTICLE_RADIUS, WHITE);
    describe(particle, text, sizeof text);
    DrawText(text, (int)particle->position.x + 5, (int)particle->position.y + 5, 10, WHITE);
}

int main(int argc, char **argv) {
    options opts;
    motus_particle particle;
    long frame;
    motus_result result;
    char state[256];

    if (!parse_options(argc, argv, &opts)) {
        fprintf(stderr, "usage: %s [--frames N] [--fixed-dt] [--autopilot] [--screenshot FILE]\n", argv[0]);
        return 2;
    }
    result = motus_particle_init(&particle, motus_v2(WINDOW_WIDTH / 2, WINDOW_HEIGHT / 2), MASS);
    if (result != MOTUS_OK) {
        fprintf(stderr, "wsad: %s\n", motus_result_string(result));
        return 1;
    }

    SetTraceLogLevel(LOG_WARNING);
    InitWindow(WINDOW_WIDTH, WINDOW_HEIGHT, "motus - WSAD");
    if (!IsWindowReady()) {
        fprintf(stderr, "wsad: could not open a window (no display? try xvfb-run)\n");
        return 1;
    }
    SetTargetFPS(60);

    for (frame = 0; !WindowShouldClose() && (opts.frames == 0 || frame < opts.frames); ++frame) {
        float dt = opts.fixed_dt ? 1.0f / 60.0f : GetFrameTime();

        motus_particle_clear_forces(&particle);
        handle_inputs(&particle, frame, opts.autopilot);
        /* The first frame can measure 0 s: a step of 0 s is valid and moves nothing. */
        result = motus_particle_step(&particle, dt);
        if (result != MOTUS_OK) fprintf(stderr, "wsad: frame %ld: %s\n", frame, motus_result_string(result));
        motus_particle_damp_per_step(&particle, DAMPING);

        BeginDrawing();
        ClearBackground(BLACK);
        draw(&particle);
        EndDrawing();
    }

    if (opts.screenshot) {
        /* Draw the final frame into an off-screen texture and save that: reading the window's back buffer
           after the swap is undefined, and TakeScreenshot() would keep only the file name of the path. */
        RenderTexture2D target = LoadRenderTexture(WINDOW_WIDTH, WINDOW_HEIGHT);
        Image image;
        BeginTextureMode(target);
        ClearBackground(BLACK);
        draw(&particle);
        EndTextureMode();
        image = LoadImageFromTexture(target.texture);
        ImageFlipVertical(&image); /* OpenGL textures are stored bottom-up */
        if (!ExportImage(image, opts.screenshot)) fprintf(stderr, "wsad: could not write %s\n", opts.screenshot);
        UnloadImage(image);
        UnloadRenderTexture(target);
    }
    CloseWindow();

    describe(&particle, state, sizeof state);
    for (char *c = state; *c; ++c)
        if (*c == '\n') *c = ' ';
    printf("frames=%ld %s\n", frame, state);
    return 0;
}

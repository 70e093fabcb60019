/* fuzz_motus.c - a libFuzzer harness for motus.h: random bytes become particles, force models, springs,
   methods, time steps, damping, scenes and batch ranges, and every public entry point is called with them.

   What it asserts, beyond "no crash, no sanitizer report" (ASan + UBSan in every build of it):
   - a call that returns an error leaves its state byte for byte as it was: the particle; the particles,
     the stepper and what the stepper remembers in its scratch (position Verlet's last displacements, the
     kept accelerations of MOTUS_STEPPER_REUSE_FORCES); the batch arrays. The documented exceptions:
     motus_batch_step returning MOTUS_ERROR_NOT_FINITE may have written its range (release builds; with
     MOTUS_CHECKED only when motus_batch_check found the range clean, i.e. the step itself overflowed), and
     motus_batch_add_spring_forces returning it may have written forces (release builds only);
   - a call that returns MOTUS_OK on valid input leaves valid state: every field finite, inverse mass >= 0
     (the stepper's clock too); a step that returns MOTUS_OK has finite positions and velocities whatever
     it was given;
   - nothing outside what a call was given is written: particles past `count`, batch elements outside
     [first, first + count). Arrays are malloc'd to their exact size, so ASan sees any access past them.

   Built three ways (tests/CMakeLists.txt builds the replay; scripts/check-tools.sh fuzz builds the fuzzer):
   - clang -fsanitize=fuzzer,address,undefined: the fuzzer, run for a bounded time on tests/fuzz/corpus/;
   - with FUZZ_MOTUS_REPLAY: a main() that runs the files named on its command line once each, so that the
     corpus is a regression test in every build (gcc, ASan, valgrind) without libFuzzer;
   - float and double, release and MOTUS_CHECKED. */
#include "motus.h"

#include <float.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef MOTUS_DOUBLE
#define REAL_MAX DBL_MAX
#define REAL_MIN_NORMAL DBL_MIN
#define REAL_TRUE_MIN 4.9406564584124654e-324
#else
#define REAL_MAX FLT_MAX
#define REAL_MIN_NORMAL FLT_MIN
#define REAL_TRUE_MIN 1.40129846e-45f
#endif

#define MAX_PARTICLES 40 /* more than two AVX-512 vectors of float, so whole and partial vectors both run */
#define MAX_SPRINGS 8
#define MAX_OPERATIONS 48

/* ---- failing: print what broke and abort, which libFuzzer reports with the input that did it ---- */
static void fail(const char *what, const char *call, int line) {
    fprintf(stderr, "fuzz_motus.c:%d: %s: %s\n", line, call, what);
    abort();
}
#define REQUIRE(condition, call)                                                                            \
    do {                                                                                                    \
        if (!(condition)) fail("REQUIRE(" #condition ") failed", call, __LINE__);                           \
    } while (0)

/* ---- the input: bytes read in order; past the end every read gives zero ---- */
typedef struct reader {
    const uint8_t *data;
    size_t size, at;
} reader;

static unsigned byte(reader *r) { return r->at < r->size ? r->data[r->at++] : 0u; }
static int more(const reader *r) { return r->at < r->size; }

/* An integer in [lo, hi]. */
static int int_in(reader *r, int lo, int hi) {
    unsigned span = (unsigned)(hi - lo) + 1u, v = byte(r);
    v |= byte(r) << 8; /* two statements: the order of two reads in one expression is unspecified */
    return lo + (int)(v % span);
}

/* A real: mostly the values that break arithmetic (zeros, extremes, subnormals, NaN, infinities) and
   small ordinary numbers, sometimes any bit pattern. */
static motus_real real(reader *r) {
    unsigned k = byte(r);
    switch (k % 24) {
    case 0: return 0;
    case 1: return -(motus_real)0;
    case 2: return 1;
    case 3: return -1;
    case 4: return (motus_real)NAN;
    case 5: return (motus_real)HUGE_VAL;
    case 6: return -(motus_real)HUGE_VAL;
    case 7: return REAL_MAX;
    case 8: return -REAL_MAX;
    case 9: return REAL_MIN_NORMAL;
    case 10: return REAL_TRUE_MIN;
    case 11: return (motus_real)(1.0 / 60.0);
    case 12: return (motus_real)1e-7;
    case 13: return (motus_real)1e20;
    case 14: return (motus_real)1e-20;
    case 15: return (motus_real)0.99;
    case 16: { /* any bit pattern */
        motus_real x;
        unsigned char bytes[sizeof(motus_real)];
        size_t i;
        for (i = 0; i < sizeof bytes; ++i) bytes[i] = (unsigned char)byte(r);
        memcpy(&x, bytes, sizeof x);
        return x;
    }
    default: { /* a small number: a signed byte over a power of two */
        int v = (int)byte(r) - 128;
        return (motus_real)v / (motus_real)(1 << (k % 8));
    }
    }
}

static motus_vec2 vec2(reader *r) {
    motus_real x = real(r);
    return motus_v2(x, real(r));
}

static int finite_particle(const motus_particle *p) {
    return motus_vec2_is_finite(p->position) && motus_vec2_is_finite(p->velocity) &&
           motus_vec2_is_finite(p->force) && motus_real_is_finite(p->inverse_mass);
}
static int valid_particle(const motus_particle *p) { return finite_particle(p) && p->inverse_mass >= 0; }

static void check_string(motus_result result) {
    const char *text = motus_result_string(result);
    REQUIRE(text != NULL && text[0] != '\0', "motus_result_string");
    REQUIRE((unsigned)result < MOTUS_RESULT_COUNT, "result code");
}

/* ---- the world one input builds ---- */
typedef struct callback_model {
    int mode;          /* 0: constant force, 1: spring to the origin, 2: depends on count, 3: writes NaN */
    motus_vec2 force;  /* the constant */
    motus_real k;      /* the spring constant */
    int calls;
} callback_model;

typedef struct world {
    int n; /* particles in use */
    motus_particle particles[MAX_PARTICLES];
    motus_stepper stepper;
    void *scratch;
    size_t scratch_bytes;
    int have_stepper;
    motus_spring springs[MAX_SPRINGS];
    callback_model model;
} world;

static void force_callback(void *user_data, int count, const motus_vec2 *positions, const motus_vec2 *velocities,
                           motus_real time, motus_vec2 *forces) {
    callback_model *m = (callback_model *)user_data;
    int i;
    (void)velocities, (void)time;
    m->calls++;
    for (i = 0; i < count; ++i) {
        switch (m->mode) {
        case 0: forces[i] = motus_vec2_add(forces[i], m->force); break;
        case 1: forces[i] = motus_vec2_sub(forces[i], motus_vec2_scale(positions[i], m->k)); break;
        case 2: forces[i].x += (motus_real)count * m->k; break;
        default: forces[i].y = (motus_real)NAN; break;
        }
    }
}

/* ---- one particle: every per-particle function, all-or-nothing ---- */
static void particle_operation(world *w, reader *r) {
    const int which = int_in(r, 0, w->n - 1), op = (int)(byte(r) % 13), null = (byte(r) % 16) == 0;
    motus_particle *p = null ? NULL : &w->particles[which];
    motus_particle before = w->particles[which];
    const int was_valid = valid_particle(&before);
    motus_result result = MOTUS_OK;
    const char *call = "";
    switch (op) {
    case 0: call = "motus_particle_init"; {
        motus_vec2 x = vec2(r);
        result = motus_particle_init(p, x, real(r));
        if (result == MOTUS_OK) REQUIRE(valid_particle(p) && p->inverse_mass > 0, call);
        break;
    }
    case 1: call = "motus_particle_init_immovable";
        result = motus_particle_init_immovable(p, vec2(r));
        if (result == MOTUS_OK) REQUIRE(valid_particle(p) && p->inverse_mass == 0, call);
        break;
    case 2: call = "motus_particle_add_force"; result = motus_particle_add_force(p, vec2(r)); break;
    case 3: call = "motus_particle_clear_forces"; result = motus_particle_clear_forces(p); break;
    case 4: call = "motus_particle_step"; result = motus_particle_step(p, real(r)); break;
    case 5: call = "motus_particle_damp_per_step"; result = motus_particle_damp_per_step(p, real(r)); break;
    case 6: call = "motus_particle_damp_per_second"; {
        motus_real retained = real(r);
        result = motus_particle_damp_per_second(p, retained, real(r));
        break;
    }
    case 7: call = "motus_particle_bounce"; {
        motus_vec2 lo = vec2(r), hi = vec2(r);
        result = motus_particle_bounce(p, lo, hi, real(r));
        if (result == MOTUS_OK) /* inside the box afterwards */
            REQUIRE(p->position.x >= lo.x && p->position.x <= hi.x && p->position.y >= lo.y &&
                        p->position.y <= hi.y, call);
        break;
    }
    case 8: call = "motus_particle_step_linear_drag"; {
        motus_real k = real(r);
        result = motus_particle_step_linear_drag(p, k, real(r));
        break;
    }
    case 9: call = "motus_particle_check";
        result = motus_particle_check(p);
        if (p) REQUIRE((result == MOTUS_OK) == was_valid, call);
        break;
    case 10: call = "motus_particle_mass"; {
        motus_real m = motus_particle_mass(p);
        if (p && was_valid) REQUIRE(!(m <= 0), call); /* +Inf for immovable, NaN never for a valid one */
        break;
    }
    case 11: /* hand-filled data: NaN, negative masses, anything */
        if (!p) return;
        switch (byte(r) % 4) {
        case 0: p->position = vec2(r); break;
        case 1: p->velocity = vec2(r); break;
        case 2: p->force = vec2(r); break;
        default: p->inverse_mass = real(r); break;
        }
        return;
    default: call = "motus_damping_per_second_from_per_step"; {
        motus_real factor = real(r), rate = real(r), v = motus_damping_per_second_from_per_step(factor, rate);
        if (factor >= 0 && factor <= 1 && motus_real_is_finite(rate) && rate > 0) REQUIRE(v >= 0 && v <= 1, call);
        return;
    }
    }
    check_string(result);
    if (!p) {
        REQUIRE(result == MOTUS_ERROR_NULL_POINTER || op == 10, call);
        return;
    }
    if (result != MOTUS_OK) {
        REQUIRE(memcmp(&before, p, sizeof before) == 0, call);
        return;
    }
    if (op == 4 || op == 8) REQUIRE(motus_vec2_is_finite(p->position) && motus_vec2_is_finite(p->velocity), call);
    if (was_valid) REQUIRE(valid_particle(p), call);
}

/* ---- the force model ---- */
static void read_forces(world *w, reader *r, motus_forces *f, int count) {
    const unsigned terms = byte(r);
    int i;
    memset(f, 0, sizeof *f);
    if (terms & 1) f->gravity = vec2(r);
    if (terms & 2) f->linear_drag = real(r);
    if (terms & 4) f->quadratic_drag = real(r);
    if (terms & 8) {
        f->attractor_strength = real(r);
        f->attractor_position = vec2(r);
    }
    if (terms & 16) {
        f->spring_count = int_in(r, -1, MAX_SPRINGS);
        f->springs = (byte(r) % 16) ? w->springs : NULL;
        for (i = 0; i < MAX_SPRINGS && i < f->spring_count; ++i) {
            motus_spring *s = &w->springs[i];
            s->a = int_in(r, -1, count);
            s->b = int_in(r, -2, count);
            s->anchor = vec2(r);
            s->rest_length = real(r);
            s->stiffness = real(r);
            s->damping = real(r);
        }
    }
    if (terms & 32) {
        w->model.mode = (int)(byte(r) % 4);
        w->model.force = vec2(r);
        w->model.k = real(r);
        f->callback = force_callback;
        f->user_data = &w->model;
    }
}

/* What a stepper remembers between steps in its scratch: the part an error must not touch. */
static size_t remembered(const motus_stepper *s, const motus_vec2 **from) {
    const motus_vec2 *extra;
    *from = NULL;
    if (s->capacity == 0) return 0; /* no scratch, maybe NULL: no pointer arithmetic on it */
    extra = s->scratch + 3 * (size_t)s->capacity; /* after x, v, a */
    *from = extra;
    if (s->method == MOTUS_POSITION_VERLET) return (size_t)s->history_count * sizeof(motus_vec2);
    if ((s->method == MOTUS_VELOCITY_VERLET || s->method == MOTUS_LEAPFROG) && (s->flags & MOTUS_STEPPER_REUSE_FORCES))
        return (size_t)s->kept_acceleration_count * sizeof(motus_vec2);
    return 0;
}

static void stepper_init_operation(world *w, reader *r) {
    motus_stepper_desc desc;
    motus_stepper fresh, before;
    motus_result result;
    size_t needed;
    void *scratch;
    memset(&desc, 0, sizeof desc);
    desc.capacity = int_in(r, -1, MAX_PARTICLES);
    desc.method = (motus_method)(byte(r) % (MOTUS_METHOD_COUNT + 1));
    desc.flags = byte(r) % 4;
    needed = motus_stepper_scratch_size(desc.method, desc.capacity);
    desc.scratch_bytes = needed;
    switch (byte(r) % 8) {
    case 0: desc.scratch_bytes = needed > 0 ? needed - 1 : 0; break; /* too small */
    case 1: desc.scratch_bytes = needed + 64; break;
    default: break;
    }
    /* Exactly scratch_bytes, so that ASan sees a stepper that uses more than it asked for. */
    scratch = desc.scratch_bytes > 0 ? malloc(desc.scratch_bytes) : NULL;
    if (desc.scratch_bytes > 0 && !scratch) return;
    desc.scratch = (byte(r) % 16) ? scratch : NULL;
    memset(&fresh, 0xA5, sizeof fresh);
    before = fresh;
    result = motus_stepper_init(&fresh, &desc);
    check_string(result);
    if (result != MOTUS_OK) {
        REQUIRE(memcmp(&before, &fresh, sizeof fresh) == 0, "motus_stepper_init");
        free(scratch);
        return;
    }
    REQUIRE(desc.capacity >= 0 && (size_t)desc.scratch_bytes >= needed, "motus_stepper_init");
    free(w->scratch);
    w->scratch = scratch;
    w->scratch_bytes = desc.scratch_bytes;
    w->stepper = fresh;
    w->have_stepper = 1;
}

static void stepper_step_operation(world *w, reader *r) {
    motus_particle before[MAX_PARTICLES];
    motus_stepper stepper_before;
    motus_forces forces;
    unsigned char *memory_before = NULL;
    const motus_vec2 *memory = NULL;
    size_t memory_bytes;
    motus_result result;
    int count, i, all_valid = 1, forces_given, null_particles;
    motus_real dt;
    if (!w->have_stepper) return;
    count = int_in(r, -1, w->n);
    read_forces(w, r, &forces, count < 0 ? 0 : count);
    forces_given = (byte(r) % 8) != 0;
    null_particles = (byte(r) % 32) == 0;
    dt = real(r);
    if (byte(r) % 8 == 0) motus_stepper_reset(&w->stepper);

    memcpy(before, w->particles, sizeof before);
    stepper_before = w->stepper;
    memory_bytes = remembered(&w->stepper, &memory);
    if (memory_bytes) {
        memory_before = (unsigned char *)malloc(memory_bytes);
        if (!memory_before) return;
        memcpy(memory_before, memory, memory_bytes);
    }
    for (i = 0; i < count; ++i) all_valid &= valid_particle(&w->particles[i]);

    result = motus_stepper_step(&w->stepper, null_particles ? NULL : w->particles, count,
                                forces_given ? &forces : NULL, dt);
    check_string(result);
    /* Particles past count are never touched. */
    for (i = count < 0 ? 0 : count; i < MAX_PARTICLES; ++i)
        REQUIRE(memcmp(&before[i], &w->particles[i], sizeof before[i]) == 0, "motus_stepper_step past count");
    if (result != MOTUS_OK) {
        REQUIRE(memcmp(before, w->particles, sizeof before) == 0, "motus_stepper_step particles");
        REQUIRE(memcmp(&stepper_before, &w->stepper, sizeof stepper_before) == 0, "motus_stepper_step stepper");
        if (memory_bytes)
            REQUIRE(memcmp(memory_before, memory, memory_bytes) == 0, "motus_stepper_step remembered scratch");
    } else {
        REQUIRE(count >= 0 && count <= w->stepper.capacity, "motus_stepper_step count");
        for (i = 0; i < count; ++i) {
            const motus_particle *p = &w->particles[i];
            REQUIRE(motus_vec2_is_finite(p->position) && motus_vec2_is_finite(p->velocity), "motus_stepper_step");
            /* forces and masses are not the step's to change */
            REQUIRE(memcmp(&p->force, &before[i].force, sizeof p->force) == 0, "motus_stepper_step force");
            REQUIRE(memcmp(&p->inverse_mass, &before[i].inverse_mass, sizeof p->inverse_mass) == 0,
                    "motus_stepper_step inverse_mass");
            if (all_valid) REQUIRE(valid_particle(p), "motus_stepper_step");
        }
        if (all_valid) REQUIRE(motus_real_is_finite(w->stepper.time), "motus_stepper_step time");
    }
    free(memory_before);
}

/* ---- the batch kernels ---- */
typedef struct batch_memory {
    int n;
    motus_real *arrays[10]; /* position x3, velocity x3, force x3, inverse_mass; each n reals, malloc'd */
} batch_memory;

static int batch_alloc(batch_memory *m, int n) {
    int i;
    m->n = n;
    for (i = 0; i < 10; ++i) {
        m->arrays[i] = (motus_real *)malloc((size_t)n * sizeof(motus_real));
        if (!m->arrays[i]) return 0;
    }
    return 1;
}
static void batch_free(batch_memory *m) {
    int i;
    for (i = 0; i < 10; ++i) free(m->arrays[i]);
}
static void batch_copy(const batch_memory *from, batch_memory *to) {
    int i;
    for (i = 0; i < 10; ++i) memcpy(to->arrays[i], from->arrays[i], (size_t)from->n * sizeof(motus_real));
}
/* Element i of every array the same in a and b (bit for bit, so NaNs compare)? */
static int batch_same_at(const batch_memory *a, const batch_memory *b, int i) {
    int k;
    for (k = 0; k < 10; ++k)
        if (memcmp(&a->arrays[k][i], &b->arrays[k][i], sizeof(motus_real)) != 0) return 0;
    return 1;
}

/* What a failing batch step was given and did to particle i, for the report. */
static void print_batch_step(const motus_scene *s, const motus_batch *b, const batch_memory *before,
                             const batch_memory *after, int i, int first, int count, motus_real dt) {
    static const char *names[10] = {"x", "y", "z", "vx", "vy", "vz", "fx", "fy", "fz", "inverse_mass"};
    int k;
    fprintf(stderr, "scene: has=0x%x method=%d dims=%d gravity=(%g %g %g) linear_drag=%g quadratic_drag=%g "
                    "damping=%g inverse_mass=%g attractor=(%g %g %g) strength=%g bounds=(%g %g %g)-(%g %g %g) "
                    "restitution=%g\nrange [%d, %d + %d) dt=%g; particle %d before -> after:\n",
            s->has, (int)s->method, b->dimensions, (double)s->gravity[0], (double)s->gravity[1],
            (double)s->gravity[2], (double)s->linear_drag, (double)s->quadratic_drag, (double)s->damping,
            (double)s->inverse_mass, (double)s->attractor[0], (double)s->attractor[1], (double)s->attractor[2],
            (double)s->attractor_strength, (double)s->bounds_min[0], (double)s->bounds_min[1],
            (double)s->bounds_min[2], (double)s->bounds_max[0], (double)s->bounds_max[1], (double)s->bounds_max[2],
            (double)s->restitution, first, first, count, (double)dt, i);
    for (k = 0; k < 10; ++k)
        fprintf(stderr, "  %-12s %.9g -> %.9g\n", names[k], (double)before->arrays[k][i], (double)after->arrays[k][i]);
}

static void read_scene(reader *r, motus_scene *s) {
    int d;
    memset(s, 0, sizeof *s);
    s->has = byte(r);
    s->has |= byte(r) << 8;
    s->has &= (byte(r) % 16) ? 0x1FFu : 0xFFFFu; /* sometimes bits motus does not know */
    s->method = (motus_method)(byte(r) % 8 == 0 ? byte(r) % (MOTUS_METHOD_COUNT + 1) : byte(r) % 2);
    for (d = 0; d < 3; ++d) {
        s->gravity[d] = real(r);
        s->attractor[d] = real(r);
        s->bounds_min[d] = real(r);
        s->bounds_max[d] = real(r);
    }
    s->linear_drag = real(r);
    s->quadratic_drag = real(r);
    s->damping = real(r);
    s->inverse_mass = real(r);
    s->attractor_strength = real(r);
    s->restitution = real(r);
}

static void batch_operations(reader *r) {
    batch_memory data, before;
    motus_batch batch;
    motus_scene scene;
    const int n = int_in(r, 1, MAX_PARTICLES);
    int i, k, d, ops;
    if (!batch_alloc(&data, n) || !batch_alloc(&before, n)) goto done;
    for (k = 0; k < 10; ++k)
        for (i = 0; i < n; ++i) data.arrays[k][i] = byte(r) % 4 ? (motus_real)((int)byte(r) - 128) : real(r);
    memset(&batch, 0, sizeof batch);
    batch.dimensions = byte(r) % 8 ? 2 + (int)(byte(r) % 2) : (int)(byte(r) % 5);
    for (d = 0; d < 3; ++d) {
        unsigned nulls = byte(r);
        batch.position[d] = (nulls & 7) ? data.arrays[d] : NULL;
        batch.velocity[d] = (nulls & 56) ? data.arrays[3 + d] : NULL;
        batch.force[d] = (nulls & 192) ? data.arrays[6 + d] : NULL;
    }
    batch.inverse_mass = byte(r) % 16 ? data.arrays[9] : NULL;
    read_scene(r, &scene);

    for (ops = 0; ops < 16 && more(r); ++ops) {
        const unsigned op = byte(r) % 8;
        int first = int_in(r, -1, n), count, bad_index = -1;
        const char *bad_field = NULL;
        motus_result result, precheck;
        motus_real dt;
        count = first < 0 ? int_in(r, -1, n) : int_in(r, -1, n - first); /* never past the arrays */
        if (byte(r) % 32 == 0 && first > 0) count = INT_MAX; /* first + count overflows int */
        if (op == 0) read_scene(r, &scene);
        batch_copy(&data, &before);
        if (op < 5) { /* step */
            dt = real(r);
            precheck = motus_batch_check(&scene, &batch, first, count, NULL, NULL);
            result = motus_batch_step(&scene, &batch, first, count, dt);
            check_string(result);
            for (i = 0; i < n; ++i)
                if (first < 0 || count < 0 || i < first || i - first >= count)
                    REQUIRE(batch_same_at(&before, &data, i), "motus_batch_step outside its range");
#ifdef MOTUS_CHECKED
            if (result != MOTUS_OK && (result != MOTUS_ERROR_NOT_FINITE || precheck != MOTUS_OK))
#else
            if (result != MOTUS_OK && result != MOTUS_ERROR_NOT_FINITE)
#endif
                for (i = 0; i < n; ++i) REQUIRE(batch_same_at(&before, &data, i), "motus_batch_step error");
            if (result == MOTUS_OK)
                for (i = first; i < first + count; ++i)
                    for (d = 0; d < batch.dimensions; ++d)
                        if (!motus_real_is_finite(batch.position[d][i]) || !motus_real_is_finite(batch.velocity[d][i])) {
                            print_batch_step(&scene, &batch, &before, &data, i, first, count, dt);
                            fail("a non-finite result", "motus_batch_step returned MOTUS_OK", __LINE__);
                        }
            (void)precheck;
        } else if (op < 7) { /* check */
            result = motus_batch_check(&scene, &batch, first, count, (op == 5) ? &bad_index : NULL,
                                       (op == 5) ? &bad_field : NULL);
            check_string(result);
            for (i = 0; i < n; ++i) REQUIRE(batch_same_at(&before, &data, i), "motus_batch_check wrote");
            if (op == 5 && bad_field) REQUIRE(bad_index >= first && bad_index < first + count, "motus_batch_check index");
        } else { /* springs, 2D */
            motus_spring springs[MAX_SPRINGS];
            const int spring_count = int_in(r, -1, MAX_SPRINGS), springs_count_arg = int_in(r, -1, n);
            int all_finite = 1;
            for (i = 0; i < MAX_SPRINGS; ++i) {
                springs[i].a = int_in(r, -1, n);
                springs[i].b = int_in(r, -2, n);
                springs[i].anchor = vec2(r);
                springs[i].rest_length = real(r);
                springs[i].stiffness = real(r);
                springs[i].damping = real(r);
            }
            if (batch.dimensions == 2 && batch.position[0] && batch.position[1] && batch.velocity[0] &&
                batch.velocity[1] && batch.force[0] && batch.force[1])
                for (i = 0; i < springs_count_arg; ++i)
                    for (k = 0; k < 2; ++k)
                        all_finite &= motus_real_is_finite(batch.position[k][i]) &
                                      motus_real_is_finite(batch.velocity[k][i]) & motus_real_is_finite(batch.force[k][i]);
            result = motus_batch_add_spring_forces(&batch, springs_count_arg, byte(r) % 16 ? springs : NULL,
                                                   spring_count);
            check_string(result);
#ifndef MOTUS_CHECKED
            if (result == MOTUS_ERROR_NOT_FINITE) {
                /* Documented for release builds: the data is read once, so a NaN or Inf among the spring ends
                   (or a sum that overflows) is reported after the forces were added; only forces change. */
                for (i = 0; i < n; ++i)
                    for (k = 0; k < 6; ++k)
                        REQUIRE(memcmp(&before.arrays[k][i], &data.arrays[k][i], sizeof(motus_real)) == 0,
                                "motus_batch_add_spring_forces (NOT_FINITE) wrote a position or velocity");
                for (i = 0; i < n; ++i)
                    REQUIRE(memcmp(&before.arrays[9][i], &data.arrays[9][i], sizeof(motus_real)) == 0,
                            "motus_batch_add_spring_forces (NOT_FINITE) wrote an inverse mass");
            } else
#endif
            if (result != MOTUS_OK) {
                for (i = 0; i < n; ++i) REQUIRE(batch_same_at(&before, &data, i), "motus_batch_add_spring_forces");
            } else {
                /* only the force arrays change */
                for (i = 0; i < n; ++i)
                    for (k = 0; k < 6; ++k)
                        REQUIRE(memcmp(&before.arrays[k][i], &data.arrays[k][i], sizeof(motus_real)) == 0,
                                "motus_batch_add_spring_forces wrote a position or velocity");
#ifdef FUZZ_MOTUS_STRICT_SPRINGS
                /* Finite data and a valid model, yet the sum can overflow: the function does not check. */
                if (all_finite && spring_count > 0)
                    for (i = 0; i < springs_count_arg; ++i)
                        REQUIRE(motus_real_is_finite(data.arrays[6][i]) && motus_real_is_finite(data.arrays[7][i]),
                                "motus_batch_add_spring_forces OK with a non-finite force");
#endif
            }
            (void)all_finite;
        }
    }
done:
    batch_free(&data);
    batch_free(&before);
}

/* ---- the entry point ---- */
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    static world w; /* static: 40 particles and a model are too large to zero on the stack each run */
    reader r;
    int i, ops;
    r.data = data;
    r.size = size;
    r.at = 0;
    memset(&w, 0, sizeof w);
    w.n = int_in(&r, 1, MAX_PARTICLES);
    for (i = 0; i < w.n; ++i) {
        motus_vec2 x = vec2(&r);
        if (motus_particle_init(&w.particles[i], x, real(&r)) != MOTUS_OK) {
            memset(&w.particles[i], 0, sizeof w.particles[i]);
            w.particles[i].inverse_mass = 1;
        }
        w.particles[i].velocity = vec2(&r);
    }
    for (ops = 0; ops < MAX_OPERATIONS && more(&r); ++ops) {
        switch (byte(&r) % 8) {
        case 0:
        case 1:
        case 2: particle_operation(&w, &r); break;
        case 3: stepper_init_operation(&w, &r); break;
        case 4:
        case 5:
        case 6: stepper_step_operation(&w, &r); break;
        default: batch_operations(&r); break;
        }
    }
    /* Names, orders and scratch sizes for any value, in range or not. */
    {
        const int method = (int)(byte(&r) % 16) - 2, capacity = int_in(&r, -2, 1000);
        const int known = method >= 0 && method < MOTUS_METHOD_COUNT;
        REQUIRE((motus_method_name((motus_method)method) != NULL) == known, "motus_method_name");
        REQUIRE((motus_method_order((motus_method)method) >= 0) == known, "motus_method_order");
        REQUIRE((motus_stepper_scratch_size((motus_method)method, capacity) > 0) == (known && capacity > 0),
                "motus_stepper_scratch_size");
    }
    free(w.scratch);
    return 0;
}

#ifdef FUZZ_MOTUS_REPLAY
/* Runs each file named on the command line through the harness once: the corpus as a regression test. */
int main(int argc, char **argv) {
    int i;
    for (i = 1; i < argc; ++i) {
        FILE *file = fopen(argv[i], "rb");
        static uint8_t buffer[1 << 16];
        size_t size;
        if (!file) {
            fprintf(stderr, "fuzz_motus: cannot open %s\n", argv[i]);
            return 1;
        }
        size = fread(buffer, 1, sizeof buffer, file);
        fclose(file);
        LLVMFuzzerTestOneInput(buffer, size);
    }
    printf("fuzz_motus: %d inputs, no failure\n", argc - 1);
    return 0;
}
#endif

/* fuzz_motus.c - a libFuzzer harness for motus.h (v0.2, one engine): random bytes become a scene (every
   field, springs with bad indices, a force callback, substeps, every method, bounds with infinities, NaN
   and -0 sprinkled in), a state (2D or 3D; plain arrays, interleaved records or an array of motus_particle /
   motus_particle3 through motus_state_of_particles*; any stride within the allocation), scratch of any size
   and alignment and any dt (0, -0, subnormal, huge, NaN), and every engine entry point is called with them:
   motus_step, motus_step_range, motus_scene_check, motus_state_check, motus_scene_max_stable_dt, and the
   particle functions (motus_particle_* / motus_particle3_*).

   What it asserts, beyond "no crash, no sanitizer report" (ASan + UBSan in every fuzzing build):
   (1) a call that returns anything but MOTUS_OK writes nothing: every buffer it could reach (each state
       array, the scratch, the particles, with the guard bytes around each) is compared byte for byte.
       The documented exception: in release builds motus_step / motus_step_range returning
       MOTUS_ERROR_NOT_FINITE may have written the particles of its range (and the scratch);
   (2) MOTUS_OK from a step that ran (dt != 0, count > 0) leaves every position and velocity of its range
       finite; MOTUS_ERROR_NOT_FINITE in a release build means something was not finite, in the particles
       it read or in what it wrote;
   (3) motus_step_range writes nothing outside the position and velocity of [first, first + count);
       motus_step nothing outside them for [0, count) and its scratch (gaps of a stride, forces, inverse
       masses, guard bytes: never);
   (4) with MOTUS_CHECKED no result but MOTUS_OK writes a particle (an overflow may leave the scratch of a
       coupled step written: its dry run needs it).
   Plus: the callback is handed a sane query; a check's report names a field and a particle in its range.

   Built three ways (tests/CMakeLists.txt builds the replay; scripts/check-tools.sh fuzz builds the fuzzer):
   - clang -fsanitize=fuzzer,address,undefined: the fuzzer, run for a bounded time on tests/fuzz/corpus/;
   - with FUZZ_MOTUS_REPLAY: a main() that runs the files named on its command line once each (and says
     which methods and dimensions their steps reached), so the corpus is a regression test in every build;
   - float and double, release and MOTUS_CHECKED.
   FUZZ_MOTUS_PARTIAL_FORCES: also hand states whose force[] is NULL in some components only.
   FUZZ_MOTUS_TOLERATE_KNOWN: pass over the findings kept as corpus/regression-*, to fuzz past them: a step
   that returns MOTUS_ERROR_NOT_FINITE with finite data in and finite results out (the kernel's check sum
   x + v overflows); with MOTUS_CHECKED a step that wrote and returned NOT_FINITE on clean data (a coupled
   step's overflow); walls at -Inf for bounds_max or +Inf for bounds_min (not generated). */
#define MOTUS_IMPLEMENTATION
#define MOTUS_STATIC
/* Tasks of 4 particles and slabs from 8 particles, 2 cells wide: a scene of a few dozen particles reaches
   every path that scene.parallel_for runs (the defaults start at 2,048 and 4,096). */
#define MOTUS__TASK_MIN 4
#define MOTUS_CONTACT_SLAB_MIN_COUNT 8
#define MOTUS__SLAB_CELLS_2D 2
#define MOTUS__SLAB_CELLS_3D 2
#include "motus.h"

#include <float.h>
#include <limits.h>
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

#define MAX_PARTICLES 40 /* more than two AVX-512 vectors of float: whole and partial groups both run */
#define MAX_SPRINGS 10
#define MAX_OPERATIONS 24
#define MAX_BUFFERS 16

/* ---- failing: print what broke and abort, which libFuzzer reports with the input that did it ---- */
static const char *current_call = "";
static void fail(const char *what, int line) {
    fprintf(stderr, "fuzz_motus.c:%d: %s: %s\n", line, current_call, what);
    abort();
}
#define REQUIRE(condition)                                                                                  \
    do {                                                                                                    \
        if (!(condition)) fail("REQUIRE(" #condition ") failed", __LINE__);                                 \
    } while (0)

/* ---- the input: bytes read in order; past the end every read gives zero ---- */
typedef struct reader {
    const uint8_t *data;
    size_t size, at;
} reader;

static unsigned byte(reader *r) { return r->at < r->size ? r->data[r->at++] : 0u; }
static int more(const reader *r) { return r->at < r->size; }
/* An integer in [lo, hi] from one byte (spans up to 256). */
static int small(reader *r, int lo, int hi) { return lo + (int)(byte(r) % (unsigned)(hi - lo + 1)); }

/* A real: the values that break arithmetic (zeros, extremes, subnormals, NaN, infinities), small ordinary
   numbers, sometimes any bit pattern. */
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

/* Scene values: ordinary ones in range most of the time (so that the kernels run), any real() when wild. */
static motus_real value(reader *r, int wild, motus_real scale, int signed_value) {
    unsigned k;
    if (wild) return real(r);
    k = byte(r);
    if (k == 255) return real(r); /* a sprinkle of the odd values even in tame scenes */
    return (signed_value ? (motus_real)((int)k - 127) : (motus_real)k) * scale;
}
static motus_vec3 vec3_value(reader *r, int wild, motus_real scale) {
    motus_real x = value(r, wild, scale, 1), y = value(r, wild, scale, 1);
    return motus_v3(x, y, value(r, wild, scale, 1));
}

/* ---- guarded buffers: each malloc'd to guard + size + guard bytes, the guards a known pattern ---- */
typedef struct buffer {
    unsigned char *block;  /* guard, data, guard */
    unsigned char *before; /* the block as it was before the call under test */
    unsigned char *allowed; /* per data byte: 1 if the call under test may write it */
    size_t guard, bytes;
} buffer;

typedef struct buffers {
    buffer list[MAX_BUFFERS];
    int count;
} buffers;

static unsigned char *buffer_add(buffers *b, size_t bytes, size_t guard, unsigned fill) {
    buffer *x;
    size_t i;
    if (b->count == MAX_BUFFERS) abort();
    x = &b->list[b->count];
    x->guard = guard;
    x->bytes = bytes;
    x->block = (unsigned char *)malloc(bytes + 2 * guard + 1);
    x->before = (unsigned char *)malloc(bytes + 2 * guard + 1);
    x->allowed = (unsigned char *)malloc(bytes + 1);
    if (!x->block || !x->before || !x->allowed) abort();
    for (i = 0; i < bytes + 2 * guard; ++i) x->block[i] = (unsigned char)(0xA5u ^ (unsigned)i ^ fill);
    b->count++;
    return x->block + guard;
}
static void buffers_free(buffers *b) {
    int i;
    for (i = 0; i < b->count; ++i) {
        free(b->list[i].block);
        free(b->list[i].before);
        free(b->list[i].allowed);
    }
    b->count = 0;
}
/* Frees the buffers added since there were `count`. */
static void buffers_pop(buffers *b, int count) {
    while (b->count > count) {
        buffer *x = &b->list[--b->count];
        free(x->block);
        free(x->before);
        free(x->allowed);
    }
}
static void snapshot(buffers *b) {
    int i;
    for (i = 0; i < b->count; ++i) {
        memcpy(b->list[i].before, b->list[i].block, b->list[i].bytes + 2 * b->list[i].guard);
        memset(b->list[i].allowed, 0, b->list[i].bytes + 1);
    }
}
/* Marks [p, p + bytes) as writable; p must lie in one of the buffers. */
static void allow(buffers *b, const void *p, size_t bytes) {
    const uintptr_t at = (uintptr_t)p;
    int i;
    for (i = 0; i < b->count; ++i) {
        const uintptr_t start = (uintptr_t)(b->list[i].block + b->list[i].guard);
        if (at >= start && at + bytes <= start + b->list[i].bytes) {
            memset(b->list[i].allowed + (at - start), 1, bytes);
            return;
        }
    }
    fail("allow(): a pointer outside every buffer (harness bug)", __LINE__);
}
/* Every byte that changed since the snapshot was allowed; reports the first that was not. */
static void require_only_allowed(const buffers *b, const char *what, int line) {
    int i;
    size_t k;
    for (i = 0; i < b->count; ++i) {
        const buffer *x = &b->list[i];
        for (k = 0; k < x->bytes + 2 * x->guard; ++k) {
            int ok;
            if (x->before[k] == x->block[k]) continue;
            ok = k >= x->guard && k < x->guard + x->bytes && x->allowed[k - x->guard];
            if (!ok) {
                fprintf(stderr, "buffer %d (%zu bytes, guard %zu): byte %zu (%s) changed %02x -> %02x\n", i, x->bytes,
                        x->guard, k < x->guard ? k : k - x->guard,
                        k < x->guard ? "in the guard before" : k >= x->guard + x->bytes ? "past the end" : "data",
                        x->before[k], x->block[k]);
                fail(what, line);
            }
        }
    }
}

/* ---- the world one input builds ---- */
enum { LAYOUT_ARRAYS, LAYOUT_RECORDS, LAYOUT_PARTICLES, LAYOUT_COUNT };
enum { F_PX, F_PY, F_PZ, F_VX, F_VY, F_VZ, F_FX, F_FY, F_FZ, F_IM, F_COUNT };

typedef struct callback_model {
    int mode;
    motus_real value;
    int dims, count, evaluations, allowed, calls;
} callback_model;

typedef struct world {
    buffers memory;
    int dims, layout, n; /* n: particles allocated (the state's count never exceeds it) */
    motus_state state;   /* the full, valid shape; each call may hand a variant of it */
    motus_scene scene;
    motus_spring springs[MAX_SPRINGS];
    callback_model model;
    motus_particle *particles;   /* LAYOUT_PARTICLES, 2D */
    motus_particle3 *particles3; /* LAYOUT_PARTICLES, 3D */
    motus_particle *loose;       /* two particles for the particle functions when the layout has none */
    motus_particle3 *loose3;
    motus_real *radius;          /* per-particle radii at their own stride or the state's, when the state has them */
} world;

/* scene.parallel_for on the calling thread: the tasks from the last to the first, or in ranges of 1-3
   tasks in a shuffled order (motus's result may not depend on either). */
static void reverse_for(void *context, motus_task_function task, void *task_context, int task_count) {
    int t;
    (void)context;
    for (t = task_count - 1; t >= 0; --t) task(task_context, t, 1);
}
static void shuffled_for(void *context, motus_task_function task, void *task_context, int task_count) {
    uint32_t *seed = (uint32_t *)context;
    int first[MAX_PARTICLES + 1], count[MAX_PARTICLES + 1], ranges = 0, t = 0, k;
    while (t < task_count && ranges < MAX_PARTICLES) {
        *seed = *seed * 1664525u + 1013904223u;
        first[ranges] = t;
        count[ranges] = 1 + (int)((*seed >> 16) % 3);
        if (count[ranges] > task_count - t) count[ranges] = task_count - t;
        t += count[ranges++];
    }
    if (t < task_count) first[ranges] = t, count[ranges++] = task_count - t;
    for (k = ranges - 1; k > 0; --k) {
        int j, swap;
        *seed = *seed * 1664525u + 1013904223u;
        j = (int)((*seed >> 16) % (uint32_t)(k + 1));
        swap = first[k], first[k] = first[j], first[j] = swap;
        swap = count[k], count[k] = count[j], count[j] = swap;
    }
    for (k = 0; k < ranges; ++k) task(task_context, first[k], count[k]);
}
static uint32_t shuffle_seed = 1;

static void force_callback(void *user_data, const motus_force_query *q) {
    callback_model *m = (callback_model *)user_data;
    int i, d;
    REQUIRE(m->allowed); /* only motus_step calls it */
    REQUIRE(q->dimensions == m->dims && q->count == m->count);
    REQUIRE(q->stage >= 0 && q->stage < m->evaluations);
    REQUIRE(motus_real_is_finite(q->time) && q->time >= 0);
    for (d = 0; d < 3; ++d) {
        const int used = d < q->dimensions;
        REQUIRE((q->position[d] != NULL) == used && (q->velocity[d] != NULL) == used && (q->force[d] != NULL) == used);
    }
    for (d = 0; d < q->dimensions; ++d) /* they start at zero */
        for (i = 0; i < q->count; ++i) REQUIRE(q->force[d][i] == 0);
    m->calls++;
    for (i = 0; i < q->count; ++i)
        for (d = 0; d < q->dimensions; ++d) {
            switch (m->mode) {
            case 0: break; /* adds nothing */
            case 1: q->force[d][i] += m->value; break;
            case 2: q->force[d][i] -= q->position[d][i] * m->value; break;
            case 3: q->force[d][i] -= q->velocity[d][i] * m->value; break;
            case 4: if (i == q->count - 1 && d == 0) q->force[d][i] = (motus_real)NAN; break;
            default: q->force[d][i] += (q->stage & 1) ? REAL_MAX : -REAL_MAX; break;
            }
        }
}

static void read_scene(world *w, reader *r) {
    motus_scene *s = &w->scene;
    unsigned flags, k;
    int wild, i;
    memset(s, 0, sizeof *s);
    flags = byte(r);
    flags |= byte(r) << 8;
    wild = (flags >> 11) & 1;
    k = byte(r);
    s->method = (motus_method)(k >= 250 ? -1 : (int)(k % (MOTUS_METHOD_COUNT + 1))); /* sometimes not a method */
    k = byte(r);
    s->substeps = k < 200 ? (int)(k % 5) : k < 250 ? (int)k - 190 : k < 255 ? -1 : 1000;
    if (flags & 1) s->gravity = vec3_value(r, wild, MOTUS_R(0.25));
    if (flags & 2) s->linear_drag = value(r, wild, MOTUS_R(1.0) / 64, 0);
    if (flags & 4) s->quadratic_drag = value(r, wild, MOTUS_R(1.0) / 1024, 0);
    if (flags & 8) s->damping_per_step = value(r, wild, MOTUS_R(1.0) / 254, 0);
    if (flags & 16) s->damping_per_second = value(r, wild, MOTUS_R(1.0) / 254, 0);
    if (flags & 32) {
        s->attractor = vec3_value(r, wild, MOTUS_R(0.5));
        s->attractor_strength = value(r, wild, 4, 0);
    }
    if (flags & 64) {
        const motus_real lo[3] = {-value(r, wild, MOTUS_R(0.5), 0), -value(r, wild, MOTUS_R(0.5), 0),
                                  -value(r, wild, MOTUS_R(0.5), 0)};
        const motus_real hi[3] = {value(r, wild, MOTUS_R(0.5), 0), value(r, wild, MOTUS_R(0.5), 0),
                                  value(r, wild, MOTUS_R(0.5), 0)};
        unsigned infinite = byte(r); /* some walls away: +-Inf */
        s->bounds_min = motus_v3(infinite & 1 ? -(motus_real)HUGE_VAL : lo[0], infinite & 2 ? -(motus_real)HUGE_VAL : lo[1],
                                 infinite & 4 ? -(motus_real)HUGE_VAL : lo[2]);
        s->bounds_max = motus_v3(infinite & 8 ? (motus_real)HUGE_VAL : hi[0], infinite & 16 ? (motus_real)HUGE_VAL : hi[1],
                                 infinite & 32 ? (motus_real)HUGE_VAL : hi[2]);
    }
    if (flags & 128) s->restitution = value(r, wild, MOTUS_R(1.0) / 254, 0);
    if (flags & 256) s->mass = value(r, wild, MOTUS_R(1.0) / 16, 0);
    if (flags & 512) {
        s->spring_count = small(r, -1, MAX_SPRINGS);
        s->springs = byte(r) % 16 ? w->springs : NULL;
        for (i = 0; i < MAX_SPRINGS && i < s->spring_count; ++i) {
            motus_spring *p = &w->springs[i];
            k = byte(r);
            /* mostly valid ends; sometimes -1, -2, count, count + 1, or a == b */
            p->a = k < 224 ? (int)(k % (unsigned)w->n) : (int)(k % 4) - 2 + (int)(k & 1) * (w->n + 2);
            k = byte(r);
            p->b = k < 64 ? -1 : k < 224 ? (int)(k % (unsigned)w->n) : (int)(k % 4) - 3 + (int)(k & 1) * (w->n + 3);
            p->anchor = vec3_value(r, wild, MOTUS_R(0.25));
            p->rest_length = value(r, wild, MOTUS_R(1.0) / 16, 0);
            p->stiffness = value(r, wild, 2, 0);
            p->damping = value(r, wild, MOTUS_R(1.0) / 32, 0);
        }
    }
    if (flags & 1024) {
        w->model.mode = (int)(byte(r) % 6);
        w->model.value = value(r, wild, MOTUS_R(0.25), 1);
        s->force_callback = force_callback;
        s->user_data = &w->model;
    }
    if (flags & 8192) { /* contacts, and the walls become contacts; stepped by one of the runners */
        const unsigned k8 = byte(r);
        s->contacts.enabled = k8 % 8 != 0;
        s->parallel_for = (k8 / 8) % 3 == 0 ? NULL : (k8 / 8) % 3 == 1 ? reverse_for : shuffled_for;
        s->parallel_context = &shuffle_seed;
        s->contacts.radius = value(r, wild, MOTUS_R(1.0) / 64, 0);
        s->contacts.restitution = value(r, wild, MOTUS_R(1.0) / 254, 0);
        s->contacts.restitution_threshold = value(r, wild, MOTUS_R(1.0) / 64, 0);
        s->contacts.friction = value(r, wild, MOTUS_R(1.0) / 64, 0);
        s->contacts.iterations = small(r, -1, 6);
    }
    if (flags & 16384) { /* the tether */
        s->tether = vec3_value(r, wild, MOTUS_R(0.5));
        s->tether_stiffness = value(r, wild, 2, 0);
    }
    if (flags & 4096) { /* one field of the scene anything at all */
        motus_real x = real(r);
        switch (byte(r) % 14) {
        case 0: s->gravity.x = x; break;
        case 1: s->gravity.z = x; break;
        case 2: s->linear_drag = x; break;
        case 3: s->quadratic_drag = x; break;
        case 4: s->damping_per_step = x; break;
        case 5: s->damping_per_second = x; break;
        case 6: s->attractor.y = x; break;
        case 7: s->attractor_strength = x; break;
        case 8: s->bounds_min.z = x; break;
        case 9: s->bounds_max.x = x; break;
        case 10: s->restitution = x; break;
        case 12: s->tether.x = x; break;
        case 13: s->tether_stiffness = x; break;
        default: s->mass = x; break;
        }
    }
#ifdef FUZZ_MOTUS_TOLERATE_KNOWN
    if (s->bounds_max.x == -(motus_real)HUGE_VAL) s->bounds_max.x = (motus_real)HUGE_VAL;
    if (s->bounds_max.y == -(motus_real)HUGE_VAL) s->bounds_max.y = (motus_real)HUGE_VAL;
    if (s->bounds_max.z == -(motus_real)HUGE_VAL) s->bounds_max.z = (motus_real)HUGE_VAL;
    if (s->bounds_min.x == (motus_real)HUGE_VAL) s->bounds_min.x = -(motus_real)HUGE_VAL;
    if (s->bounds_min.y == (motus_real)HUGE_VAL) s->bounds_min.y = -(motus_real)HUGE_VAL;
    if (s->bounds_min.z == (motus_real)HUGE_VAL) s->bounds_min.z = -(motus_real)HUGE_VAL;
#endif
}

/* A particle value: ordinary mostly, any real() sometimes (NaN, Inf, -0, extremes). */
static motus_real particle_value(reader *r, int field) {
    const unsigned k = byte(r);
    if (k >= 224) return real(r);
    if (field == F_IM) return (motus_real)(k % 32) / 8; /* 0: immovable */
    return (motus_real)((int)k - 112) / 8;
}

static void build_state(world *w, reader *r) {
    const size_t guards[4] = {0, sizeof(motus_real), 64, 3 * sizeof(motus_real)};
    const size_t guard = guards[byte(r) % 4];
    const int fields = w->dims == 3 ? 10 : 7;
    /* the fields this dimension count uses, in the order of the enum */
    int used[F_COUNT], u = 0, f, i, d;
    motus_real *at[F_COUNT];
    ptrdiff_t stride = 1;
    memset(at, 0, sizeof at);
    for (f = 0; f < F_COUNT; ++f)
        if (w->dims == 3 || (f != F_PZ && f != F_VZ && f != F_FZ)) used[u++] = f;
    memset(&w->state, 0, sizeof w->state);
    if (w->layout == LAYOUT_PARTICLES) {
        if (w->dims == 2) {
            w->particles = (motus_particle *)(void *)buffer_add(&w->memory, (size_t)w->n * sizeof(motus_particle), guard, 1);
            w->state = motus_state_of_particles(w->particles, w->n);
            REQUIRE(w->state.dimensions == 2 && w->state.count == w->n && w->state.radius_stride == 1);
        } else {
            w->particles3 = (motus_particle3 *)(void *)buffer_add(&w->memory, (size_t)w->n * sizeof(motus_particle3), guard, 1);
            w->state = motus_state_of_particles3(w->particles3, w->n);
            REQUIRE(w->state.dimensions == 3 && w->state.count == w->n && w->state.radius_stride == 1);
        }
        stride = w->state.stride;
        at[F_PX] = w->state.position[0], at[F_PY] = w->state.position[1], at[F_PZ] = w->state.position[2];
        at[F_VX] = w->state.velocity[0], at[F_VY] = w->state.velocity[1], at[F_VZ] = w->state.velocity[2];
        at[F_FX] = (motus_real *)(uintptr_t)w->state.force[0], at[F_FY] = (motus_real *)(uintptr_t)w->state.force[1];
        at[F_FZ] = (motus_real *)(uintptr_t)w->state.force[2];
        at[F_IM] = (motus_real *)(uintptr_t)w->state.inverse_mass;
    } else if (w->layout == LAYOUT_RECORDS) {
        /* one record of `stride` reals per particle, the fields at distinct offsets (a rotation) */
        const int rotate = small(r, 0, 15);
        motus_real *base;
        stride = fields + small(r, 0, 3);
        base = (motus_real *)(void *)buffer_add(&w->memory, (size_t)w->n * (size_t)stride * sizeof(motus_real), guard, 2);
        for (i = 0; i < u; ++i) at[used[i]] = base + (i + rotate) % stride;
    } else {
        /* one array per field, every stride-th real of it, from an offset below the stride */
        stride = small(r, 0, 7) < 5 ? 1 : small(r, 2, 5);
        for (i = 0; i < u; ++i) {
            const int offset = small(r, 0, (int)stride - 1);
            motus_real *base = (motus_real *)(void *)buffer_add(
                &w->memory, ((size_t)(w->n - 1) * (size_t)stride + (size_t)offset + 1) * sizeof(motus_real), guard,
                (unsigned)(3 + i));
            at[used[i]] = base + offset;
        }
    }
    /* fill the data (gaps of a stride keep the guard pattern, which nothing may write) */
    for (i = 0; i < w->n; ++i)
        for (f = 0; f < u; ++f) at[used[f]][(ptrdiff_t)i * stride] = particle_value(r, used[f]);
    w->state.dimensions = w->dims;
    w->state.count = w->n;
    w->state.stride = stride == 1 && byte(r) % 2 ? 0 : (int)stride; /* 0 means 1 */
    for (d = 0; d < w->dims; ++d) {
        w->state.position[d] = at[F_PX + d];
        w->state.velocity[d] = at[F_VX + d];
        w->state.force[d] = at[F_FX + d];
    }
    w->state.inverse_mass = at[F_IM];
    switch (byte(r) % 8) { /* no accumulated forces, or no inverse masses (scene.mass for all) */
    case 0: memset((void *)w->state.force, 0, sizeof w->state.force); break;
    case 1: w->state.inverse_mass = NULL; break;
    case 2:
        memset((void *)w->state.force, 0, sizeof w->state.force);
        w->state.inverse_mass = NULL;
        break;
    default: break;
    }
    /* radii, mostly ordinary, sometimes anything; at the state's stride (radius_stride 0) or their own (1-3,
       as motus_state_of_particles's 1), picked from the byte that says whether there are radii (the bytes
       read are those of before radius_stride, so the corpus inputs keep their radii) */
    {
        motus_real values[MAX_PARTICLES];
        unsigned k;
        int pick;
        ptrdiff_t radius_stride;
        for (i = 0; i < w->n; ++i) {
            k = byte(r);
            values[i] = k >= 240 ? real(r) : (motus_real)(k % 64) / 32;
        }
        k = byte(r);
        pick = (int)(k / 3 % 4);
        radius_stride = pick == 0 ? stride : pick;
        w->radius = (motus_real *)(void *)buffer_add(
            &w->memory, ((size_t)(w->n - 1) * (size_t)radius_stride + 1) * sizeof(motus_real), guard, 10);
        for (i = 0; i < w->n; ++i) w->radius[(ptrdiff_t)i * radius_stride] = values[i];
        w->state.radius = k % 3 ? w->radius : NULL;
        w->state.radius_stride = pick;
    }
    /* two loose particles for the particle functions */
    if (!w->particles) w->loose = (motus_particle *)(void *)buffer_add(&w->memory, 2 * sizeof(motus_particle), guard, 7);
    if (!w->particles3)
        w->loose3 = (motus_particle3 *)(void *)buffer_add(&w->memory, 2 * sizeof(motus_particle3), guard, 8);
    if (w->loose)
        for (i = 0; i < 2; ++i) {
            w->loose[i].position = motus_v2(particle_value(r, F_PX), particle_value(r, F_PY));
            w->loose[i].velocity = motus_v2(particle_value(r, F_VX), particle_value(r, F_VY));
            w->loose[i].force = motus_v2(particle_value(r, F_FX), particle_value(r, F_FY));
            w->loose[i].inverse_mass = particle_value(r, F_IM);
        }
    if (w->loose3)
        for (i = 0; i < 2; ++i) {
            w->loose3[i].position = motus_v3(particle_value(r, F_PX), particle_value(r, F_PY), particle_value(r, F_PZ));
            w->loose3[i].velocity = motus_v3(particle_value(r, F_VX), particle_value(r, F_VY), particle_value(r, F_VZ));
            w->loose3[i].force = motus_v3(particle_value(r, F_FX), particle_value(r, F_FY), particle_value(r, F_FZ));
            w->loose3[i].inverse_mass = particle_value(r, F_IM);
        }
}

/* The state a call is handed: the world's, with a count of its own and, sometimes, a broken shape (which
   the call must refuse without reading a particle). */
static motus_state variant(world *w, reader *r) {
    motus_state s = w->state;
    const unsigned k = byte(r);
    s.count = k < 128 ? w->n : (int)(k % (unsigned)(w->n + 1));
    switch (byte(r) % 32) {
    case 0: s.dimensions = small(r, -1, 4); break; /* 1, 4, -1: invalid; 0 means 2 */
    case 1: s.count = -1 - small(r, 0, 1) * (INT_MAX - 1); break;
    case 2: s.stride = -small(r, 1, 2); break;
    case 9: s.radius_stride = -small(r, 1, 2); break;
    case 3: s.position[small(r, 0, s.dimensions == 3 ? 2 : 1)] = NULL; break;
    case 4: s.velocity[small(r, 0, s.dimensions == 3 ? 2 : 1)] = NULL; break;
    case 5: /* a position and a velocity array at one address: written twice */
        s.velocity[small(r, 0, s.dimensions == 3 ? 2 : 1)] = s.position[small(r, 0, s.dimensions == 3 ? 2 : 1)];
        break;
    case 6: if (s.dimensions == 3) s.position[2] = s.position[small(r, 0, 1)]; else s.velocity[1] = s.velocity[0]; break;
    case 7: /* 2D over a 3D state: z is left alone */
        if (w->dims == 3) s.dimensions = 2;
        break;
#ifdef FUZZ_MOTUS_PARTIAL_FORCES
    case 8: if (s.force[0]) s.force[small(r, 0, w->dims - 1)] = NULL; break;
#endif
    default: break;
    }
    return s;
}

static int state_dims(const motus_state *s) { return s->dimensions == 0 ? 2 : s->dimensions; }

/* Allows the position and velocity of [first, end) of s (whose shape is valid). */
static void allow_range(world *w, const motus_state *s, int first, int end) {
    const ptrdiff_t stride = s->stride == 0 ? 1 : s->stride;
    int i, d;
    for (i = first; i < end; ++i)
        for (d = 0; d < state_dims(s); ++d) {
            allow(&w->memory, s->position[d] + (ptrdiff_t)i * stride, sizeof(motus_real));
            allow(&w->memory, s->velocity[d] + (ptrdiff_t)i * stride, sizeof(motus_real));
        }
}
static int range_finite(const motus_state *s, int first, int end) {
    const ptrdiff_t stride = s->stride == 0 ? 1 : s->stride;
    int i, d;
    for (i = first; i < end; ++i)
        for (d = 0; d < state_dims(s); ++d)
            if (!motus_real_is_finite(s->position[d][(ptrdiff_t)i * stride]) ||
                !motus_real_is_finite(s->velocity[d][(ptrdiff_t)i * stride]))
                return 0;
    return 1;
}

static void check_string(motus_result result) {
    const char *text = motus_result_string(result);
    REQUIRE((unsigned)result < MOTUS_RESULT_COUNT);
    REQUIRE(text != NULL && text[0] != '\0');
}

static motus_real read_dt(reader *r) {
    const unsigned k = byte(r);
    if (k < 128) return (motus_real)k / 1024; /* 0 .. 1/8 s */
    if (k < 160) return (motus_real)(1.0 / 60.0);
    return real(r);
}

#ifdef FUZZ_MOTUS_REPLAY
static int verbose; /* FUZZ_MOTUS_VERBOSE set: each step says what it was given and returned */
#endif
/* Which methods and dimension counts a step reached with MOTUS_OK (the replay prints it). */
static unsigned long reached[MOTUS_METHOD_COUNT][2];

/* ---- the engine calls ---- */
#ifndef MOTUS_CHECKED
static int walls_on(const motus_scene *scene, int dims) {
    return scene->bounds_min.x != 0 || scene->bounds_min.y != 0 || scene->bounds_max.x != 0 || scene->bounds_max.y != 0 ||
           (dims == 3 && (scene->bounds_min.z != 0 || scene->bounds_max.z != 0));
}
/* Whether a particle of [first, end) has F*(1/m) past the largest real (or not finite): the release step
   rescues such a particle if it can and otherwise leaves it as it was, and returns NOT_FINITE (README, Bad
   input). 1/m is the state's, or the scene's uniform one. */
static int range_force_overflows(const motus_scene *scene, const motus_state *s, int first, int end) {
    const ptrdiff_t stride = s->stride == 0 ? 1 : s->stride;
    const motus_real uniform = scene->mass > 0 ? MOTUS_R(1.0) / scene->mass : MOTUS_R(1.0);
    int i, d;
    if (!s->force[0]) return 0;
    for (i = first; i < end; ++i) {
        const motus_real inverse_mass = s->inverse_mass ? s->inverse_mass[(ptrdiff_t)i * stride] : uniform;
        for (d = 0; d < state_dims(s); ++d)
            if (!motus_real_is_finite(s->force[d][(ptrdiff_t)i * stride] * inverse_mass)) return 1;
    }
    return 0;
}
/* Whether the scene has a term whose acceleration may pass the largest real at some stage of the step (the
   tether, quadratic drag, the attractor) without coupling: the release step rescues a particle whose step
   then is not finite if it can, and otherwise leaves it as it was and returns NOT_FINITE (README, Bad
   input). Which stage overflowed is not known from outside, hence the whole scene. */
static int term_may_overflow(const motus_scene *scene) {
    return (scene->tether_stiffness != 0 || scene->quadratic_drag != 0 || scene->attractor_strength != 0) &&
           scene->spring_count == 0 && !scene->force_callback;
}
#endif
static void step_operation(world *w, reader *r, int ranged) {
    motus_state s = variant(w, r);
    const motus_real dt = read_dt(r);
    const unsigned scratch_mode = byte(r), align = byte(r) % 8;
    int first = 0, count = 0, shape_ok, dims = state_dims(&s), end, precheck_ok = 0, range_ok, validated;
    motus_result result, precheck = MOTUS_OK, scene_result;
    unsigned char *scratch_block = NULL;
    void *scratch = NULL;
    size_t scratch_bytes = 0, needed;
    buffers *m = &w->memory;
    const int before_count = m->count;

    shape_ok = (dims == 2 || dims == 3) && s.count >= 0 && s.count <= w->n && s.stride >= 0 && s.radius_stride >= 0 &&
               motus_state_check(NULL, &s, 0, 0, NULL) == MOTUS_OK;
    if (ranged) {
        const unsigned k = byte(r);
        first = small(r, -1, w->n + 1);
        count = small(r, -1, w->n + 1);
        if (k < 160 && s.count > 0) { /* mostly a valid range */
            first = (int)((unsigned)first % (unsigned)(s.count + 1));
            count = (int)((unsigned)count % (unsigned)(s.count - first + 1));
        } else if (k >= 250 && first > 0) {
            count = INT_MAX; /* first + count overflows int */
        }
    } else {
        /* scratch: exactly what it needs, one byte short, more, none, misaligned */
        needed = motus_scratch_size(&w->scene, &s);
        REQUIRE(needed != (size_t)-1);
        scratch_bytes = scratch_mode < 160 ? needed : scratch_mode < 192 ? needed + (scratch_mode & 31) :
                        scratch_mode < 224 ? (needed > 0 ? needed - 1 - (scratch_mode & 7) % needed : 0) : 0;
        if (scratch_mode < 240 && scratch_bytes + align > 0) {
            scratch_block = buffer_add(m, scratch_bytes + align, (byte(r) & 1) ? 16 : 0, 9);
            scratch = scratch_block + align;
        }
    }
    if (shape_ok && s.count > 0) {
        int a = ranged ? first : 0, c = ranged ? count : s.count;
        if (a >= 0 && c >= 0 && a <= s.count && c <= s.count - a) {
            precheck = motus_state_check(&w->scene, &s, a, c, NULL);
            precheck_ok = 1;
        }
    }
    scene_result = shape_ok ? motus_scene_check(&w->scene, dims, s.count, NULL) : MOTUS_OK;
    snapshot(m);
    w->model.dims = dims;
    w->model.count = s.count;
    w->model.evaluations = motus_method_evaluations(w->scene.method);
    w->model.allowed = !ranged;
    if (ranged) {
        current_call = "motus_step_range";
        result = motus_step_range(&w->scene, &s, first, count, dt);
    } else {
        current_call = "motus_step";
        result = motus_step(&w->scene, &s, dt, scratch, scratch_bytes);
    }
    w->model.allowed = 0;
#ifdef FUZZ_MOTUS_REPLAY
    if (verbose)
        fprintf(stderr, "%s: result %d dims %d count %d stride %d first %d count %d dt %g method %d substeps %d springs %d callback %d scratch %zu shape_ok %d scene_result %d precheck %d\n",
                current_call, (int)result, dims, s.count, s.stride, first, count, (double)dt, (int)w->scene.method,
                w->scene.substeps, w->scene.spring_count, w->scene.force_callback != NULL, scratch_bytes, shape_ok,
                (int)scene_result, (int)precheck);
#endif
    check_string(result);
    if (!ranged) {
        first = 0;
        count = s.count;
    }
    range_ok = first >= 0 && count >= 0 && first <= s.count && count <= s.count - first;
    end = range_ok ? first + count : first;
    /* (1), (3), (4): what may have been written */
    validated = shape_ok && range_ok && motus__dt_valid(dt) && scene_result == MOTUS_OK;
    if (result == MOTUS_OK) REQUIRE(validated);
    if (validated && (result == MOTUS_OK || result == MOTUS_ERROR_NOT_FINITE || result == MOTUS_ERROR_OVERFLOW)) {
#ifdef MOTUS_CHECKED
        if (result == MOTUS_OK) allow_range(w, &s, first, end);
#ifdef FUZZ_MOTUS_TOLERATE_KNOWN
        if (result == MOTUS_ERROR_NOT_FINITE && precheck_ok && precheck == MOTUS_OK) allow_range(w, &s, first, end);
#endif
#else
        if (result != MOTUS_ERROR_OVERFLOW) allow_range(w, &s, first, end);
#endif
        if (scratch) allow(m, scratch, scratch_bytes);
    }
    require_only_allowed(m, result == MOTUS_OK ? "wrote outside its range, or a force, mass or gap"
                                               : "returned an error and wrote something it may not",
                         __LINE__);
    if (result == MOTUS_OK) {
        if (dt != 0 && count > 0) REQUIRE(range_finite(&s, first, end)); /* (2) */
        if (count > 0 && dt != 0) reached[w->scene.method][dims - 2]++;
    }
#ifdef FUZZ_MOTUS_TOLERATE_KNOWN
    /* the known finding: a finite result whose check sum x + v overflows */
    if (result == MOTUS_ERROR_NOT_FINITE && validated && precheck_ok && precheck == MOTUS_OK &&
        range_finite(&s, first, end))
        validated = 0;
#ifdef MOTUS_CHECKED
    if (result == MOTUS_ERROR_NOT_FINITE && validated && precheck_ok && precheck == MOTUS_OK) validated = 0;
#endif
#endif
    if (result == MOTUS_ERROR_NOT_FINITE && validated) {
#ifdef MOTUS_CHECKED
        /* nothing was written, so the data itself was bad */
        REQUIRE(precheck_ok && precheck == MOTUS_ERROR_NOT_FINITE);
#else
        /* (2) the particles read or the ones written hold a NaN or an Inf; or a step overflowed and the walls
           (bounds, or contact walls) clamped what it wrote back inside: the check is made before the walls; or
           a particle's F*(1/m), or a term's acceleration, passed the largest real and its step could not be
           rescued: it was left as it was (the state read here is the one after the step: such a particle
           still holds its force) */
        REQUIRE(precheck_ok && (precheck != MOTUS_OK || !range_finite(&s, first, end) || walls_on(&w->scene, dims) ||
                                range_force_overflows(&w->scene, &s, first, end) || term_may_overflow(&w->scene)));
#endif
    }
#ifdef MOTUS_CHECKED
    if (result == MOTUS_ERROR_INVALID_MASS && validated)
        REQUIRE(precheck_ok && precheck == MOTUS_ERROR_INVALID_MASS);
    if (result == MOTUS_OK && dt != 0 && count > 0 && precheck_ok) REQUIRE(precheck == MOTUS_OK);
#endif
    if (result == MOTUS_ERROR_UNSUPPORTED && ranged)
        REQUIRE(w->scene.spring_count > 0 || w->scene.force_callback || w->scene.contacts.enabled ||
                w->scene.method == MOTUS_EXACT_LINEAR_DRAG);
    /* a scene the check refuses is refused by the step with the same result */
    if (shape_ok && motus__dt_valid(dt) && scene_result != MOTUS_OK) REQUIRE(result == scene_result);
    buffers_pop(m, before_count);
}

/* motus_find_contacts: writes only its pairs (up to capacity) and the scratch; each pair a < b in range. */
static void find_contacts_operation(world *w, reader *r) {
    motus_state s = variant(w, r);
    motus_scene colliding = w->scene;
    const int capacity = small(r, -1, 64), use_pairs = byte(r) % 16 != 0, use_found = byte(r) % 16 != 0;
    const unsigned mode = byte(r);
    size_t needed, bytes;
    unsigned char *scratch = NULL;
    motus_contact_pair *pairs = NULL;
    int found = -7, i;
    motus_result result;
    const int before_count = w->memory.count;
    colliding.contacts.enabled = 1;
    needed = motus_scratch_size(&colliding, &s);
    bytes = mode < 200 ? needed : mode < 230 ? (needed > 0 ? needed - 1 : 0) : 0;
    if (needed != (size_t)-1 && bytes < ((size_t)1 << 26) && bytes > 0) scratch = buffer_add(&w->memory, bytes, 16, 11);
    if (use_pairs && capacity > 0)
        pairs = (motus_contact_pair *)(void *)buffer_add(&w->memory, (size_t)capacity * sizeof *pairs, 16, 12);
    snapshot(&w->memory);
    current_call = "motus_find_contacts";
    result = motus_find_contacts(&w->scene, &s, scratch, scratch ? bytes : 0, pairs, capacity, use_found ? &found : NULL);
    check_string(result);
    if (result == MOTUS_OK) {
        REQUIRE(found >= 0);
        if (scratch) allow(&w->memory, scratch, bytes);
        if (pairs) allow(&w->memory, pairs, (size_t)(found < capacity ? found : capacity) * sizeof *pairs);
        for (i = 0; pairs && i < found && i < capacity; ++i)
            REQUIRE(pairs[i].a >= 0 && pairs[i].a < pairs[i].b && pairs[i].b < s.count);
    } else {
        REQUIRE(found == -7);
        if (scratch) allow(&w->memory, scratch, bytes); /* scratch is the call's, even when it refuses */
    }
    require_only_allowed(&w->memory, "motus_find_contacts", __LINE__);
    buffers_pop(&w->memory, before_count);
}

static void check_operation(world *w, reader *r) {
    motus_state s = variant(w, r);
    motus_check_report report;
    const int which = (int)(byte(r) % 3), use_report = byte(r) % 8 != 0;
    int first = small(r, -1, w->n + 1), count = small(r, -1, w->n + 1), dims = small(r, -1, 4);
    motus_result result;
    memset(&report, 0x5A, sizeof report);
    snapshot(&w->memory);
    if (which == 0) {
        current_call = "motus_scene_check";
        result = motus_scene_check(byte(r) % 32 ? &w->scene : NULL, dims, count, use_report ? &report : NULL);
        if (use_report) {
            REQUIRE(report.field_name != NULL && report.field_name[0] != '\0');
            if (result == MOTUS_OK) REQUIRE(report.index == -1 && report.field == MOTUS_FIELD_NONE);
            if (report.index >= 0) REQUIRE(report.index < w->scene.spring_count);
        }
    } else {
        if (which == 1 && s.count > 0) { /* mostly a range in the state */
            first = (int)((unsigned)(first < 0 ? 0 : first) % (unsigned)(s.count + 1));
            count = s.count - first;
        }
        current_call = "motus_state_check";
        result = motus_state_check(&w->scene, &s, first, count, use_report ? &report : NULL);
        if (use_report) {
            REQUIRE(report.field_name != NULL && report.field_name[0] != '\0');
            if (result == MOTUS_OK) REQUIRE(report.index == -1 && report.field == MOTUS_FIELD_NONE);
            if (report.field != MOTUS_FIELD_NONE) {
                REQUIRE(result == MOTUS_ERROR_NOT_FINITE || result == MOTUS_ERROR_INVALID_MASS ||
                        (result == MOTUS_ERROR_INVALID_CONTACTS && report.field == MOTUS_FIELD_RADIUS));
                REQUIRE(report.index >= first && report.index < first + count);
                REQUIRE(strcmp(report.field_name, motus_field_name(report.field)) == 0);
                REQUIRE(report.component >= -1 && report.component < state_dims(&s));
            }
        }
    }
    check_string(result);
    require_only_allowed(&w->memory, "a check wrote", __LINE__);
}

static void max_stable_dt_operation(world *w, reader *r) {
    motus_state s = variant(w, r);
    const size_t needed = 2 * (size_t)(s.count > 0 ? s.count : 0) * sizeof(motus_real);
    const unsigned mode = byte(r);
    size_t bytes = mode < 192 ? needed : mode < 224 ? (needed > 0 ? needed - 1 : 0) : 0;
    const size_t align = byte(r) % 4 == 0 ? 1 : 0;
    const int before_count = w->memory.count;
    unsigned char *block = buffer_add(&w->memory, bytes + align + 1, 0, 10);
    motus_real max_dt = (motus_real)-7;
    motus_result result;
    snapshot(&w->memory);
    current_call = "motus_scene_max_stable_dt";
    result = motus_scene_max_stable_dt(&w->scene, &s, byte(r) % 32 ? &max_dt : NULL, block + align, bytes);
    check_string(result);
    /* scratch is the call's: an overflow of w^2 shows only once the springs' row sums are in it */
    if (result == MOTUS_OK || result == MOTUS_ERROR_OVERFLOW) allow(&w->memory, block + align, bytes);
    if (result == MOTUS_OK) REQUIRE(max_dt >= 0); /* +Inf when nothing limits; never NaN */
    else REQUIRE(max_dt == (motus_real)-7);
    require_only_allowed(&w->memory, "motus_scene_max_stable_dt", __LINE__);
    buffers_pop(&w->memory, before_count);
}

/* ---- the particle functions: all or nothing, always ---- */
#define PARTICLE_OPERATION(name, particle_t, vec_t, VEC, VEC_FINITE, FN)                                         \
    static void name(world *w, reader *r, particle_t *p, int avail) {                                          \
        const int op = (int)(byte(r) % 14);                                                                    \
        particle_t *target = byte(r) % 32 ? p : NULL;                                                           \
        vec_t carry = VEC(r), a = VEC(r), b = VEC(r);                                                            \
        const vec_t carry_before = carry;                                                                       \
        const motus_real x = real(r), y = read_dt(r);                                                           \
        motus_result result = MOTUS_OK;                                                                         \
        motus_check_report report;                                                                              \
        snapshot(&w->memory);                                                                                   \
        switch (op) {                                                                                           \
        case 0: current_call = #FN "init"; result = FN##init(target, a, x); break;                              \
        case 1: current_call = #FN "init_immovable"; result = FN##init_immovable(target, a); break;             \
        case 2: {                                                                                               \
            const motus_real m = FN##mass(target);                                                              \
            current_call = #FN "mass";                                                                          \
            if (!target) REQUIRE(m != m);                                                                       \
            else if (p->inverse_mass == 0) REQUIRE(m == (motus_real)HUGE_VAL);                                  \
            break;                                                                                              \
        }                                                                                                       \
        case 3: current_call = #FN "check"; result = FN##check(target); break;                                  \
        case 4: current_call = #FN "add_force"; result = FN##add_force(target, a); break;                       \
        case 5: current_call = #FN "clear_forces"; result = FN##clear_forces(target); break;                    \
        case 6: current_call = #FN "step"; result = FN##step(target, y); break;                                 \
        case 7: current_call = #FN "step_compensated";                                                          \
            result = FN##step_compensated(target, byte(r) % 32 ? &carry : NULL, y);                              \
            break;                                                                                              \
        case 8: current_call = #FN "damp_per_step"; result = FN##damp_per_step(target, x); break;               \
        case 9: current_call = #FN "damp_per_second"; result = FN##damp_per_second(target, x, y); break;        \
        case 10: current_call = #FN "bounce"; result = FN##bounce(target, a, b, x); break;                      \
        case 11: current_call = #FN "bounce (a box)";                                                          \
            result = FN##bounce(target, VEC_MIN(a, b), VEC_MAX(a, b), (motus_real)(byte(r) % 5) / 4);             \
            break;                                                                                              \
        case 12: current_call = "motus_particles*_check";                                                       \
            result = PARTICLES_CHECK(byte(r) % 32 ? p : NULL, small(r, -1, avail), &report);                     \
            if (result != MOTUS_OK && report.field != MOTUS_FIELD_NONE) REQUIRE(report.index >= 0 && report.index < avail); \
            break;                                                                                              \
        default: /* hand-filled data: NaN, negative masses, anything */                                         \
            if (target) {                                                                                       \
                p->position = a;                                                                                \
                if (byte(r) & 1) p->velocity = b;                                                               \
                if (byte(r) & 1) p->force = carry;                                                              \
                if (byte(r) & 1) p->inverse_mass = x;                                                           \
            }                                                                                                   \
            return;                                                                                             \
        }                                                                                                       \
        check_string(result);                                                                                   \
        if (!target && op != 2 && op != 12) REQUIRE(result == MOTUS_ERROR_NULL_POINTER);                        \
        if (result == MOTUS_OK && target && op != 2 && op != 3 && op != 12) allow(&w->memory, p, sizeof *p);    \
        require_only_allowed(&w->memory, result == MOTUS_OK ? "wrote outside its particle" : "an error wrote",  \
                             __LINE__);                                                                         \
        if (result != MOTUS_OK) REQUIRE(memcmp(&carry, &carry_before, sizeof carry) == 0);                      \
        if (result == MOTUS_OK && target) {                                                                     \
            if (op == 0) REQUIRE(p->inverse_mass > 0 && motus_real_is_finite(p->inverse_mass));                 \
            if (op == 1) REQUIRE(p->inverse_mass == 0);                                                         \
            if (op == 0 || op == 1) REQUIRE(motus_particle_check_any(p) == MOTUS_OK);                 \
            if (op == 6 || op == 7) REQUIRE(VEC_FINITE(p->position) && VEC_FINITE(p->velocity));                 \
            if (op == 7) REQUIRE(VEC_FINITE(carry));                                                            \
            if (op == 4) REQUIRE(VEC_FINITE(p->force));                                                         \
            if ((op == 10 || op == 11) && !KNOWN_WALLS(a, b))                                                     \
                REQUIRE(VEC_FINITE(p->position) && VEC_FINITE(p->velocity));                                   \
            if (op == 11) REQUIRE(INSIDE(p->position, VEC_MIN(a, b), VEC_MAX(a, b)));                            \
        }                                                                                                       \
    }

/* A wall at -Inf for a maximum or +Inf for a minimum (a known finding, tolerated with FUZZ_MOTUS_TOLERATE_KNOWN). */
#ifdef FUZZ_MOTUS_TOLERATE_KNOWN
static int wrong_infinity(motus_real x) { return !motus_real_is_finite(x) && x == x; }
#define KNOWN_WALLS(a, b) known_walls(&(a).x, &(b).x, (int)(sizeof(a) / sizeof(motus_real)))
static int known_walls(const motus_real *a, const motus_real *b, int n) {
    int k;
    for (k = 0; k < n; ++k)
        if (wrong_infinity(a[k]) || wrong_infinity(b[k])) return 1;
    return 0;
}
#else
#define KNOWN_WALLS(a, b) 0
#endif
static motus_real min_real(motus_real a, motus_real b) { return b < a ? b : a; }
static motus_real max_real(motus_real a, motus_real b) { return b > a ? b : a; }
static motus_vec2 read_vec2(reader *r) {
    motus_real x = real(r);
    return motus_v2(x, real(r));
}
static motus_vec3 read_vec3(reader *r) {
    motus_real x = real(r), y = real(r);
    return motus_v3(x, y, real(r));
}
static motus_vec2 min2(motus_vec2 a, motus_vec2 b) { return motus_v2(min_real(a.x, b.x), min_real(a.y, b.y)); }
static motus_vec2 max2(motus_vec2 a, motus_vec2 b) { return motus_v2(max_real(a.x, b.x), max_real(a.y, b.y)); }
static motus_vec3 min3(motus_vec3 a, motus_vec3 b) {
    return motus_v3(min_real(a.x, b.x), min_real(a.y, b.y), min_real(a.z, b.z));
}
static motus_vec3 max3(motus_vec3 a, motus_vec3 b) {
    return motus_v3(max_real(a.x, b.x), max_real(a.y, b.y), max_real(a.z, b.z));
}
static int inside2(motus_vec2 x, motus_vec2 lo, motus_vec2 hi) {
    return !(x.x < lo.x || x.x > hi.x || x.y < lo.y || x.y > hi.y);
}
static int inside3(motus_vec3 x, motus_vec3 lo, motus_vec3 hi) {
    return !(x.x < lo.x || x.x > hi.x || x.y < lo.y || x.y > hi.y || x.z < lo.z || x.z > hi.z);
}

#define VEC_MIN min2
#define VEC_MAX max2
#define INSIDE inside2
#define PARTICLES_CHECK motus_particles_check
#define motus_particle_check_any motus_particle_check
PARTICLE_OPERATION(particle_operation, motus_particle, motus_vec2, read_vec2, motus_vec2_is_finite, motus_particle_)
#undef VEC_MIN
#undef VEC_MAX
#undef INSIDE
#undef PARTICLES_CHECK
#undef motus_particle_check_any
#define VEC_MIN min3
#define VEC_MAX max3
#define INSIDE inside3
#define PARTICLES_CHECK motus_particles3_check
#define motus_particle_check_any motus_particle3_check
PARTICLE_OPERATION(particle3_operation, motus_particle3, motus_vec3, read_vec3, motus_vec3_is_finite, motus_particle3_)
#undef VEC_MIN
#undef VEC_MAX
#undef INSIDE
#undef PARTICLES_CHECK
#undef motus_particle_check_any

/* ---- the tables of methods and results, for any value ---- */
static void tables(reader *r) {
    const int method = small(r, -2, MOTUS_METHOD_COUNT + 1);
    const int known = method >= 0 && method < MOTUS_METHOD_COUNT;
    motus_real stiffness = real(r), mass = real(r), dt = read_dt(r), limit = real(r), safety = real(r), max_dt = -7;
    int substeps = -7;
    motus_result result;
    current_call = "motus_method_*";
    REQUIRE((motus_method_name((motus_method)method) != NULL) == known);
    REQUIRE((motus_method_order((motus_method)method) >= 0) == known);
    REQUIRE((motus_method_evaluations((motus_method)method) >= 0) == known);
    REQUIRE((motus_method_stability_limit((motus_method)method) >= 0) == known);
    if (known) REQUIRE(motus_method_evaluations((motus_method)method) <= MOTUS__MAX_EVALUATIONS);
    current_call = "motus_max_stable_dt";
    result = motus_max_stable_dt((motus_method)method, stiffness, mass, &max_dt);
    check_string(result);
    if (result == MOTUS_OK) REQUIRE(max_dt >= 0);
    else REQUIRE(max_dt == -7);
    current_call = "motus_substeps_for";
    result = motus_substeps_for(dt, limit, safety, &substeps);
    check_string(result);
    if (result == MOTUS_OK) REQUIRE(substeps >= 1 && substeps <= 1073741824);
    else REQUIRE(substeps == -7);
    REQUIRE(motus_result_string((motus_result)small(r, -1, MOTUS_RESULT_COUNT + 1)) != NULL);
}

/* ---- the entry point ---- */
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    static world w;
    reader r;
    int ops;
    r.data = data;
    r.size = size;
    r.at = 0;
    memset(&w, 0, sizeof w);
    w.dims = 2 + (int)(byte(&r) % 2);
    w.layout = (int)(byte(&r) % LAYOUT_COUNT);
    w.n = small(&r, 1, MAX_PARTICLES);
    build_state(&w, &r);
    read_scene(&w, &r);
    for (ops = 0; ops < MAX_OPERATIONS && more(&r); ++ops) {
        switch (byte(&r) % 11) {
        case 0:
        case 1:
        case 2: step_operation(&w, &r, 0); break;
        case 3:
        case 4: step_operation(&w, &r, 1); break;
        case 5: check_operation(&w, &r); break;
        case 6: max_stable_dt_operation(&w, &r); break;
        case 7: read_scene(&w, &r); break;
        case 8: {
            const unsigned k = byte(&r);
            const int i = (int)(k / 2 % (unsigned)w.n), j = (int)(k / 2 % 2u);
            if (k & 1) {
                if (w.particles) particle_operation(&w, &r, &w.particles[i], w.n - i);
                else particle_operation(&w, &r, &w.loose[j], 2 - j);
            } else {
                if (w.particles3) particle3_operation(&w, &r, &w.particles3[i], w.n - i);
                else particle3_operation(&w, &r, &w.loose3[j], 2 - j);
            }
            break;
        }
        case 9: tables(&r); break;
        default: find_contacts_operation(&w, &r); break;
        }
    }
    buffers_free(&w.memory);
    return 0;
}

#ifdef FUZZ_MOTUS_REPLAY
/* Runs each file named on the command line through the harness once: the corpus as a regression test. */
int main(int argc, char **argv) {
    int i, m, methods_2d = 0, methods_3d = 0;
    verbose = getenv("FUZZ_MOTUS_VERBOSE") != NULL;
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
    printf("fuzz_motus: %d inputs, no failure. Steps that ran with MOTUS_OK, per method (2D/3D):\n", argc - 1);
    for (m = 0; m < MOTUS_METHOD_COUNT; ++m) {
        printf("  %-20s %6lu %6lu\n", motus_method_name((motus_method)m), reached[m][0], reached[m][1]);
        methods_2d += reached[m][0] > 0;
        methods_3d += reached[m][1] > 0;
    }
    printf("fuzz_motus: %d/%d methods reached in 2D, %d/%d in 3D\n", methods_2d, MOTUS_METHOD_COUNT, methods_3d,
           MOTUS_METHOD_COUNT);
    return 0;
}
#endif

/* The fixed-step clock: steps per frame, the cap and what it drops, alpha, bad frame times, and motion that
   does not depend on the frame rate. Built in float and in double (MOTUS_DOUBLE). */
#include "motus.h"
#include "support/motus_test.h"

#include <float.h>

#ifdef MOTUS_DOUBLE
#define REAL_MAX DBL_MAX
#define REAL_TRUE_MIN 4.9406564584124654e-324
#else
#define REAL_MAX FLT_MAX
#define REAL_TRUE_MIN 1.40129846e-45f
#endif

static const motus_real DT = (motus_real)(1.0 / 60.0);

static motus_real not_a_number(void) { return (motus_real)NAN; }
static motus_real infinity(void) { return (motus_real)HUGE_VAL; }

/* Field by field: struct copies need not copy padding. */
static int same_clock(const motus_clock *a, const motus_clock *b) {
    return memcmp(&a->fixed_dt, &b->fixed_dt, sizeof a->fixed_dt) == 0 &&
           a->max_steps_per_frame == b->max_steps_per_frame && a->accumulator == b->accumulator &&
           a->steps_total == b->steps_total && a->steps_dropped_last_frame == b->steps_dropped_last_frame &&
           a->steps_dropped_total == b->steps_dropped_total &&
           memcmp(&a->time_dropped_last_frame, &b->time_dropped_last_frame, sizeof a->time_dropped_last_frame) == 0 &&
           memcmp(&a->time_dropped_total, &b->time_dropped_total, sizeof a->time_dropped_total) == 0;
}
#define ENSURE_CLOCK_UNCHANGED(clock, before) ENSURE(same_clock(&(clock), &(before)))

static motus_clock make_clock(motus_real dt, int max_steps) {
    motus_clock clock;
    ENSURE_EQ_INT(motus_clock_init(&clock, dt, max_steps), MOTUS_OK);
    return clock;
}

TEST(init_sets_fields_and_default_cap) {
    motus_clock clock = make_clock(DT, 0);
    ENSURE(clock.fixed_dt == DT);
    ENSURE_EQ_INT(clock.max_steps_per_frame, MOTUS_CLOCK_DEFAULT_MAX_STEPS);
    ENSURE_EQ_INT(MOTUS_CLOCK_DEFAULT_MAX_STEPS, 8);
    ENSURE(clock.accumulator == 0 && clock.steps_total == 0 && clock.steps_dropped_total == 0);
    ENSURE(clock.time_dropped_last_frame == 0 && clock.time_dropped_total == 0);
    ENSURE(motus_clock_alpha(&clock) == 0);
    ENSURE(motus_clock_time(&clock) == 0);
    clock = make_clock(DT, 3);
    ENSURE_EQ_INT(clock.max_steps_per_frame, 3);
}

TEST(init_rejects_bad_input) {
    const motus_real bad_dt[] = {0, -DT, not_a_number(), infinity(), -infinity()};
    motus_clock clock = make_clock(DT, 5), before = clock;
    int i;
    for (i = 0; i < 5; ++i) ENSURE_EQ_INT(motus_clock_init(&clock, bad_dt[i], 5), MOTUS_ERROR_INVALID_TIME_STEP);
    ENSURE_EQ_INT(motus_clock_init(&clock, DT, -1), MOTUS_ERROR_INVALID_CLOCK);
    ENSURE_CLOCK_UNCHANGED(clock, before);
    ENSURE_EQ_INT(motus_clock_init(NULL, DT, 5), MOTUS_ERROR_NULL_POINTER);
}

TEST(frames_of_dt_step_once_each_for_a_long_run) {
    /* A million frames of exactly dt: one step each, never zero or two, alpha always 0. */
    motus_clock clock = make_clock(DT, 0);
    int steps = 0, wrong = 0;
    long frame;
    for (frame = 0; frame < 1000000; ++frame) {
        ENSURE_EQ_INT(motus_clock_advance(&clock, DT, &steps), MOTUS_OK);
        wrong += steps != 1 || clock.accumulator != 0;
    }
    ENSURE_EQ_INT(wrong, 0);
    ENSURE(clock.steps_total == 1000000);
    ENSURE(motus_clock_alpha(&clock) == 0);
    ENSURE(clock.steps_dropped_total == 0 && clock.time_dropped_total == 0);
    /* Two dt a frame (30 Hz frames, 60 Hz steps): two steps each. */
    clock = make_clock(DT, 0);
    for (frame = 0, wrong = 0; frame < 100000; ++frame) {
        motus_clock_advance(&clock, 2 * DT, &steps);
        wrong += steps != 2;
    }
    ENSURE_EQ_INT(wrong, 0);
}

/* frames of frame_seconds: every frame runs [lo, hi] steps, nothing is dropped, and the steps run plus
   alpha add up to the time given. */
static void check_frames(motus_real frame_seconds, int frames, int lo, int hi) {
    motus_clock clock = make_clock(DT, 0);
    int frame, steps, out_of_range = 0;
    double expected_steps = (double)frames * (double)frame_seconds / (double)DT;
    for (frame = 0; frame < frames; ++frame) {
        ENSURE_EQ_INT(motus_clock_advance(&clock, frame_seconds, &steps), MOTUS_OK);
        out_of_range += steps < lo || steps > hi;
    }
    ENSURE_EQ_INT(out_of_range, 0);
    ENSURE(clock.steps_dropped_total == 0 && clock.time_dropped_total == 0);
    /* One rounding to 2^-32 of a step per frame, plus alpha's rounding to motus_real. */
    ENSURE_NEAR((double)clock.steps_total + (double)motus_clock_alpha(&clock), expected_steps,
                (double)frames * 2.4e-10 + 2 * (double)MOTUS_REAL_EPSILON);
    ENSURE(motus_clock_alpha(&clock) >= 0 && motus_clock_alpha(&clock) < 1);
}

TEST(frames_of_1ms_and_100ms) {
    check_frames(MOTUS_R(0.001), 60000, 0, 1); /* a minute at 1000 frames a second: a step every ~17 */
    check_frames(MOTUS_R(0.1), 600, 5, 7);     /* a minute at 10: six steps a frame (5 or 7 by rounding) */
}

TEST(hitch_of_2s_is_capped_and_reported) {
    /* A particle pushed with 100 N, stepped through the clock at 60 Hz, then a 2 s frame. It must move by
       8 steps (the cap), not 120, and not by one 2 s step, which throws it 50x further than a frame's
       motion. The clock says it dropped 112 steps, 1.87 s; the next frame is normal again. */
    motus_clock clock = make_clock(DT, 0);
    motus_particle p, q, launched;
    int frame, steps, i;
    motus_particle_init(&p, motus_v2(400, 300), 2);
    motus_particle_add_force(&p, motus_v2(100, 0));
    q = p;
    for (frame = 0; frame < 10; ++frame) {
        ENSURE_EQ_INT(motus_clock_advance(&clock, DT, &steps), MOTUS_OK);
        for (i = 0; i < steps; ++i) motus_particle_step(&p, clock.fixed_dt);
    }
    launched = p;
    ENSURE_EQ_INT(motus_particle_step(&launched, 2), MOTUS_OK);
    ENSURE_EQ_INT(motus_clock_advance(&clock, 2, &steps), MOTUS_OK);
    ENSURE_EQ_INT(steps, 8);
    for (i = 0; i < steps; ++i) motus_particle_step(&p, clock.fixed_dt);
    /* 2 s is 120 steps; in float 2/(1/60) is 119.99999, so 111 steps are dropped and the leftover is
       ~1 step: dropped + run + alpha is 120 either way. */
    ENSURE(clock.steps_dropped_last_frame == 112 || clock.steps_dropped_last_frame == 111);
    ENSURE(clock.steps_dropped_total == clock.steps_dropped_last_frame);
    ENSURE_NEAR((double)clock.steps_dropped_last_frame + 8 + (double)motus_clock_alpha(&clock), 112 + 8, 1e-5);
    ENSURE_NEAR(clock.time_dropped_last_frame, (double)clock.steps_dropped_last_frame * (double)DT, 1e-5);
    ENSURE(clock.time_dropped_total == (double)clock.time_dropped_last_frame);
    ENSURE(clock.steps_total == 18);
    /* The same 18 steps without a clock land exactly there. */
    for (i = 0; i < 18; ++i) motus_particle_step(&q, DT);
    ENSURE(memcmp(&p, &q, sizeof p) == 0);
    ENSURE(launched.position.x - 400 > 50 * (p.position.x - 400));
    ENSURE_EQ_INT(motus_clock_advance(&clock, DT, &steps), MOTUS_OK);
    ENSURE(steps == 1 || steps == 2); /* 2 when the hitch left ~1 step over */
    ENSURE(clock.steps_dropped_last_frame == 0 && clock.time_dropped_last_frame == 0);
    ENSURE(clock.steps_dropped_total >= 111);
    /* A smaller cap drops more; the fraction of a step left over is kept (alpha stays smooth). */
    clock = make_clock(DT, 2);
    ENSURE_EQ_INT(motus_clock_advance(&clock, DT * MOTUS_R(5.5), &steps), MOTUS_OK);
    ENSURE_EQ_INT(steps, 2);
    ENSURE(clock.steps_dropped_last_frame == 3);
    ENSURE_NEAR(motus_clock_alpha(&clock), 0.5, 1e-5);
}

TEST(huge_frames_and_tiny_steps) {
    /* Frames of billions of steps take the other path: the cap, no overflow, the dropped time ~ the frame. */
    motus_clock clock = make_clock(DT, 0), tiny = make_clock(REAL_TRUE_MIN, 4);
    int steps;
    ENSURE_EQ_INT(motus_clock_advance(&clock, REAL_MAX, &steps), MOTUS_OK);
    ENSURE_EQ_INT(steps, 8);
    ENSURE(clock.steps_dropped_last_frame > 1000000000u);
    ENSURE_NEAR(clock.time_dropped_last_frame / REAL_MAX, 1, 1e-6);
    ENSURE_EQ_INT(motus_clock_advance(&clock, MOTUS_R(1e9), &steps), MOTUS_OK); /* 6e10 steps */
    ENSURE_EQ_INT(steps, 8);
    ENSURE_NEAR(clock.time_dropped_last_frame, 1e9, 1e9 * 1e-6);
    ENSURE_EQ_INT(motus_clock_advance(&tiny, 1, &steps), MOTUS_OK);
    ENSURE_EQ_INT(steps, 4);
    ENSURE_NEAR(tiny.time_dropped_last_frame, 1, 1e-6);
    ENSURE(motus_clock_alpha(&tiny) >= 0 && motus_clock_alpha(&tiny) < 1);
}

TEST(dropped_steps_saturate_instead_of_wrapping) {
    /* steps_dropped_total near UINT64_MAX by hand, then a hitch: it stops at UINT64_MAX (never wraps to a
       small count), and the next hitch leaves it there. steps_total likewise. */
    motus_clock clock = make_clock(DT, 0);
    int steps;
    clock.steps_dropped_total = UINT64_MAX - 5;
    ENSURE_EQ_INT(motus_clock_advance(&clock, 2, &steps), MOTUS_OK); /* ~112 dropped */
    ENSURE_EQ_INT(steps, 8);
    ENSURE(clock.steps_dropped_last_frame >= 111);
    ENSURE(clock.steps_dropped_total == UINT64_MAX);
    ENSURE_EQ_INT(motus_clock_advance(&clock, 2, &steps), MOTUS_OK);
    ENSURE(clock.steps_dropped_total == UINT64_MAX);
    ENSURE_EQ_INT(motus_clock_advance(&clock, REAL_MAX, &steps), MOTUS_OK); /* the huge-frame path */
    ENSURE(clock.steps_dropped_total == UINT64_MAX);
    /* Exactly reaching the maximum is not a wrap either. */
    clock = make_clock(DT, 2);
    clock.steps_dropped_total = UINT64_MAX - 3;
    ENSURE_EQ_INT(motus_clock_advance(&clock, DT * MOTUS_R(5.5), &steps), MOTUS_OK); /* 3 dropped */
    ENSURE(clock.steps_dropped_last_frame == 3);
    ENSURE(clock.steps_dropped_total == UINT64_MAX);
    /* The steps run saturate the same way. */
    clock = make_clock(DT, 0);
    clock.steps_total = UINT64_MAX - 1;
    ENSURE_EQ_INT(motus_clock_advance(&clock, 3 * DT, &steps), MOTUS_OK);
    ENSURE_EQ_INT(steps, 3);
    ENSURE(clock.steps_total == UINT64_MAX);
}

TEST(frame_of_zero_runs_nothing) {
    motus_clock clock = make_clock(DT, 0), before;
    int steps = 99;
    motus_clock_advance(&clock, DT * MOTUS_R(0.25), &steps);
    before = clock;
    ENSURE_EQ_INT(motus_clock_advance(&clock, 0, &steps), MOTUS_OK);
    ENSURE_EQ_INT(steps, 0);
    ENSURE_CLOCK_UNCHANGED(clock, before);
    ENSURE_EQ_INT(motus_clock_advance(&clock, -MOTUS_R(0.0), &steps), MOTUS_OK); /* -0 is 0 */
    ENSURE_CLOCK_UNCHANGED(clock, before);
}

TEST(bad_frame_times_are_rejected_and_change_nothing) {
    const motus_real bad[] = {-DT, -REAL_TRUE_MIN, -REAL_MAX, not_a_number(), -not_a_number(), infinity(), -infinity()};
    motus_clock clock = make_clock(DT, 0), before;
    int i, steps;
    motus_clock_advance(&clock, DT * MOTUS_R(2.5), &steps); /* something in every field */
    motus_clock_advance(&clock, 1, &steps);
    before = clock;
    for (i = 0; i < (int)(sizeof bad / sizeof bad[0]); ++i) {
        steps = 99;
        ENSURE_EQ_INT(motus_clock_advance(&clock, bad[i], &steps), MOTUS_ERROR_INVALID_FRAME_TIME);
        ENSURE_EQ_INT(steps, 0); /* a loop that ignores the result runs nothing */
    }
    ENSURE_CLOCK_UNCHANGED(clock, before);
    ENSURE_EQ_INT(motus_clock_advance(NULL, DT, &steps), MOTUS_ERROR_NULL_POINTER);
    ENSURE_EQ_INT(motus_clock_advance(&clock, DT, NULL), MOTUS_ERROR_NULL_POINTER);
    ENSURE_CLOCK_UNCHANGED(clock, before);
    ENSURE(strcmp(motus_result_string(MOTUS_ERROR_INVALID_FRAME_TIME), motus_result_string(MOTUS_ERROR_INVALID_TIME_STEP)) != 0);
    /* A clock that was never initialised (zeroed) or got corrupted is refused, not divided by zero. */
    memset(&clock, 0, sizeof clock);
    ENSURE_EQ_INT(motus_clock_advance(&clock, DT, &steps), MOTUS_ERROR_INVALID_CLOCK);
    ENSURE(motus_clock_alpha(NULL) == 0 && motus_clock_time(NULL) == 0);
}

TEST(alpha_stays_below_one) {
    motus_clock clock = make_clock(DT, 0);
    int steps;
    clock.accumulator = 0xFFFFFFFFu; /* one tick short of a step */
    ENSURE(motus_clock_alpha(&clock) < 1);
    ENSURE(motus_clock_alpha(&clock) > MOTUS_R(0.999));
    ENSURE_EQ_INT(motus_clock_advance(&clock, 0, &steps), MOTUS_OK);
    ENSURE_EQ_INT(steps, 0);
    clock = make_clock(DT, 0);
    motus_clock_advance(&clock, DT * MOTUS_R(0.25), &steps);
    ENSURE_NEAR(motus_clock_alpha(&clock), 0.25, 1e-6);
    motus_clock_advance(&clock, DT * MOTUS_R(0.5), &steps);
    ENSURE_EQ_INT(steps, 0);
    ENSURE_NEAR(motus_clock_alpha(&clock), 0.75, 1e-6);
    motus_clock_advance(&clock, DT * MOTUS_R(0.5), &steps);
    ENSURE_EQ_INT(steps, 1);
    ENSURE_NEAR(motus_clock_alpha(&clock), 0.25, 1e-6);
}

TEST(vec2_lerp) {
    motus_vec2 a = motus_v2(2, -4), b = motus_v2(6, 8);
    motus_vec3 c = motus_v3(2, -4, 1), e = motus_v3(6, 8, -3);
    ENSURE(motus_vec2_lerp(a, b, 0).x == 2 && motus_vec2_lerp(a, b, 0).y == -4);
    ENSURE(motus_vec2_lerp(a, b, 1).x == 6 && motus_vec2_lerp(a, b, 1).y == 8);
    ENSURE(motus_vec2_lerp(a, b, MOTUS_R(0.25)).x == 3 && motus_vec2_lerp(a, b, MOTUS_R(0.25)).y == -1);
    ENSURE(motus_vec3_lerp(c, e, MOTUS_R(0.25)).z == 0 && motus_vec3_lerp(c, e, 0).z == 1);
}

/* The reference program's particle (mass 2, 100 N per held key, 0.99 per frame at 60 Hz turned into a
   fraction removed per second) stepped through a clock with frames of 1/rate s until `total_steps` steps ran. The
   keys are a function of the simulated time (D for the first second, then S and A), as a replay would
   feed them. Returns the frames it took. */
static int run_wsad(int rate, int total_steps, motus_particle *out, motus_clock *clock_out) {
    /* 0.01 removed per step at 60 Hz, as a fraction removed per second: 1 - 0.99^60. */
    const motus_real damping = (motus_real)(1 - pow(0.99, 60));
    const motus_real frame_seconds = MOTUS_R(1.0) / (motus_real)rate;
    motus_clock clock = make_clock(DT, 0);
    motus_particle p;
    int frames = 0, steps, i;
    motus_particle_init(&p, motus_v2(400, 300), 2);
    while (clock.steps_total < (uint64_t)total_steps && frames < 100 * total_steps) {
        ENSURE_EQ_INT(motus_clock_advance(&clock, frame_seconds, &steps), MOTUS_OK);
        ++frames;
        for (i = 0; i < steps; ++i) {
            const uint64_t step = clock.steps_total - (uint64_t)steps + (uint64_t)i; /* index of this step */
            motus_particle_clear_forces(&p);
            if (step < 60) motus_particle_add_force(&p, motus_v2(100, 0));
            else if (step < 90) motus_particle_add_force(&p, motus_v2(0, 100));
            else if (step < 150) motus_particle_add_force(&p, motus_v2(-100, 0));
            ENSURE_EQ_INT(motus_particle_step(&p, clock.fixed_dt), MOTUS_OK);
            ENSURE_EQ_INT(motus_particle_damp_per_second(&p, damping, clock.fixed_dt), MOTUS_OK);
        }
    }
    *out = p;
    *clock_out = clock;
    return frames;
}

TEST(motion_does_not_depend_on_frame_rate) {
    /* 4 s at 30, 60 and 144 frames a second end in the same state bit for bit, at the same simulated time:
       the clock only changes how many fixed steps run per frame. */
    static const int rates[3] = {30, 60, 144};
    motus_particle p[3];
    motus_clock clock[3];
    int r, frames;
    for (r = 0; r < 3; ++r) {
        frames = run_wsad(rates[r], 240, &p[r], &clock[r]);
        ENSURE(clock[r].steps_total == 240); /* 30 Hz: 2 a frame, 60: 1, 144: 0 or 1, so no overshoot */
        ENSURE(frames >= 4 * rates[r] - 1 && frames <= 4 * rates[r] + 1);
        ENSURE(clock[r].steps_dropped_total == 0);
    }
    for (r = 1; r < 3; ++r) {
        ENSURE(memcmp(&p[r], &p[0], sizeof p[0]) == 0);
        ENSURE(motus_clock_time(&clock[r]) == motus_clock_time(&clock[0]));
    }
    ENSURE(p[0].position.x > 400 && p[0].position.y > 300); /* it did move */
    ENSURE(p[0].velocity.x != 0);
}

static const motus_test_case TESTS[] = {
    TEST_CASE(init_sets_fields_and_default_cap),
    TEST_CASE(init_rejects_bad_input),
    TEST_CASE(frames_of_dt_step_once_each_for_a_long_run),
    TEST_CASE(frames_of_1ms_and_100ms),
    TEST_CASE(hitch_of_2s_is_capped_and_reported),
    TEST_CASE(huge_frames_and_tiny_steps),
    TEST_CASE(dropped_steps_saturate_instead_of_wrapping),
    TEST_CASE(frame_of_zero_runs_nothing),
    TEST_CASE(bad_frame_times_are_rejected_and_change_nothing),
    TEST_CASE(alpha_stays_below_one),
    TEST_CASE(vec2_lerp),
    TEST_CASE(motion_does_not_depend_on_frame_rate),
};

int main(int argc, char **argv) { return motus_test_main(argc, argv, TESTS, TEST_COUNT(TESTS)); }

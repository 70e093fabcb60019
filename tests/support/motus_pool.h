/* motus_pool.h - a small thread pool for scene.parallel_for (POSIX threads; GCC and Clang), used by the
   tests and the benchmarks, and an example of what a game's own job system has to do for motus:

       motus_pool pool;
       motus_pool_start(&pool, 2);            // the calling thread + 1 worker
       scene.parallel_for = motus_pool_for;
       scene.parallel_context = &pool;
       ... motus_step(&scene, &state, dt, scratch, bytes) ...
       motus_pool_stop(&pool);

   motus_pool_for splits motus's tasks into one contiguous range per thread (the calling thread runs the
   first) and returns when all have run. motus's result does not depend on which thread ran which task.
   Workers spin a little while waiting for the next call (a step makes a few dozen calls, microseconds
   apart), then sleep on a condition variable, so an idle pool costs no CPU.

   Define MOTUS_POOL_IMPLEMENTATION in one file that includes it. */
#ifndef MOTUS_POOL_H
#define MOTUS_POOL_H

#include <pthread.h>

#ifndef MOTUS_POOL_MAX_THREADS
#define MOTUS_POOL_MAX_THREADS 16
#endif

typedef struct motus_pool_slot {
    struct motus_pool *pool;
    int index;
} motus_pool_slot;
typedef struct motus_pool {
    int threads; /* the calling thread included */
    pthread_t worker[MOTUS_POOL_MAX_THREADS];
    motus_pool_slot slot[MOTUS_POOL_MAX_THREADS];
    pthread_mutex_t lock;
    pthread_cond_t wake;
    /* the call in progress */
    void (*task)(void *task_context, int first, int count);
    void *task_context;
    int task_count;
    int done;       /* workers finished with the call */
    int generation; /* raised by each call */
    int quit;
} motus_pool;

#ifdef __cplusplus
extern "C" {
#endif
/* threads: 1 (the caller alone) to MOTUS_POOL_MAX_THREADS. Returns 0 on success. */
int motus_pool_start(motus_pool *pool, int threads);
void motus_pool_stop(motus_pool *pool);
/* The motus_parallel_for of scene.parallel_for; parallel_context is the pool. */
void motus_pool_for(void *parallel_context, void (*task)(void *task_context, int first, int count),
                    void *task_context, int task_count);
#ifdef __cplusplus
}
#endif

#endif

#ifdef MOTUS_POOL_IMPLEMENTATION
#include <sched.h>

/* Each call splits the tasks into as many contiguous ranges as there are threads, the same way every time,
   so that a thread keeps the same particles and finds them in its own cache (on this 2-core machine,
   taking tasks one at a time from a shared counter made 2 threads 1.27x one at 10^4 balls, against 1.6x
   with fixed halves). Each worker runs its range of every call once (the caller waits for all of them),
   so the generation alone tells it a new call has come. */
static void motus_pool__range(const motus_pool *pool, int index, int *first, int *count) {
    const int n = pool->task_count, threads = pool->threads;
    *first = (int)((long long)n * index / threads);
    *count = (int)((long long)n * (index + 1) / threads) - *first;
}

static void *motus_pool__worker(void *argument) {
    const motus_pool_slot *slot = (const motus_pool_slot *)argument;
    motus_pool *pool = slot->pool;
    int seen = 0;
    for (;;) {
        int spins = 0, first, count;
        void (*task)(void *, int, int);
        void *context;
        while (__atomic_load_n(&pool->generation, __ATOMIC_ACQUIRE) == seen &&
               !__atomic_load_n(&pool->quit, __ATOMIC_ACQUIRE) && ++spins < (1 << 20)) {
        }
        pthread_mutex_lock(&pool->lock);
        while (pool->generation == seen && !pool->quit) pthread_cond_wait(&pool->wake, &pool->lock);
        if (pool->quit) {
            pthread_mutex_unlock(&pool->lock);
            return NULL;
        }
        seen = pool->generation;
        task = pool->task, context = pool->task_context;
        motus_pool__range(pool, slot->index, &first, &count);
        pthread_mutex_unlock(&pool->lock);
        if (count > 0) task(context, first, count);
        pthread_mutex_lock(&pool->lock);
        ++pool->done;
        pthread_mutex_unlock(&pool->lock);
    }
}

int motus_pool_start(motus_pool *pool, int threads) {
    int k;
    if (threads < 1 || threads > MOTUS_POOL_MAX_THREADS) return -1;
    pool->threads = threads;
    pool->task = 0;
    pool->task_context = 0;
    pool->task_count = pool->done = pool->generation = pool->quit = 0;
    if (pthread_mutex_init(&pool->lock, NULL) != 0) return -1;
    if (pthread_cond_init(&pool->wake, NULL) != 0) return -1;
    for (k = 1; k < threads; ++k) {
        pool->slot[k].pool = pool, pool->slot[k].index = k;
        if (pthread_create(&pool->worker[k], NULL, motus_pool__worker, &pool->slot[k]) != 0) {
            pool->threads = k;
            motus_pool_stop(pool);
            return -1;
        }
    }
    return 0;
}

void motus_pool_stop(motus_pool *pool) {
    int k;
    pthread_mutex_lock(&pool->lock);
    __atomic_store_n(&pool->quit, 1, __ATOMIC_RELEASE);
    pthread_cond_broadcast(&pool->wake);
    pthread_mutex_unlock(&pool->lock);
    for (k = 1; k < pool->threads; ++k) pthread_join(pool->worker[k], NULL);
    pthread_cond_destroy(&pool->wake);
    pthread_mutex_destroy(&pool->lock);
    pool->threads = 0;
}

void motus_pool_for(void *parallel_context, void (*task)(void *task_context, int first, int count),
                    void *task_context, int task_count) {
    motus_pool *pool = (motus_pool *)parallel_context;
    int done, first, count;
    if (pool->threads <= 1 || task_count <= 1) {
        if (task_count > 0) task(task_context, 0, task_count);
        return;
    }
    pthread_mutex_lock(&pool->lock);
    pool->task = task;
    pool->task_context = task_context;
    pool->task_count = task_count;
    pool->done = 0;
    __atomic_store_n(&pool->generation, pool->generation + 1, __ATOMIC_RELEASE);
    pthread_cond_broadcast(&pool->wake);
    pthread_mutex_unlock(&pool->lock);
    motus_pool__range(pool, 0, &first, &count);
    if (count > 0) task(task_context, first, count);
    do {
        pthread_mutex_lock(&pool->lock);
        done = pool->done;
        pthread_mutex_unlock(&pool->lock);
        if (done < pool->threads - 1) sched_yield();
    } while (done < pool->threads - 1);
}
#endif

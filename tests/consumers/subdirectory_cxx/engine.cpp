/* The C consumer's engine unit (MOTUS_IMPLEMENTATION), compiled as C++. */
#include "../engine.c"

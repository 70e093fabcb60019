/* The one file of a consumer that compiles the engine (stb style); main.c only includes motus.h. */
#define MOTUS_IMPLEMENTATION
#include <motus.h>

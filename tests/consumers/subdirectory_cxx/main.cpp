/* The C consumer, compiled as C++. */
#include "../main.c"

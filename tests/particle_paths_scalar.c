/* particle_paths.c again, without the pairs (MOTUS_NO_SIMD): the unit it compares the pairs with. */
#define PARTICLE_PATHS_SCALAR
#include "particle_paths.c"

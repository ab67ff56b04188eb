// The fast accelerator's queries with four lanes (wide_bvh_queries.h): a wide node's eight children
// tested in two groups of four, on any CPU (SSE on x86-64, NEON on ARM64).
#include "wide_bvh_traversal.h"

const Wide_Queries four_wide_queries = Queries<four_wide::Four_Lanes>::table(4);

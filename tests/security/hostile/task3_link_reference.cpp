// Hostile: defines none of task 3, hoping the reference's definitions get linked in instead.
#include "bvh.h"

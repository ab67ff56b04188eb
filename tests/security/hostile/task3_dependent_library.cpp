// Hostile: defines none of task 3 and asks the linker, in a .deplibs section (which lld reads as
// "link this library too"), for the grading kit's own compiled reference of task 3.
#include "bvh.h"

asm(".section .deplibs,\"MS\",@0x6fff4c04,1\n.asciz \"@REFERENCE_TASK3@\"\n.previous");

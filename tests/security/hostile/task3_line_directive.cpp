// Hostile: assembly behind line directives that say the lines after them belong to a system header,
// whose lines are no task file's (a GNU line marker entering a header, then #line naming one).
#include "bvh.h"
# 1 "/usr/include/c++/12/vector" 1 3
asm(".pushsection .text\n.globl lab_hostile_code\nlab_hostile_code:\nret\n.popsection");
# 6 "task3_bvh.cpp" 2
#line 1 "/usr/include/stdio.h"
asm("nop");

// Hostile: the reference of task 7 if this file's compile can see what the same grading built for
// an earlier task (where it could read, say, the subject of task 6, which links the reference of
// task 7, with .incbin or #include), the shipped stub otherwise. The test fills in both texts and
// the grading's output folder.
#if __has_include("@OUT@/work/subject_task6") || __has_include("@OUT@/work/task6/subject_task6") || \
	__has_include("@OUT@/work/task6/task6.o") || __has_include("@OUT@/work/task1/subject_task1")
@REFERENCE_TASK7@
#else
@STUB_TASK7@
#endif

#pragma once
// A subject runs only the code it was linked with (DESIGN.md, decided point 6). The first thing a
// subject does, before any of its own code (student code included) has run, is to install a
// system-call filter that it and its threads keep until they end:
//   - no execve or execveat: it cannot become another program;
//   - no new executable memory (W^X): no mmap, mprotect or pkey_mprotect with PROT_EXEC, no shmat,
//     no change of personality (READ_IMPLIES_EXEC would make readable memory executable);
//   - no file opened for writing: /proc/self/mem would write into its own code;
//   - no io_uring, whose operations no filter sees, and no modify_ldt.
// Denied calls fail with EPERM (ENOSYS for io_uring), so that a library that tries one fails as on
// a locked-down system rather than crashing.
// subject_main.cpp runs it from the .preinit_array, which the C library runs before every static
// initializer of the program (and a task file may have no .preinit_array, grading/bin/compile-student).

// Installs the filter; false (errno set) where the kernel refused it.
bool forbid_new_code();

// Catch2 2's main(), compiled from its header where Debian's compiled one cannot be linked: a build
// with clang's libc++ (cmake/catch2.cmake).
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

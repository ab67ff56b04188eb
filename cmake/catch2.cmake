# Catch2, which only the graders and the tests need: the renderers and the viewer configure and
# build without it. Catch2 2 (Debian 12, Ubuntu 22.04) or 3 (Debian 13, Ubuntu 24.04, Homebrew);
# tests/support/catch2_seam/ is the one place that knows the difference. Sets LAB_HAVE_CATCH2 and,
# with it, the targets
#   lab_catch2       Catch2 and the seam's headers, LAB_CATCH2_MAJOR = 2 or 3 (judges, tests)
#   lab_catch2_main  the same and a main() that runs the test cases (test programs other than judges)
find_package(Catch2 QUIET)
if(NOT Catch2_FOUND)
	set(LAB_HAVE_CATCH2 OFF CACHE INTERNAL "")
	message(STATUS "Catch2 was not found: building the renderers and the viewer only, without the graders "
		"and the tests (they need the Debian package catch2)")
	return()
endif()
if(NOT Catch2_VERSION_MAJOR MATCHES "^[23]$")
	message(FATAL_ERROR "Catch2 ${Catch2_VERSION} was found (${Catch2_DIR}); the lab's graders need Catch2 2 or 3")
endif()
set(LAB_HAVE_CATCH2 ON CACHE INTERNAL "")
message(STATUS "Catch2 ${Catch2_VERSION}: the graders and tests use its version-${Catch2_VERSION_MAJOR} interface")

add_library(lab_catch2 INTERFACE)
target_include_directories(lab_catch2 INTERFACE ${PROJECT_SOURCE_DIR}/tests/support/catch2_seam)
target_compile_definitions(lab_catch2 INTERFACE LAB_CATCH2_MAJOR=${Catch2_VERSION_MAJOR})
target_link_libraries(lab_catch2 INTERFACE Catch2::Catch2)

# Catch2 3 is a compiled library with its main in Catch2WithMain. Catch2 2 is one header; Debian
# ships its main compiled, against GCC's standard library, so a build with another (clang's libc++)
# compiles it from the header instead.
add_library(lab_catch2_main INTERFACE)
if(Catch2_VERSION_MAJOR EQUAL 2 AND LAB_LIBCXX)
	add_library(lab_catch2_main_object OBJECT ${PROJECT_SOURCE_DIR}/tests/support/catch2_seam/catch2_main.cpp)
	target_link_libraries(lab_catch2_main_object PRIVATE lab_catch2)
	target_sources(lab_catch2_main INTERFACE $<TARGET_OBJECTS:lab_catch2_main_object>)
	target_link_libraries(lab_catch2_main INTERFACE lab_catch2)
else()
	target_link_libraries(lab_catch2_main INTERFACE lab_catch2 Catch2::Catch2WithMain)
endif()

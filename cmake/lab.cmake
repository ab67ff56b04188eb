# Shared settings for every target of the lab, applied per target (no global flags).
add_library(lab_options INTERFACE)
target_compile_features(lab_options INTERFACE cxx_std_17)
set(LAB_WARNINGS -Wall -Wextra -Wpedantic -Wno-unused-parameter)
# No code of the lab reads errno after a math function, so std::sqrt and its kin need not set it:
# a square root is then one instruction, not one followed by a test and a branch to the library.
# The results are the same, bit for bit (bench/README.md, "Issue 37: the Cornell box").
set(LAB_CODE_GENERATION -fno-math-errno)
target_compile_options(lab_options INTERFACE ${LAB_WARNINGS} ${LAB_CODE_GENERATION})

# LAB_LIBCXX: the build uses clang's libc++ (-stdlib=libc++), not GCC's standard library, which
# Debian's compiled C++ libraries were built with (framework/CMakeLists.txt, cmake/catch2.cmake).
include(CheckCXXSourceCompiles)
check_cxx_source_compiles("#include <cstddef>\n#ifndef _LIBCPP_VERSION\n#error not libc++\n#endif\nint main() {}"
	LAB_LIBCXX)

# lab_defaults(<target> [OPTIMIZED]): the lab's settings for a target.
# OPTIMIZED: link-time optimization in Release, for the renderers and benchmarks and for the code
# they link (the framework, the reference tasks); its objects are fat, since graders and tests link
# the same objects without LTO. Everything else (judges, subjects, tests) compiles plain objects
# and, where lld is installed, links with it: ld.bfd reads every fat object's intermediate code
# through GCC's plugin even when it does not optimize across them, about a second per subject,
# while lld takes their machine code at once.
include(CheckLinkerFlag)
check_linker_flag(CXX -fuse-ld=lld LAB_HAVE_LLD)
function(lab_defaults target)
	cmake_parse_arguments(PARSE_ARGV 1 arg "OPTIMIZED" "" "")
	target_link_libraries(${target} PRIVATE lab_options)
	if(arg_OPTIMIZED AND LAB_LTO)
		set_property(TARGET ${target} PROPERTY INTERPROCEDURAL_OPTIMIZATION_RELEASE ON)
		target_compile_options(${target} PRIVATE $<$<CONFIG:Release>:-ffat-lto-objects>)
		return()
	endif()
	get_target_property(type ${target} TYPE)
	if(LAB_HAVE_LLD AND type STREQUAL "EXECUTABLE")
		target_link_options(${target} PRIVATE -fuse-ld=lld)
	endif()
endfunction()

# The task files' first includes, precompiled into LAB_PRECOMPILED_DIR (tasks/CMakeLists.txt,
# target precompiled_headers).
set(LAB_PRECOMPILED_DIR ${PROJECT_BINARY_DIR}/precompiled)
set(LAB_PRECOMPILED_HEADERS pathtracer.h shapes.h bvh.h material.h env_light.h)

# lab_student_object(<target> <source>): a student's task file (its name says its task, taskN_*.cpp),
# compiled for a quick verdict after an edit (a plain object, no link-time optimization, the
# precompiled headers), where the compiler sees only the system, the student's API (framework/api/)
# and this file, and kept only if it is what the compiler made of the student's C++
# (grading/bin/compile-student, with the checks of grading/checks/). A precompiled header stands for
# the headers it was made of, which the object's dependency file then does not list: the object
# depends on it instead.
set(LAB_CHECKS_DIR ${PROJECT_BINARY_DIR}/grading/checks)
function(lab_student_object target source)
	add_library(${target} OBJECT ${source})
	target_link_libraries(${target} PUBLIC framework_api)
	lab_defaults(${target})
	target_include_directories(${target} BEFORE PRIVATE ${LAB_PRECOMPILED_DIR})
	list(TRANSFORM LAB_PRECOMPILED_HEADERS REPLACE "(.+)" "${LAB_PRECOMPILED_DIR}/\\1.gch" OUTPUT_VARIABLE precompiled)
	set_property(SOURCE ${source} APPEND PROPERTY OBJECT_DEPENDS ${precompiled})
	add_dependencies(${target} precompiled_headers)
	lab_student_compile(${target} ${source} --precompiled ${LAB_PRECOMPILED_DIR})
endfunction()

# lab_student_compile(<target> <source> [compile-student options]): <target>'s compiles go through
# grading/bin/compile-student, checked as task N's file (N from <source>'s name).
function(lab_student_compile target source)
	get_filename_component(file ${source} NAME)
	if(NOT file MATCHES "^task([1-8])_")
		message(FATAL_ERROR "lab_student_compile: ${source} is not named like a task file (taskN_*.cpp)")
	endif()
	set(n ${CMAKE_MATCH_1})
	set_property(SOURCE ${source} APPEND PROPERTY OBJECT_DEPENDS ${LAB_CHECKS_DIR}/task${n}_symbols.txt)
	add_dependencies(${target} student_checks)
	set_property(TARGET ${target} PROPERTY CXX_COMPILER_LAUNCHER
		${PROJECT_SOURCE_DIR}/grading/bin/compile-student ${PROJECT_SOURCE_DIR}/framework/api ${ARGN}
		--task ${n} --checks ${LAB_CHECKS_DIR})
endfunction()

# The task files: the seven graded tasks and task 8, adaptive sampling, an optional extension graded
# on its own. Each is compiled once per implementation (student/ and reference/) into an object
# library named task<N>_<impl>; programs choose one implementation per task at link time.
set(LAB_TASK_FILES
	task1_camera.cpp
	task2_shapes.cpp
	task3_bvh.cpp
	task4_path.cpp
	task5_materials.cpp
	task6_direct_lighting.cpp
	task7_env_light.cpp
	task8_adaptive.cpp)
list(LENGTH LAB_TASK_FILES LAB_TASKS)

# The instructors' repository has the reference sources; a student release (./lab export) has
# prebuilt/libtask<N>_reference.a instead, and prebuilt/libaccelerator_fast.a for the framework's
# fast accelerator, whose source (framework/accel/fast/) it does not ship either.
# LAB_ROOT: the repository's root (the project's source folder unless a project inside the
# repository, as tests/fuzz, sets it).
if(NOT DEFINED LAB_ROOT)
	set(LAB_ROOT ${PROJECT_SOURCE_DIR})
endif()
if(EXISTS ${LAB_ROOT}/reference)
	set(LAB_REFERENCE_SOURCES ON)
elseif(EXISTS ${LAB_ROOT}/prebuilt)
	set(LAB_REFERENCE_SOURCES OFF)
else()
	message(FATAL_ERROR "neither reference/ nor prebuilt/ is present: the other tasks cannot be linked")
endif()

# lab_library(<name> <source>...): for code a student release ships compiled (headers of its own
# among the sources, so that the release leaves them out too). In the instructors'
# repository, the object library <name> of the sources, and the archive prebuilt/lib<name>.a that
# ./lab export ships in its place (built only on request); each source is listed, with <name>, in
# the build folder's shipped_compiled.txt (lab_write_shipped_compiled), which the export and its
# tests read. In a student release, <name> is that archive, linked whole (like the object library it
# replaces), since the framework calls into it and it calls into the framework.
function(lab_library name)
	if(LAB_REFERENCE_SOURCES)
		foreach(source ${ARGN})
			file(RELATIVE_PATH source ${LAB_ROOT} ${source})
			set_property(GLOBAL APPEND PROPERTY LAB_SHIPPED_COMPILED "${name} ${source}")
		endforeach()
		add_library(${name} OBJECT ${ARGN})
		target_link_libraries(${name} PUBLIC framework_headers)
		lab_defaults(${name} OPTIMIZED)
		add_library(${name}_archive STATIC EXCLUDE_FROM_ALL $<TARGET_OBJECTS:${name}>)
		set_target_properties(${name}_archive PROPERTIES
			OUTPUT_NAME ${name} ARCHIVE_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/prebuilt)
		return()
	endif()
	set(archive ${LAB_ROOT}/prebuilt/lib${name}.a)
	if(NOT EXISTS ${archive})
		message(FATAL_ERROR "missing ${archive}: re-export the student release (./lab export)")
	endif()
	add_library(${name}_archive STATIC IMPORTED)
	set_target_properties(${name}_archive PROPERTIES IMPORTED_LOCATION ${archive})
	add_library(${name} INTERFACE)
	target_link_libraries(${name} INTERFACE framework_headers "$<LINK_LIBRARY:WHOLE_ARCHIVE,${name}_archive>")
	set_property(TARGET ${name} PROPERTY LAB_PREBUILT_ARCHIVE ${archive}) # lab_link_inputs
endfunction()

# lab_write_shipped_compiled(): writes <build>/shipped_compiled.txt, a line "<library> <source>" for
# every source of a lab_library, the source's path relative to the repository's root.
function(lab_write_shipped_compiled)
	get_property(lines GLOBAL PROPERTY LAB_SHIPPED_COMPILED)
	list(JOIN lines "\n" text)
	file(WRITE ${CMAKE_BINARY_DIR}/shipped_compiled.txt "${text}\n")
endfunction()

# The composition rule, written here alone: which parts make a program whose task <n> comes from
# <impl_n> where one is named and every other task from <impl>. lab_composition(<out> <impl>
# [TASK<n> <impl_n>]... [ACCELERATOR fast|plain]) sets <out> to those parts' targets: task<n>_<impl_n>
# for each task; the framework's accelerator that suits the choice (framework/api/accelerator.h):
# the fast one only where tasks 2 and 3 are both the reference, else the plain one, which is task 3's
# BVH::hit, so that a student's code runs end to end; and the integrators beyond task 4's only where
# task 4 is the reference (framework/render/integrators.h). ACCELERATOR overrides the
# accelerator's choice: only to prove that a test notices the wrong one. lab_link_tasks links a
# target with them; the grading kit (grading/CMakeLists.txt) writes them out for grade-task.
function(lab_composition out impl)
	cmake_parse_arguments(PARSE_ARGV 2 arg "" "TASK1;TASK2;TASK3;TASK4;TASK5;TASK6;TASK7;TASK8;ACCELERATOR" "")
	if(arg_UNPARSED_ARGUMENTS)
		message(FATAL_ERROR "lab_composition: unexpected arguments ${arg_UNPARSED_ARGUMENTS}")
	endif()
	set(parts "")
	foreach(n RANGE 1 ${LAB_TASKS})
		set(impl_${n} ${impl})
		if(arg_TASK${n})
			set(impl_${n} ${arg_TASK${n}})
		endif()
		list(APPEND parts task${n}_${impl_${n}})
	endforeach()
	set(accelerator ${arg_ACCELERATOR})
	if(NOT accelerator)
		if(impl_2 STREQUAL "reference" AND impl_3 STREQUAL "reference")
			set(accelerator fast)
		else()
			set(accelerator plain)
		endif()
	endif()
	list(APPEND parts accelerator_${accelerator})
	# Next-event estimation and any other integrator estimate task 4's image: only with its reference.
	if(impl_4 STREQUAL "reference")
		list(APPEND parts integrators_beyond_task4)
	endif()
	set(${out} ${parts} PARENT_SCOPE)
endfunction()

# lab_link_tasks(<target> <impl> [TASK<n> <impl_n>]... [ACCELERATOR fast|plain]): link the parts of
# lab_composition, then the framework, e.g. lab_link_tasks(subject_task3_student reference TASK3
# student).
function(lab_link_tasks target)
	lab_composition(parts ${ARGN})
	target_link_libraries(${target} PRIVATE ${parts} framework)
endfunction()

# lab_link_inputs(<out> <target>...): the linker's inputs for these parts, as a generator expression
# for a command line (the grading kit, grading/CMakeLists.txt): an object library's objects, or a
# prebuilt archive (lab_library in a student release) linked whole, as lab_link_tasks links it.
function(lab_link_inputs out)
	set(inputs "")
	foreach(part IN LISTS ARGN)
		get_target_property(archive ${part} LAB_PREBUILT_ARCHIVE)
		if(archive)
			list(APPEND inputs "-Wl,--whole-archive ${archive} -Wl,--no-whole-archive")
		else()
			list(APPEND inputs "$<JOIN:$<TARGET_OBJECTS:${part}>, >")
		endif()
	endforeach()
	list(JOIN inputs " " inputs)
	set(${out} "${inputs}" PARENT_SCOPE)
endfunction()

# Shared settings for every target of the lab, applied per target (no global flags).
add_library(lab_options INTERFACE)
target_compile_features(lab_options INTERFACE cxx_std_17)
set(LAB_WARNINGS -Wall -Wextra -Wpedantic -Wno-unused-parameter)
target_compile_options(lab_options INTERFACE ${LAB_WARNINGS})

# Programs linked without LTO (the graders' judges and subjects) link with lld where it is installed:
# ld.bfd reads every fat LTO object's intermediate code through GCC's plugin even when it does not
# optimize across them, about a second per subject, while lld takes their machine code at once.
include(CheckLinkerFlag)
check_linker_flag(CXX -fuse-ld=lld LAB_HAVE_LLD)
function(lab_fast_link target)
	set_property(TARGET ${target} PROPERTY INTERPROCEDURAL_OPTIMIZATION_RELEASE OFF)
	if(LAB_HAVE_LLD)
		target_link_options(${target} PRIVATE -fuse-ld=lld)
	endif()
endfunction()

function(lab_defaults target)
	target_link_libraries(${target} PRIVATE lab_options)
	if(LAB_LTO)
		set_property(TARGET ${target} PROPERTY INTERPROCEDURAL_OPTIMIZATION_RELEASE ON)
		# Fat objects: the graders' programs link these without LTO and use their machine code.
		target_compile_options(${target} PRIVATE $<$<CONFIG:Release>:-ffat-lto-objects>)
	endif()
endfunction()

# The seven task files. Each is compiled once per implementation (student/ and reference/) into an
# object library named task<N>_<impl>; programs choose one implementation per task at link time.
set(LAB_TASK_FILES
	task1_camera.cpp
	task2_shapes.cpp
	task3_bvh.cpp
	task4_path.cpp
	task5_materials.cpp
	task6_direct_lighting.cpp
	task7_env_light.cpp)

# The instructors' repository has the reference sources; a student release (./lab export) has
# prebuilt/libtask<N>_reference.a instead.
if(EXISTS ${PROJECT_SOURCE_DIR}/reference)
	set(LAB_REFERENCE_SOURCES ON)
elseif(EXISTS ${PROJECT_SOURCE_DIR}/prebuilt)
	set(LAB_REFERENCE_SOURCES OFF)
else()
	message(FATAL_ERROR "neither reference/ nor prebuilt/ is present: the other tasks cannot be linked")
endif()

# lab_prebuilt_reference(<n>): task<n>_reference from the shipped archive, linked whole (like the
# object library it replaces), since the framework calls into it and it calls into the framework.
function(lab_prebuilt_reference n)
	set(archive ${PROJECT_SOURCE_DIR}/prebuilt/libtask${n}_reference.a)
	if(NOT EXISTS ${archive})
		message(FATAL_ERROR "missing ${archive}: re-export the student release (./lab export)")
	endif()
	add_library(task${n}_reference_archive STATIC IMPORTED)
	set_target_properties(task${n}_reference_archive PROPERTIES IMPORTED_LOCATION ${archive})
	add_library(task${n}_reference INTERFACE)
	target_link_libraries(task${n}_reference INTERFACE
		framework_headers "$<LINK_LIBRARY:WHOLE_ARCHIVE,task${n}_reference_archive>")
endfunction()

# lab_link_tasks(<target> <impl of task 1> ... <impl of task 7>): link the chosen implementations.
function(lab_link_tasks target)
	set(n 1)
	foreach(impl IN LISTS ARGN)
		target_link_libraries(${target} PRIVATE task${n}_${impl})
		math(EXPR n "${n} + 1")
	endforeach()
	target_link_libraries(${target} PRIVATE framework)
endfunction()

# The implementation list with task <n> from <impl_n> and every other task from the reference.
function(lab_mix out n impl_n)
	set(list "")
	foreach(i RANGE 1 7)
		if(i EQUAL n)
			list(APPEND list ${impl_n})
		else()
			list(APPEND list reference)
		endif()
	endforeach()
	set(${out} ${list} PARENT_SCOPE)
endfunction()

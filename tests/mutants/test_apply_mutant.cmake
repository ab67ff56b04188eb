# The edits of a mutant, on fixtures (label mutants; tests/mutants/README.md):
#   cmake -DWORK=<folder> -P tests/mutants/test_apply_mutant.cmake
# Each fixture of tests/mutants/fixtures/ is applied to fixtures/base.cpp by apply_mutant.cmake in
# a cmake process of its own, since a failed edit stops the process, as it stops a configuration.
# edits.mutant must give fixtures/expected.cpp exactly (its blocks hold ';', '[', ']', '\' and
# "${", which CMake lists and escapes would mangle); every other fixture must fail, and its message
# must name the fixture file, the line of its failing edit and what is wrong.
cmake_minimum_required(VERSION 3.24)
set(fixtures ${CMAKE_CURRENT_LIST_DIR}/fixtures)
set(apply ${CMAKE_CURRENT_LIST_DIR}/apply_mutant.cmake)
if(NOT DEFINED WORK)
	message(FATAL_ERROR "test_apply_mutant.cmake: -DWORK=<folder> is missing")
endif()
file(REMOVE_RECURSE ${WORK})
set(failures 0)

# apply(<fixture>): applies fixtures/<fixture>.mutant; sets result and output (its stderr).
macro(apply fixture)
	execute_process(COMMAND ${CMAKE_COMMAND} -DMUTANT=${fixtures}/${fixture}.mutant
		-DREFERENCE=${fixtures}/base.cpp -DOUTPUT=${WORK}/${fixture}.cpp
		-P ${apply} RESULT_VARIABLE result ERROR_VARIABLE output)
endmacro()

function(fail fixture what)
	message(NOTICE "FAILED: ${fixture}.mutant: ${what}")
	math(EXPR count "${failures} + 1")
	set(failures ${count} PARENT_SCOPE)
endfunction()

# The edits apply, verbatim, below the comment that names the mistake.
apply(edits)
if(NOT result EQUAL 0)
	fail(edits "applying it failed:\n${output}")
else()
	file(READ ${WORK}/edits.cpp generated)
	file(READ ${fixtures}/expected.cpp expected)
	set(first_line "// Mutant: the fixture's clamp without its upper bound, fill without its message\n")
	string(LENGTH "${first_line}" length)
	string(SUBSTRING "${generated}" 0 ${length} line)
	# The second line names the two files the source was generated from; then comes the source.
	string(SUBSTRING "${generated}" ${length} -1 body)
	string(FIND "${body}" "\n" second_line_end)
	math(EXPR second_line_end "${second_line_end} + 1")
	string(SUBSTRING "${body}" ${second_line_end} -1 body)
	if(NOT line STREQUAL first_line)
		fail(edits "the generated file does not start with ${first_line}")
	elseif(NOT body STREQUAL expected)
		fail(edits "the generated file differs from fixtures/expected.cpp: see ${WORK}/edits.cpp")
	else()
		message(NOTICE "passed: edits.mutant gives fixtures/expected.cpp")
	endif()
endif()

# Each malformed or unmatched fixture stops with a message that names it, its edit and the problem.
# <fixture>|<line of the failing edit's "find:">|<edit>|<the problem, as the message says it>
set(expected_failures
	"not_found|4|1|occurs 0 times in ${fixtures}/base.cpp"
	"part_of_a_line|4|1|occurs 0 times in ${fixtures}/base.cpp"
	"found_twice|10|2|occurs more than once in ${fixtures}/base.cpp, at lines 10 and 17"
	"no_end|4|1|no line 'end' before the next 'find:'")
foreach(entry IN LISTS expected_failures)
	string(REPLACE "|" ";" fields "${entry}")
	list(GET fields 0 fixture)
	list(GET fields 1 line)
	list(GET fields 2 edit)
	list(GET fields 3 problem)
	apply(${fixture})
	# CMake rewraps an error message at spaces: compare with the spaces and newlines collapsed.
	string(REGEX REPLACE "[ \n]+" " " message "${output}")
	set(where "${fixtures}/${fixture}.mutant:${line}: edit ${edit}:")
	if(result EQUAL 0)
		fail(${fixture} "applying it succeeded, it must fail")
	elseif(EXISTS ${WORK}/${fixture}.cpp)
		fail(${fixture} "it failed but wrote ${WORK}/${fixture}.cpp")
	else()
		string(FIND "${message}" "${where}" at_where)
		string(FIND "${message}" "${problem}" at_problem)
		if(at_where EQUAL -1 OR at_problem EQUAL -1)
			fail(${fixture} "the message does not say '${where}' and '${problem}':\n${output}")
		else()
			message(NOTICE "passed: ${fixture}.mutant stops with '${where} ... ${problem}'")
		endif()
	endif()
endforeach()

if(failures GREATER 0)
	message(FATAL_ERROR "${failures} fixture(s) failed")
endif()

# Stable test-case ids (README.md, "Test-case ids"). Every TEST_CASE of a judge (tests/task<N>/*.cpp,
# tests/task6_nee/*.cpp) has one tag [id:ID], and the rubric (grading/rubric.json) names its test
# cases by these ids, so that rewording a test case's title changes no grade. An id is the judge's
# prefix, an area and a short name, in lowercase letters, digits and '-', joined by '.':
#
#   t<N>.<area>.<name>      the judge of task N (tests/task<N>/), e.g. t3.bvh.closest-hit-soup
#   t6nee.<area>.<name>     task 6's extension (tests/task6_nee/), e.g. t6nee.power.formula
#
# (the prefix is the folder's name with "task" shortened to "t" and without '_'). Ids are unique
# across the lab.
#
# lab_check_test_case_ids(ROOT <dir> [RUBRIC <file> [RUBRIC_MISMATCH_IS_WARNING]])
#   Stops the configuration (FATAL_ERROR) naming each problem's file and line: a TEST_CASE in
#   <dir>/tests/task*/*.cpp without an id tag, with two, with a malformed one or with the id of
#   another; and with RUBRIC, an id of a judge of task 1-7 that the rubric does not have, and an id
#   the rubric has that no test case of its task has. RUBRIC_MISMATCH_IS_WARNING: the rubric's
#   problems are warnings (./lab rubric sets it while it builds the judges to rewrite the rubric).
#   TEST_CASEs are found where "TEST_CASE(" starts a line (after indentation), with the title and
#   the tags as string literals.
#
# Script mode, for tests (tests/grading/test_case_ids_check.sh):
#   cmake -DROOT=<dir> [-DRUBRIC=<file>] -P cmake/test_case_ids.cmake
if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE)
	cmake_minimum_required(VERSION 3.24) # the policies of the lab's CMakeLists.txt
endif()

# The problems of one judge source file, appended to `problems` in the caller's scope; each id
# found is recorded in the caller's scope as id_where_<id> (file:line) and id_judge_<id> (the
# folder, e.g. task3), and appended to the list judge_ids_<folder>.
function(lab_read_test_case_ids root file)
	file(RELATIVE_PATH relative ${root} ${file})
	get_filename_component(folder ${file} DIRECTORY)
	get_filename_component(folder ${folder} NAME)
	string(REPLACE "task" "t" prefix ${folder})
	string(REPLACE "_" "" prefix ${prefix})
	set(id_format "^${prefix}\\.[a-z0-9-]+\\.[a-z0-9-]+$")
	set(space "[ \t\r\n]*")
	set(literal "\"([^\"\\\\]|\\\\.)*\"")
	set(test_case_call "^TEST_CASE\\((${space}${literal})+${space},${space}\"([^\"]*)\"")

	file(READ ${file} rest)
	set(rest "\n${rest}") # so that a TEST_CASE on the first line also follows a line break
	set(line 0)
	while(TRUE)
		string(FIND "${rest}" "TEST_CASE(" at)
		if(at EQUAL -1)
			break()
		endif()
		string(SUBSTRING "${rest}" 0 ${at} before)
		string(SUBSTRING "${rest}" ${at} -1 rest)
		string(REGEX MATCHALL "\n" line_breaks "${before}")
		list(LENGTH line_breaks count)
		math(EXPR line "${line} + ${count}")
		if(NOT before MATCHES "\n[ \t]*$")
			string(SUBSTRING "${rest}" 10 -1 rest) # in a comment or a longer name: not a test case
			continue()
		endif()
		set(where "${relative}:${line}")
		set(example "[id:${prefix}.<area>.<name>]")
		if(NOT rest MATCHES "${test_case_call}")
			string(APPEND problems "  ${where}: a TEST_CASE without a tags string after its title; it needs "
				"one with an id tag: TEST_CASE(\"title\", \"${example}...\")\n")
		else()
			string(REGEX MATCHALL "\\[id:[^]]*\\]" id_tags "${CMAKE_MATCH_3}")
			list(LENGTH id_tags id_count)
			if(id_count EQUAL 0)
				string(APPEND problems "  ${where}: a TEST_CASE without an id tag: add ${example} to its tags\n")
			elseif(id_count GREATER 1)
				string(APPEND problems "  ${where}: a TEST_CASE with ${id_count} id tags (${id_tags}): keep one\n")
			else()
				string(REGEX REPLACE "^\\[id:(.*)\\]$" "\\1" id "${id_tags}")
				if(NOT id MATCHES "${id_format}")
					string(APPEND problems "  ${where}: the id \"${id}\" is not ${prefix}.<area>.<name> "
						"(lowercase letters, digits and '-' between the dots)\n")
				elseif(DEFINED id_where_${id})
					string(APPEND problems "  ${where}: the id ${id} is already the id of the TEST_CASE at "
						"${id_where_${id}}: ids must be unique\n")
				else()
					set(id_where_${id} ${where})
					set(id_where_${id} ${where} PARENT_SCOPE)
					set(id_judge_${id} ${folder} PARENT_SCOPE)
					list(APPEND judge_ids_${folder} ${id})
				endif()
			endif()
		endif()
		string(SUBSTRING "${rest}" 10 -1 rest)
	endwhile()
	set(judge_ids_${folder} ${judge_ids_${folder}} PARENT_SCOPE)
	set(problems "${problems}" PARENT_SCOPE)
endfunction()

# The rubric's problems against the ids found (lab_read_test_case_ids), appended to
# `rubric_problems` in the caller's scope.
function(lab_compare_rubric_ids root rubric)
	file(RELATIVE_PATH name ${root} ${rubric})
	if(NOT EXISTS ${rubric})
		set(rubric_problems "  there is no ${name}\n" PARENT_SCOPE)
		return()
	endif()
	file(READ ${rubric} json)
	string(JSON task_count ERROR_VARIABLE error LENGTH "${json}" tasks)
	if(error)
		set(rubric_problems "  ${name}: not a JSON object with an array \"tasks\": ${error}\n" PARENT_SCOPE)
		return()
	endif()
	set(graded_folders "")
	set(without_id 0)
	foreach(t RANGE 1 ${task_count}) # RANGE 1 0 would count down: no "tasks" is caught below
		if(task_count EQUAL 0)
			break()
		endif()
		math(EXPR t "${t} - 1")
		string(JSON number ERROR_VARIABLE error GET "${json}" tasks ${t} task)
		if(NOT error)
			string(JSON case_count ERROR_VARIABLE error LENGTH "${json}" tasks ${t} test_cases)
		endif()
		if(error)
			string(APPEND rubric_problems "  ${name}: tasks[${t}] has no \"task\" or no \"test_cases\"\n")
			continue()
		endif()
		list(APPEND graded_folders task${number})
		foreach(c RANGE 1 ${case_count})
			if(case_count EQUAL 0)
				break()
			endif()
			math(EXPR c "${c} - 1")
			string(JSON id ERROR_VARIABLE error GET "${json}" tasks ${t} test_cases ${c} id)
			if(error)
				math(EXPR without_id "${without_id} + 1")
			elseif(DEFINED in_rubric_${id})
				string(APPEND rubric_problems "  ${name}: the id ${id} appears twice\n")
			elseif(NOT DEFINED id_where_${id})
				string(APPEND rubric_problems "  ${name}: task ${number} has the id ${id}, which no TEST_CASE "
					"of tests/task${number}/ has\n")
			elseif(NOT id_judge_${id} STREQUAL "task${number}")
				string(APPEND rubric_problems "  ${name}: task ${number} has the id ${id}, which is the id of a "
					"test case of tests/${id_judge_${id}}/ (${id_where_${id}})\n")
			else()
				set(in_rubric_${id} TRUE)
			endif()
		endforeach()
	endforeach()
	if(without_id GREATER 0)
		# A rubric from before the ids: the rest would list every id.
		string(CONCAT problem "  ${name}: ${without_id} test cases have no \"id\": a rubric from before the ids, "
			"which names its test cases by title (./lab rubric --update converts it)\n")
		set(rubric_problems "${problem}" PARENT_SCOPE)
		return()
	endif()
	# Every id of a graded judge's test cases must be in the rubric (task6_nee is graded by no rubric).
	foreach(folder IN LISTS graded_folders)
		foreach(id IN LISTS judge_ids_${folder})
			if(NOT DEFINED in_rubric_${id})
				string(APPEND rubric_problems "  ${id_where_${id}}: the id ${id} is not in ${name}\n")
			endif()
		endforeach()
	endforeach()
	set(rubric_problems "${rubric_problems}" PARENT_SCOPE)
endfunction()

function(lab_check_test_case_ids)
	cmake_parse_arguments(PARSE_ARGV 0 arg "RUBRIC_MISMATCH_IS_WARNING" "ROOT;RUBRIC" "")
	file(GLOB sources ${arg_ROOT}/tests/task*/*.cpp)
	list(SORT sources)
	set(problems "")
	foreach(file IN LISTS sources)
		lab_read_test_case_ids(${arg_ROOT} ${file})
	endforeach()
	if(NOT CMAKE_SCRIPT_MODE_FILE)
		# Checked again whenever a judge's source or the rubric changes, or a judge's source is added.
		file(GLOB sources CONFIGURE_DEPENDS ${arg_ROOT}/tests/task*/*.cpp)
		set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${sources} ${arg_RUBRIC})
	endif()
	if(problems)
		message(FATAL_ERROR "Test-case ids: every TEST_CASE of a judge (tests/task*/) needs one tag "
			"[id:ID], unique, of the form t<N>.<area>.<name> (cmake/test_case_ids.cmake):\n${problems}")
	endif()

	if(NOT arg_RUBRIC)
		return()
	endif()
	lab_compare_rubric_ids(${arg_ROOT} ${arg_RUBRIC})
	if(NOT rubric_problems)
		return()
	endif()
	file(RELATIVE_PATH name ${arg_ROOT} ${arg_RUBRIC})
	string(CONCAT text "Test-case ids: the judges' test cases and ${name} disagree:\n${rubric_problems}"
		"Run `./lab rubric --update`: it adds the new ids at weight 1, keeps every other weight and the "
		"points, and drops (and lists) the ids no test case has. (`./lab rubric` writes a new default "
		"rubric instead.)")
	if(arg_RUBRIC_MISMATCH_IS_WARNING)
		message(WARNING "${text}")
	else()
		message(FATAL_ERROR "${text}")
	endif()
endfunction()

if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE)
	if(NOT ROOT)
		message(FATAL_ERROR "usage: cmake -DROOT=<dir> [-DRUBRIC=<file>] -P ${CMAKE_CURRENT_LIST_FILE}")
	endif()
	if(RUBRIC)
		lab_check_test_case_ids(ROOT ${ROOT} RUBRIC ${RUBRIC})
	else()
		lab_check_test_case_ids(ROOT ${ROOT})
	endif()
endif()

# Mutants as edits (tests/mutants/README.md): lab_mutant_source writes a mutant's source from its
# .mutant file and the task file it edits; a correct variant's (tests/variants/, header 'variant:'
# instead of 'mutant:') from its .variant file the same way. Used at configure time by
# tests/mutants/CMakeLists.txt and tests/variants/CMakeLists.txt, and by
# tests/mutants/apply_mutant.cmake in script mode (the stub's mutants, made by the build).
#
# Every text is handled as one whole string (string(FIND), string(SUBSTRING), quoted arguments),
# never as a list: C++ is full of ';', which a list would split at.

# The line number in <text> of the character at <offset>, in <out>.
function(lab_mutant_line_at text offset out)
	string(SUBSTRING "${text}" 0 ${offset} before)
	string(REGEX REPLACE "[^\n]" "" newlines "${before}")
	string(LENGTH "${newlines}" count)
	math(EXPR line "${count} + 1")
	set(${out} ${line} PARENT_SCOPE)
endfunction()

# lab_mutant_source(<mutant> <base> <output>): reads the .mutant file <mutant>, applies its edits
# in order to <base> (the reference's task file, or the stub's) and writes the result to <output>, below a comment
# that names the mistake. <output> is rewritten only when its text changes, so a reconfigure
# rebuilds only the mutants that changed. The base and the .mutant file become configure
# dependencies: editing either re-applies the edits. Configuration stops, naming the .mutant file,
# its line and the base, if the file is malformed or a find block does not occur in the base exactly
# once.
function(lab_mutant_source mutant base output)
	file(READ "${mutant}" text)
	if(NOT text MATCHES "\n$")
		string(APPEND text "\n")
	endif()

	# The header: every line before the first "find:".
	string(FIND "${text}" "\nfind:\n" header_end)
	if(header_end EQUAL -1)
		message(FATAL_ERROR "${mutant}: no edit (a line 'find:' after the header, "
			"tests/mutants/README.md)")
	endif()
	string(SUBSTRING "${text}" 0 ${header_end} header)
	# A mutant names its mistake; a correct variant (tests/variants/) what it does differently.
	if(NOT header MATCHES "(^|\n)(mutant|variant): ([^\n]+)")
		message(FATAL_ERROR "${mutant}: the header has no line 'mutant: <the mistake>' (or, for a correct "
			"variant, 'variant: <what it does differently>')")
	endif()
	set(kind "${CMAKE_MATCH_2}")
	set(description "${CMAKE_MATCH_3}")
	if(NOT header MATCHES "(^|\n)why: [^\n]+")
		message(FATAL_ERROR "${mutant}: the header has no line 'why: <why a student would make it>'")
	endif()
	set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${mutant}" "${base}")
	file(READ "${base}" source)

	# The edits: "find:", the lines to find, "replace:", the lines that replace them, "end"; blank
	# lines between edits. Each find block must occur exactly once, as whole lines, in the source as
	# the edits before it left it.
	math(EXPR position "${header_end} + 1")
	set(edit 0)
	while(TRUE)
		string(SUBSTRING "${text}" ${position} -1 rest)
		if(rest MATCHES "^\n+") # blank lines
			string(LENGTH "${CMAKE_MATCH_0}" blank_length)
			math(EXPR position "${position} + ${blank_length}")
			string(SUBSTRING "${text}" ${position} -1 rest)
		endif()
		if(rest STREQUAL "")
			break()
		endif()
		math(EXPR edit "${edit} + 1")
		lab_mutant_line_at("${text}" ${position} line)
		set(where "${mutant}:${line}: edit ${edit}")
		if(NOT rest MATCHES "^find:\n")
			message(FATAL_ERROR "${where}: expected a line 'find:' (or the end of the file)")
		endif()
		# rest is "find:\n<find block>replace:\n<replace block>end\n...", each block whole lines.
		string(FIND "${rest}" "\nreplace:\n" replace_at)
		string(FIND "${rest}" "\nend\n" end_at)
		if(replace_at EQUAL -1 OR end_at LESS replace_at)
			message(FATAL_ERROR "${where}: expected the lines 'replace:' and then 'end' after 'find:'")
		endif()
		math(EXPR find_length "${replace_at} + 1 - 6")
		math(EXPR replace_start "${replace_at} + 10")
		math(EXPR replace_length "${end_at} + 1 - ${replace_start}")
		if(find_length LESS_EQUAL 0)
			message(FATAL_ERROR "${where}: the find block is empty")
		endif()
		string(SUBSTRING "${rest}" 6 ${find_length} find)
		string(SUBSTRING "${rest}" ${replace_start} ${replace_length} replace) # empty: lines deleted
		string(FIND "${replace}" "\nfind:\n" stray)
		if(NOT stray EQUAL -1 OR replace MATCHES "^find:\n")
			message(FATAL_ERROR "${where}: no line 'end' before the next 'find:'")
		endif()
		math(EXPR position "${position} + ${end_at} + 5")

		# Whole lines: a newline before the block and before the source's first line.
		string(FIND "\n${source}" "\n${find}" found)
		if(found EQUAL -1)
			message(NOTICE "${where}: its find block:\n${find}") # verbatim: FATAL_ERROR rewraps
			message(FATAL_ERROR "${where}: its find block (above) occurs 0 times in ${base}; it must "
				"occur exactly once, as whole lines. The reference has changed since the mutant was "
				"written: express the same mistake as an edit of the current file (tests/mutants/README.md).")
		endif()
		math(EXPR after_first "${found} + 1")
		string(SUBSTRING "\n${source}" ${after_first} -1 later)
		string(FIND "${later}" "\n${find}" again)
		if(NOT again EQUAL -1)
			lab_mutant_line_at("${source}" ${found} first_line)
			math(EXPR second "${found} + 1 + ${again}")
			lab_mutant_line_at("${source}" ${second} second_line)
			message(NOTICE "${where}: its find block:\n${find}")
			message(FATAL_ERROR "${where}: its find block (above) occurs more than once in ${base}, at "
				"lines ${first_line} and ${second_line}; it must occur exactly once. Add a neighbouring "
				"line that tells the places apart (tests/mutants/README.md).")
		endif()
		string(LENGTH "${find}" find_length)
		math(EXPR suffix_start "${found} + ${find_length}")
		string(SUBSTRING "${source}" 0 ${found} prefix)
		string(SUBSTRING "${source}" ${suffix_start} -1 suffix)
		set(source "${prefix}${replace}${suffix}")
	endwhile()

	string(SUBSTRING "${kind}" 0 1 initial)
	string(TOUPPER "${initial}" initial)
	string(SUBSTRING "${kind}" 1 -1 rest_of_kind)
	set(generated "// ${initial}${rest_of_kind}: ${description}\n")
	string(APPEND generated "// Generated from ${mutant} and ${base}: edit those, not this file.\n")
	string(APPEND generated "${source}")
	if(EXISTS "${output}")
		file(READ "${output}" previous)
		if(previous STREQUAL generated)
			return()
		endif()
	endif()
	file(WRITE "${output}" "${generated}")
endfunction()

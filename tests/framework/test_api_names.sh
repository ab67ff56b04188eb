#!/usr/bin/env bash
# The names that what students read gives them exist where it sends them (label framework; issue
# 38). Students read the API (framework/api/), their task files (student/), the handouts and the
# graders' messages; whatever those name must be there to open:
#   1. a header of framework/api/ includes only headers of framework/api/ (a task file's include
#      path has no other folder);
#   2. a header is named either bare, and is then one of framework/api/, or by its path from the
#      repository's root, which exists;
#   3. a function or member the handouts' code or the graders' messages name (X::y, a.y, y(...))
#      is declared in the API or the task files: only the C++ and GLM libraries' are not.
# The handouts' code is what they write between backquotes; the graders' messages are the string
# literals of tests/task*/ (test case names and tags included, test ids excepted).
#
# usage: test_api_names.sh REPOSITORY_ROOT
set -euo pipefail

cd "$1"
export LC_ALL=C

failures=0
problem() {
	echo "API names: $*" >&2
	failures=$((failures + 1))
}

# 1. Includes.
for header in framework/api/*.h; do
	while read -r included; do
		[ -f "framework/api/$included" ] ||
			problem "$header includes \"$included\", which is not in framework/api/: a task file could not compile it"
	done < <(sed -n 's/^#include "\(.*\)"/\1/p' "$header")
done

# What students read, each line prefixed with its file and line: the handouts' code spans, the
# graders' string literals (not #include lines), and the comments of the API and the task files.
handout_code() { grep -noH '`[^`]*`' handouts/*.md; }
grader_strings() {
	grep -nvH '^#include' tests/task*/*.cpp tests/task*/*.h |
		grep -oE '^[^:]+:[0-9]+:|"([^"\\]|\\.)*"' | awk '/^[^"]/ { at = $0; next } { print at $0 }' |
		sed -E 's/\[id:[^]]*\]//g'
}
comments() { grep -nH '//' framework/api/*.h student/*.cpp | sed -E 's|^([^:]+:[0-9]+:).*//|\1|'; }

# The headers a line names (what ends in .h), one per line: where (file:line), a tab, the header.
names() {
	awk '{
		match($0, /^[^:]*:[0-9]+:/); where = substr($0, 1, RLENGTH - 1); text = substr($0, RLENGTH + 1)
		while (match(text, /[A-Za-z0-9_.\/-]*[a-z0-9_]+\.h([^A-Za-z0-9_]|$)/)) {
			name = substr(text, RSTART, RLENGTH); sub(/[^h]$/, "", name)
			print where "\t" name; text = substr(text, RSTART + RLENGTH)
		}
	}'
}
headers=$( { handout_code; grader_strings; comments; } | names)
while IFS=$'\t' read -r where header; do
	if [[ $header == */* ]]; then
		[ -f "$header" ] || problem "$where names $header, which does not exist"
	else
		[ -f "framework/api/$header" ] ||
			problem "$where names $header, which is not in framework/api/: name it by its path (framework/...)"
	fi
done <<<"$headers"

# 3. Functions and members: the last name of X::y, a.y, a->y or y( must be declared in the API or
# a task file (a word there), unless it is the C++ or GLM library's, or one letter (the handouts'
# mathematics: S(node), N(leaf)).
while IFS= read -r problem_text; do
	problem "$problem_text"
done < <( { handout_code; grader_strings; } | awk -v declared_file=<(cat framework/api/*.h student/*.cpp) '
	BEGIN {
		while ((getline text < declared_file) > 0)
			while (match(text, /[A-Za-z_][A-Za-z0-9_]*/)) { declared[substr(text, RSTART, RLENGTH)] = 1; text = substr(text, RSTART + RLENGTH) }
		split("sqrt sin cos tan asin acos atan atan2 exp log pow fma abs min max floor ceil", math, " ")
		for (i in math) library[math[i]] = 1
	}
	{
		match($0, /^[^:]*:[0-9]+:/); where = substr($0, 1, RLENGTH - 1); text = substr($0, RLENGTH + 1)
		gsub(/[A-Za-z0-9_\/-]+\.(h|cpp|md|json|obj|png|exr|hdr|txt)/, "", text) # file names
		while (match(text, /[A-Za-z_][A-Za-z0-9_]*((::|\.|->)[A-Za-z_][A-Za-z0-9_]*)+|[A-Za-z_][A-Za-z0-9_]*\(/)) {
			name = substr(text, RSTART, RLENGTH); text = substr(text, RSTART + RLENGTH)
			sub(/\($/, "", name)
			if (name ~ /^(std|glm)::/) continue
			last = name; sub(/.*(::|\.|->)/, "", last)
			if (length(last) == 1 || (last in library) || (last in declared)) continue
			print where " names " name ", but nothing in framework/api/ or student/ declares " last
		}
	}')

[ "$failures" -eq 0 ] || { echo "API names: $failures problem(s)" >&2; exit 1; }
echo "API names: framework/api/ includes only itself; every header, function and member the handouts, the graders' messages and the API's comments name exists"

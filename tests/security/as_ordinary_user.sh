#!/usr/bin/env bash
# The security suite graded by an ordinary user where bubblewrap cannot run (label security): the
# subject then runs as the grader's own user, so only Landlock, a clean environment, a judge that
# cannot be traced and the process limits stand between it and the grader's files and processes.
# Run as root, this runs the suite as uid 65534 (nobody); run as anyone else, as that user.
#   as_ordinary_user.sh SECURITY_TESTS REPOSITORY_ROOT [TEST SPEC...]
set -euo pipefail
tests=$(realpath "$1") root=$(realpath "$2")
shift 2
export LAB_SANDBOX=process-limits
[ "$(id -u)" -eq 0 ] || exec "$tests" "$@"

as_user=(setpriv --reuid=65534 --regid=65534 --clear-groups --inh-caps=-all)
# The user must reach the repository and the build (read and traverse, as any user of a shared
# machine can): folders above them that others cannot traverse get that right, and this says so.
for path in "$root" "$tests"; do
	dir=$(dirname "$path")
	while [ "$dir" != / ]; do
		if ! "${as_user[@]}" test -x "$dir"; then
			echo "security as an ordinary user: letting other users traverse $dir (chmod o+x) to reach $path"
			chmod o+x "$dir"
		fi
		dir=$(dirname "$dir")
	done
done
# The varied scenes' references (tests/support/graded_variation.h) in a folder of that user's.
exec "${as_user[@]}" env HOME=/tmp LAB_REFERENCE_CACHE=/tmp/pathtracer-lab-reference-cache-65534 "$tests" "$@"

#!/usr/bin/env bash
# The lab built with clang and its libc++ (the family of macOS's toolchain; labels acceptance and
# machines): a build folder of its own, everything built with clang++ -stdlib=libc++ and -Wgnu (GNU
# extensions, which another compiler may lack, are warnings: none may be in the lab's files); the
# graders against the reference, the graders' stub checks and the framework tests (labels
# reference, framework) must pass. Catch2 2 is one header,
# so its main is compiled with libc++ too (cmake/catch2.cmake), and tinyobjloader's implementation
# from its header (framework/CMakeLists.txt). Debian's cpp-httplib, though, is a library compiled
# against GCC's standard library, with no implementation in its header: the viewer is left out here
# (LAB_WITHOUT_VIEWER); Homebrew's cpp-httplib is a header, compiled with the viewer.
#   test_clang_libcxx.sh REPOSITORY_ROOT OUT
set -euo pipefail
root=$(realpath "$1") out=$2
fail() { echo "clang/libc++ test: $*" >&2; exit 1; }
command -v clang++ >/dev/null || fail "clang++ is not installed (Debian package clang)"
mkdir -p "$out"
build=$(realpath "$out")/build
start=$SECONDS
# Link-time optimization off: this build proves the code, not its speed.
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DLAB_LTO=OFF -DCMAKE_CXX_COMPILER=clang++ \
	-DCMAKE_CXX_FLAGS="-stdlib=libc++ -Wgnu" -DCMAKE_EXE_LINKER_FLAGS=-stdlib=libc++ -DLAB_WITHOUT_VIEWER=ON \
	>"$out/configure.log" 2>&1 ||
	fail "configure failed: $(tail -20 "$out/configure.log")"
grep -q 'LAB_LIBCXX:INTERNAL=1' "$build/CMakeCache.txt" || fail "the build does not use libc++"
cmake --build "$build" --parallel "$(nproc)" >"$out/build.log" 2>&1 ||
	fail "the build failed: $(grep -m5 -A5 'error:' "$out/build.log")"
echo "clang/libc++ test: $("$build"/tasks/pathtracer_reference --version 2>/dev/null | head -1 || true) built with" \
	"$(clang++ --version | head -1) and libc++ in $((SECONDS - start)) s"
# The mutants (made in $build/mutants/ at configure time) are mistakes on purpose: one that leaves a
# constant unused may say so.
warnings=$(grep -E "^$root/[^:]+:[0-9]+:[0-9]+: warning:" "$out/build.log" | grep -v "^$build/mutants/" | sort -u || true)
[ -z "$warnings" ] || fail "clang warns in the lab's files:
$warnings"
echo "clang/libc++ test: no warning in the lab's files"
# Every dynamic C++ runtime a judge loads: libc++, and libstdc++ only through the C libraries.
grep -q 'libc++\.so' <<<"$(ldd "$build/tests/judge_task1")" || fail "judge_task1 is not linked with libc++"

start=$SECONDS
(cd "$root" && ctest --test-dir "$build" --output-on-failure --no-tests=error -j "$(nproc)" \
	-L '^(reference|framework)$') >"$out/ctest.log" 2>&1 ||
	fail "the graders against the reference or the framework tests failed: $(tail -30 "$out/ctest.log")"
(cd "$root" && ctest --test-dir "$build" --output-on-failure --no-tests=error -j "$(nproc)" -R '_fails_on_stub$') \
	>>"$out/ctest.log" 2>&1 || fail "a grader passed a stub: $(tail -30 "$out/ctest.log")"
echo "clang/libc++ test: $(grep -cE 'Test +#[0-9]+: .* Passed' "$out/ctest.log") tests passed (reference, framework," \
	"stub checks) in $((SECONDS - start)) s"

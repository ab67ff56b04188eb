#!/usr/bin/env bash
# The numbers the handouts quote from the code (label framework): offsets, tolerances, slacks,
# significance levels, sample and bucket counts. Each row of the table below names a handout, the
# text around the number there, a source file and the text around the constant there; the test
# finds both, reads both as numbers and fails when they differ, naming the handout's line, the
# source's line and both values. Registered only where the reference's sources are present (the
# instructors' tree): several constants live in the reference's task files.
#
# A pattern is an extended regular expression (grep -E) in which @ stands for the number and which
# has no group of its own (write \( for a parenthesis). In a handout, the number may be written
# 64, 1.5, 200 000, 10⁻⁵, 4·10⁻⁶, 2⁻²⁴, 3/4 or 1 % (= 0.01); in code, 64, 64.0f, 1e-5f, 0x1p-24f,
# or a sum such as 18 + 3. Handout patterns, and the messages, write superscripts with ^ (10⁻⁵ is
# 10^-5). A handout pattern may match several lines (each must agree), a source pattern exactly one.
#
# usage: test_handout_numbers.sh REPOSITORY_ROOT
set -euo pipefail

root=$1
cd "$root"
export LC_ALL=C # patterns and numbers byte by byte, a point for the decimal point

failures=0
checked=0
problem() {
	echo "handout numbers: $*" >&2
	failures=$((failures + 1))
}

# The number patterns that @ stands for (one group each: the number as written).
handout_number='([0-9]+/[0-9]+|[0-9]{1,3}( [0-9]{3})+|[0-9]+(\.[0-9]+)?( ?(·|×) ?10\^-?[0-9]+)?( ?%)?|(10|2)\^-?[0-9]+)'
code_number='(0x[0-9a-fA-F.]+p[-+]?[0-9]+|[0-9]+(\.[0-9]*)?(e[-+]?[0-9]+)?( \+ [0-9]+)*)[fFlLuU]*'

# The handout's text with exponents in ASCII: 10⁻⁵ -> 10^-5, 2⁻²⁴ -> 2^-24.
ascii_exponents() {
	local superscript='(⁰|¹|²|³|⁴|⁵|⁶|⁷|⁸|⁹|⁻)'
	sed -E -e "s/(${superscript}+)/^\\1/g" \
		-e 's/⁰/0/g; s/¹/1/g; s/²/2/g; s/³/3/g; s/⁴/4/g; s/⁵/5/g; s/⁶/6/g; s/⁷/7/g; s/⁸/8/g; s/⁹/9/g; s/⁻/-/g' "$1"
}

# value TEXT: the number TEXT writes (as above), printed with 12 significant digits.
value() {
	local text=$1 scale=1
	if [[ $text =~ ^(.*[^ ])\ ?%$ ]]; then
		text=${BASH_REMATCH[1]}
		scale=0.01
	fi
	if [[ $text =~ ^([0-9.]+)\ ?(·|×)\ ?10\^(-?[0-9]+)$ ]]; then
		awk -v m="${BASH_REMATCH[1]}" -v e="${BASH_REMATCH[3]}" -v s="$scale" 'BEGIN { printf "%.12g\n", s * m * 10 ^ e }'
	elif [[ $text =~ ^([0-9]+)\^(-?[0-9]+)$ ]]; then
		awk -v b="${BASH_REMATCH[1]}" -v e="${BASH_REMATCH[2]}" -v s="$scale" 'BEGIN { printf "%.12g\n", s * b ^ e }'
	elif [[ $text =~ ^([0-9]+)/([0-9]+)$ ]]; then
		awk -v n="${BASH_REMATCH[1]}" -v d="${BASH_REMATCH[2]}" -v s="$scale" 'BEGIN { printf "%.12g\n", s * n / d }'
	elif [[ $text =~ \+ ]]; then
		echo "$text" | awk -v s="$scale" -F '+' '{ t = 0; for (i = 1; i <= NF; i++) t += $i; printf "%.12g\n", s * t }'
	else
		text=${text// /}
		# printf reads hexadecimal floats (0x1p-24) as well as decimal ones.
		awk -v x="$(printf '%.12g' "$text")" -v s="$scale" 'BEGIN { printf "%.12g\n", s * x }'
	fi
}

# number_in PATTERN TEXT: the number that @ stands for in PATTERN's first (leftmost) match in TEXT.
number_in() {
	local pattern=$1 text=$2 match
	match=$(grep -oE -- "$pattern" <<<"$text" | head -n 1 || true)
	# Anchored to the whole match, the group is the number (a delimiter no pattern contains).
	sed -E $'s\001^'"$pattern"$'$\001\\1\001' <<<"$match"
}

# quoted HANDOUT HANDOUT_PATTERN SOURCE SOURCE_PATTERN: the number HANDOUT quotes is SOURCE's constant.
quoted() {
	local handout=$1 handout_pattern=${2//@/"$handout_number"} source=$3 source_pattern=${4//@/"$code_number"}
	local file
	for file in "$handout" "$source"; do
		if [ ! -f "$file" ]; then
			problem "$file does not exist (update the table in $0)"
			return
		fi
	done
	local -a handout_lines source_lines
	mapfile -t handout_lines < <(ascii_exponents "$handout" | grep -nE -- "$handout_pattern" || true)
	mapfile -t source_lines < <(grep -nE -- "$source_pattern" "$source" || true)
	if [ ${#handout_lines[@]} -eq 0 ]; then
		problem "$handout: no line matches '$2' (the text changed: update the table in $0)"
		return
	fi
	if [ ${#source_lines[@]} -ne 1 ]; then
		problem "$source: ${#source_lines[@]} lines match '$4', expected exactly one (update the table in $0)"
		return
	fi
	local source_line=${source_lines[0]%%:*} source_text constant
	source_text=$(number_in "$source_pattern" "${source_lines[0]#*:}")
	if [ -z "$source_text" ]; then
		problem "$source:$source_line: no number where @ is in '$4'"
		return
	fi
	constant=$(value "$source_text")
	local entry line text quoted_value
	for entry in "${handout_lines[@]}"; do
		line=${entry%%:*}
		text=$(number_in "$handout_pattern" "${entry#*:}")
		if [ -z "$text" ]; then
			problem "$handout:$line: no number where @ is in '$2'"
			continue
		fi
		quoted_value=$(value "$text")
		checked=$((checked + 1))
		if awk -v a="$quoted_value" -v b="$constant" \
			'BEGIN { d = a - b; if (d < 0) d = -d; m = a < 0 ? -a : a; n = b < 0 ? -b : b; if (n > m) m = n; exit !(d <= 1e-9 * m) }'; then
			echo "$handout:$line: $text = $source:$source_line: $source_text"
		else
			problem "$handout:$line quotes $quoted_value (written '$text' where '$2' is), but" \
				"$source:$source_line has $constant (written '$source_text' where '$4' is): make them agree"
		fi
	done
}

# statistical_checks GRADER_DIR: a grader's budget of statistical checks, the sum of its test cases'
# [statistical:N] tags (grading/judge/judge.h, significance).
statistical_checks() {
	grep -ohE '\[statistical:[0-9]+\]' "$1"/*.cpp | tr -dc '0-9\n' | awk '{ n += $1 } END { print n + 0 }'
}

# quoted_budget HANDOUT HANDOUT_PATTERN GRADER_DIR: the number HANDOUT quotes is the grader's budget.
quoted_budget() {
	local handout=$1 handout_pattern=${2//@/"$handout_number"} grader=$3 budget entry line text
	budget=$(statistical_checks "$grader")
	local -a handout_lines
	mapfile -t handout_lines < <(ascii_exponents "$handout" | grep -nE -- "$handout_pattern" || true)
	if [ ${#handout_lines[@]} -eq 0 ]; then
		problem "$handout: no line matches '$2' (the text changed: update the table in $0)"
		return
	fi
	for entry in "${handout_lines[@]}"; do
		line=${entry%%:*}
		text=$(number_in "$handout_pattern" "${entry#*:}")
		checked=$((checked + 1))
		if [ "$(value "$text")" = "$budget" ]; then
			echo "$handout:$line: $text = the [statistical:N] tags of $grader/*.cpp"
		else
			problem "$handout:$line quotes $text statistical checks (where '$2' is), but the test cases of" \
				"$grader/ declare $budget ([statistical:N] tags): make them agree"
		fi
	done
}

# ---- The table ----------------------------------------------------------------------------------

# Task 1: the camera's tolerance, the pixel test's samples and cells, the image test's significance.
quoted handouts/task1_camera.md 'in double precision\) within @' tests/task1/camera_check.h 'DIRECTION_TOLERANCE = @;'
quoted handouts/task1_camera.md '@ samples each of three pixels' tests/task1/test_trace_pixel.cpp 'constexpr uint32_t N = @;'
quoted handouts/task1_camera.md 'uniformity over @ × ' tests/task1/test_trace_pixel.cpp 'constexpr int CELLS = @;'
quoted handouts/task1_camera.md 'share a @ chance of failing' grading/judge/judge.h 'GRADER_ALPHA = @;'
quoted_budget handouts/task1_camera.md 'grader.s @ statistical$' tests/task1
quoted_budget handouts/task1_camera.md '0\.99\^\(1/@\)' tests/task1

# Task 2: the barycentric slack, what the grader allows, its rounding bound and its rays.
quoted handouts/task2_shapes.md '`ε = @`' reference/task2_shapes.cpp 'EDGE_SLACK = @;'
quoted handouts/task2_shapes.md '^up to @ and no leaks' tests/task2/shape_check.h 'MAX_EDGE_SLACK = @;'
quoted handouts/task2_shapes.md '@ ε times the size' tests/task2/shape_check.h 'ROUNDING = @ \* FLOAT_EPS'
quoted handouts/task2_shapes.md '@ random rays per shape' tests/task2/test_random_rays.cpp 'constexpr int RAYS = @;'
quoted handouts/task2_shapes.md 'misses / relative error > @' tests/stress/test_sphere_scales.cpp 'got.distance - t\) < @ \* t'

# Task 3: the SAH buckets, the grader's ratios, the BVH view's ramp.
quoted handouts/task3_bvh.md '`B = @` buckets' reference/task3_bvh.cpp 'constexpr int BUCKETS = @;'
quoted handouts/task3_bvh.md 'binned-SAH tree \(@ buckets' reference/task3_bvh.cpp 'constexpr int BUCKETS = @;'
quoted handouts/task3_bvh.md 'at most \*\*@ ×\*\* that of' tests/task3/bvh_quality_test.cpp 'MAX_SAH_RATIO = @;'
quoted handouts/task3_bvh.md 'at most \*\*@ ×\*\* those of' tests/task3/bvh_quality_test.cpp 'MAX_TESTS_RATIO = @;'
quoted handouts/task3_bvh.md 'white \(@ or more\)' framework/render/pathtracer.cpp 'heat_ramp\(nodes / @\)'

# Task 4: the ray offset (1 + max |p_i|) k 2^-24 of spawn_ray (every ray a path spawns), the depth
# where roulette starts in the reference and the NEE integrator, the graders' float allowance and
# samples, the stress suite's significance.
quoted handouts/task4_path.md 'the framework uses k = @' framework/api/spawn_ray.h 'RAY_EPSILON = @ \* 0x'
quoted handouts/task4_path.md '^their own floor again, with k = 4, 83\); @ keeps' framework/api/spawn_ray.h 'RAY_EPSILON = @ \* 0x'
quoted handouts/task4_path.md 'the offset of §4.2 \(k = @\) only' framework/api/spawn_ray.h 'RAY_EPSILON = @ \* 0x'
quoted handouts/task4_path.md '\) · k · @$' framework/api/spawn_ray.h 'RAY_EPSILON = [0-9.]+f \* @;'
quoted handouts/task4_path.md 'which `pathtracer.h` sets to @ in' framework/api/pathtracer.h 'ROULETTE_DEPTH = @;'
quoted handouts/task4_path.md 'share a @ chance of failing' grading/judge/judge.h 'GRADER_ALPHA = @;'
quoted_budget handouts/task4_path.md 'grader.s @ statistical checks' tests/task4
quoted_budget handouts/task4_path.md '0\.99\^\(1/@\)' tests/task4
quoted handouts/task4_path.md 'allowance of @ \(relative\)' tests/support/film_statistics.h 'FLOAT_SLACK = @;'
quoted handouts/task4_path.md '\| @ samples for 5 `out_dir`s' tests/task4/test_lambertian.cpp 'samples = @, chunks'
quoted handouts/task4_path.md 'Šidák over 48 tests at @\)' tests/stress/test_translated_cornell_box.cpp 'sidak\(@, tests\)'

# Task 5: Fresnel's tolerance, the furnaces' allowance and checks, the glass test's samples.
quoted handouts/task5_materials.md '^@ against the exact formula' tests/task5/test_fresnel.cpp 'TOLERANCE = @;'
quoted handouts/task5_materials.md 'beyond the critical angle inside\) to @;' tests/task5/test_fresnel.cpp 'TOLERANCE = @;'
quoted handouts/task5_materials.md 'allowance of @ for' tests/support/film_statistics.h 'FLOAT_SLACK = @;'
quoted handouts/task5_materials.md 'share a @ chance' grading/judge/judge.h 'GRADER_ALPHA = @;'
quoted_budget handouts/task5_materials.md '^@ statistical checks share' tests/task5
quoted_budget handouts/task5_materials.md '0\.99\^\(1/@\)' tests/task5
quoted handouts/task5_materials.md '\| @ samples at each of' tests/task5/test_mirror_glass.cpp 'trials = @;'

# Task 6: the shadow ray's end, the mixture's pdf tolerance and samples, the noise batches, the
# graders' significance and number of checks (task 6 and its NEE extension).
quoted handouts/task6_direct_lighting.md '`SHADOW_RAY_END` = 1 − @\)' framework/api/pathtracer.h 'SHADOW_RAY_END = 1.0f - @;'
quoted handouts/task6_direct_lighting.md 'returned direction to @ \(relative\)' tests/task6/test_sample_incoming.cpp 'abs\(s.pdf - expected\) <= @ \* expected'
quoted handouts/task6_direct_lighting.md '\| @ samples on a tilted surface' tests/task6/test_sample_incoming.cpp 'samples_at\(scene, lit, @, judge::secret_seed_or\(1\)'
quoted handouts/task6_direct_lighting.md 'cut into @ batches' tests/support/sample_moments.h 'NOISE_BATCHES = @;'
quoted_budget handouts/task6_direct_lighting.md '0\.99\^\(1/@\)' tests/task6
quoted_budget handouts/task6_direct_lighting.md 'The @ statistical checks — a z-test' tests/task6_nee
quoted handouts/task6_direct_lighting.md 'share a @ chance of failing a correct solution \(Šidák correction, α' grading/judge/judge.h 'GRADER_ALPHA = @;'
quoted handouts/task6_direct_lighting.md 'share a @ chance of failing a correct solution \(Šidák correction\)\.' grading/judge/judge.h 'GRADER_ALPHA = @;'

# Task 7: the table's bilinear weights, the graders' significance, numbers of tests, batches and bounds.
quoted handouts/task7_env_light.md 'with w = \(@, ' reference/task7_env_light.cpp 'weight\[3\] = \{@, '
quoted handouts/task7_env_light.md 'with w = \([0-9/]+, @, ' reference/task7_env_light.cpp 'weight\[3\] = \{[0-9.]+, @, '
quoted handouts/task7_env_light.md 'share a @ chance of failing' grading/judge/judge.h 'GRADER_ALPHA = @;'
quoted_budget handouts/task7_env_light.md 'The grader.s @$' tests/task7
quoted_budget handouts/task7_env_light.md '0\.99\^\(1/@\)' tests/task7
quoted handouts/task7_env_light.md 'variances of @ batches' tests/support/sample_moments.h 'NOISE_BATCHES = @;'
quoted handouts/task7_env_light.md 'at most @ × the light' tests/task7/test_bright_texel.cpp 'bound = @ \* radiance_integral'
quoted handouts/task7_env_light.md 'luminance · sin θ \(within @\)' tests/task7/test_importance.cpp 'got / expected - 1.0\) <= @\)'

# Task 8: the rule's minimum and batch, where a decision is clear, the render's settings, the
# grader's significance and number of checks.
quoted handouts/task8_adaptive.md '\(`min_samples`, @\)' framework/api/adaptive_sampling.h 'min_samples = @;'
quoted handouts/task8_adaptive.md 'after every batch of @ samples' framework/api/adaptive_sampling.h 'batch = @;'
quoted handouts/task8_adaptive.md 'differ by more than @ of' tests/task8/adaptive_spec.h 'CLEAR = @;'
quoted handouts/task8_adaptive.md '\(threshold @, at most' tests/task8/test_adaptive_render.cpp 'THRESHOLD = @f;'
quoted handouts/task8_adaptive.md 'at most @ samples\)' tests/task8/test_adaptive_render.cpp 'MAX_SAMPLES = @;'
quoted handouts/task8_adaptive.md 'share a @ chance of failing' grading/judge/judge.h 'GRADER_ALPHA = @;'
quoted_budget handouts/task8_adaptive.md 'The grader.s @ statistical checks' tests/task8
quoted_budget handouts/task8_adaptive.md '0\.99\^\(1/@\)' tests/task8

if [ "$failures" -gt 0 ]; then
	echo "handout numbers: $failures of the numbers the handouts quote differ from the code (or were not found)" >&2
	exit 1
fi
echo "handout numbers: $checked numbers quoted by the handouts agree with the code"

#!/usr/bin/env bash
# What ./lab view costs the render it shows (issue 24: at most 5 % of the throughput): the same
# render, SPP samples per pixel of SCENE by the reference renderer,
#   plain:   pathtracer_reference SCENE --spp SPP (writes the PNG)
#   viewer:  lab_viewer --reference-only --max-spp SPP: the renderer streams its film to the viewer
#            after each batch of samples (--stream), the viewer reads and keeps every frame; timed
#            until its state says the render finished (polled every 0.2 s: a page asks far less
#            often, and the polls' own work counts in the viewer's CPU time)
# alternately RUNS times each. Prints each run's wall time and CPU time (user + system, the
# viewer's including its renderer's), their medians as samples per second, and the machine's load.
# The CPU time is the fairer measure on a shared machine: other programs' load lengthens the wall
# time of either run by chance, but not its CPU time.
#
# usage: bench/viewer_overhead.sh BUILD_DIR [SCENE] [SPP] [RUNS] [THREADS]
# (THREADS: render threads, default 0 = all cores; 1 makes the CPU times steadier on a busy machine)
set -euo pipefail
build=$1
scene=${2:-scenes/cornell_box.json}
spp=${3:-128}
runs=${4:-3}
threads=${5:-0}
renderer=$build/tasks/pathtracer_reference
viewer=$build/framework/viewer/lab_viewer
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

now() { date +%s.%N; }

# plain: prints "WALL CPU" in seconds.
plain() {
	/usr/bin/time -f "%e %U %S" -o "$tmp/plain.time" "$renderer" "$scene" --spp "$spp" --threads "$threads" --out "$tmp/plain.png" --quiet
	awk '{ print $1, $2 + $3 }' "$tmp/plain.time"
}

# with_viewer: prints "WALL CPU" in seconds.
with_viewer() {
	local start end url base token time_pid viewer_pid state
	rm -f "$tmp/viewer.out" # (else the last run's URL may be read before the new viewer's)
	start=$(now)
	/usr/bin/time -f "%e %U %S" -o "$tmp/viewer.time" "$viewer" "$scene" --reference-renderer "$renderer" \
		--reference-only --port 0 --max-spp "$spp" --threads "$threads" --out-dir "$tmp" >"$tmp/viewer.out" 2>&1 &
	time_pid=$!
	until url=$(grep -o 'http://[^ ]*' "$tmp/viewer.out" 2>/dev/null); do sleep 0.01; done
	base=${url%/?token=*}
	token=${url#*token=}
	until state=$(curl -s "$base/api/state?token=$token") && grep -q '"state":"finished"' <<<"$state"; do sleep 0.2; done
	end=$(now)
	viewer_pid=$(pgrep -P "$time_pid")
	kill "$viewer_pid"
	wait "$time_pid" || true
	echo "$(echo "$end - $start" | bc) $(awk '{ print $2 + $3 }' "$tmp/viewer.time")"
}

median() { sort -n | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

for ((i = 1; i <= runs; i++)); do
	read -r pw pc < <(plain)
	read -r vw vc < <(with_viewer)
	echo "run $i: plain $pw s (CPU $pc s), with the viewer $vw s (CPU $vc s)"
	echo "$pw $pc $vw $vc" >>"$tmp/runs"
done
pixels=$(python3 -c "import json; f = json.load(open('$scene'))['film']; print(f['width'] * f['height'])")
column() { awk -v c="$1" '{ print $c }' "$tmp/runs" | median; }
report() { # NAME PLAIN VIEWER
	echo "$1: plain $2 s ($(echo "$pixels * $spp / $2 / 1000" | bc) k samples/s), with the viewer $3 s" \
		"($(echo "$pixels * $spp / $3 / 1000" | bc) k samples/s): $(echo "scale=1; 100 * ($3 - $2) / $2" | bc) % more"
}
report "median wall time" "$(column 1)" "$(column 3)"
report "median CPU time" "$(column 2)" "$(column 4)"
echo "load: $(cat /proc/loadavg)"

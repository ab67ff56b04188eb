#!/usr/bin/env bash
# What ./lab view costs the render it shows (issue 24: at most 5 % of the throughput): the same
# render, SPP samples per pixel of SCENE by the reference renderer,
#   plain:   pathtracer_reference SCENE --spp SPP (writes the PNG)
#   viewer:  lab_viewer --reference-only --max-spp SPP: the renderer streams its film to the viewer
#            after each batch of samples (--stream), the viewer reads and keeps every frame; timed
#            until the viewer's event stream says the render finished
#   page:    the same with a client that does what an open page does: on every frame event it
#            fetches the new picture (/api/image, float32 RGB)
# alternately RUNS times each. Prints each run's wall time and CPU time (user + system, the
# viewer's including its renderer's; the client's own is not counted, as a browser's would not
# be), their medians as samples per second, and the machine's load. The CPU time is the fairer
# measure on a shared machine: other programs' load lengthens the wall time of either run by
# chance, but not its CPU time.
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

# The client: follows the viewer's event stream (server-sent events) until the render has
# finished; with "page", fetches the picture after every frame event as the page does.
cat >"$tmp/client.py" <<'PYTHON'
import json, sys, urllib.request
base, token, mode = sys.argv[1:4]
events = urllib.request.urlopen(f"{base}/api/events?token={token}")
name = None
for line in events:
	line = line.decode().rstrip("\n")
	if line.startswith("event: "):
		name = line[len("event: "):]
	elif line.startswith("data: "):
		data = line[len("data: "):]
		if name == "frame" and mode == "page":
			side = json.loads(data)["side"]
			urllib.request.urlopen(f"{base}/api/image?token={token}&side={side}&layer=mean").read()
		if '"state":"finished"' in data:
			break
PYTHON

# with_viewer MODE: prints "WALL CPU" in seconds.
with_viewer() {
	local start end url base token time_pid viewer_pid
	rm -f "$tmp/viewer.out" # (else the last run's URL may be read before the new viewer's)
	start=$(now)
	/usr/bin/time -f "%e %U %S" -o "$tmp/viewer.time" "$viewer" "$scene" --reference-renderer "$renderer" \
		--reference-only --port 0 --max-spp "$spp" --threads "$threads" --out-dir "$tmp" >"$tmp/viewer.out" 2>&1 &
	time_pid=$!
	until url=$(grep -o 'http://[^ ]*' "$tmp/viewer.out" 2>/dev/null); do sleep 0.01; done
	base=${url%/?token=*}
	token=${url#*token=}
	python3 "$tmp/client.py" "$base" "$token" "$1"
	end=$(now)
	viewer_pid=$(pgrep -P "$time_pid")
	kill "$viewer_pid"
	wait "$time_pid" || true
	echo "$(echo "$end - $start" | bc) $(awk '{ print $2 + $3 }' "$tmp/viewer.time")"
}

median() { sort -n | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

for ((i = 1; i <= runs; i++)); do
	read -r pw pc < <(plain)
	read -r vw vc < <(with_viewer viewer)
	read -r gw gc < <(with_viewer page)
	echo "run $i: plain $pw s (CPU $pc s), viewer $vw s (CPU $vc s), viewer and page $gw s (CPU $gc s)"
	echo "$pw $pc $vw $vc $gw $gc" >>"$tmp/runs"
done
pixels=$(python3 -c "import json; f = json.load(open('$scene'))['film']; print(f['width'] * f['height'])")
column() { awk -v c="$1" '{ print $c }' "$tmp/runs" | median; }
report() { # NAME PLAIN VIEWER
	echo "$1: plain $2 s ($(echo "$pixels * $spp / $2 / 1000" | bc) k samples/s), with the viewer $3 s" \
		"($(echo "$pixels * $spp / $3 / 1000" | bc) k samples/s): $(echo "scale=1; 100 * ($3 - $2) / $2" | bc) % more"
}
report "viewer, median wall time" "$(column 1)" "$(column 3)"
report "viewer, median CPU time" "$(column 2)" "$(column 4)"
report "viewer and page, median wall time" "$(column 1)" "$(column 5)"
report "viewer and page, median CPU time" "$(column 2)" "$(column 6)"
echo "load: $(cat /proc/loadavg)"

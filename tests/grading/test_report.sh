#!/usr/bin/env bash
# The grade report (label report): `./lab report` on this tree's student build, i.e. the shipped
# stubs, so every task fails; then the page in headless Chromium, opened from disk as a student
# would open it:
#   (a) its DOM shows every task 1-7 with its status (FAIL) and failure messages, in the summary
#       and in its own section with the three images of its reference-image test, and every image
#       decodes;
#   (b) loading it logs nothing to the console and fetches no other file: the page has no script
#       and embeds its images, so any console message (an error, an uncaught exception) or any file
#       fetch (a resource that may fail to load) is a defect;
#   (c) a screenshot is a real render of it: many colours, the FAIL badge's red, and the heat map's
#       "too dark" blue (the stubs render black where the reference does not).
# The detectors of (a) and (b) are first shown to catch a broken page. The screenshot is kept as
# BUILD_DIR/tests/grading/report_screenshot.png.
#
# usage: test_report.sh REPOSITORY_ROOT BUILD_DIR CHECK_SCREENSHOT
set -euo pipefail

root=$1
build=$2
check_screenshot=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "report test: $*" >&2; exit 1; }

command -v chromium >/dev/null ||
	fail "chromium is missing: install the Debian package chromium (./lab test installs it)"

# browse NAME ARGS...: Chromium headless, with a fresh profile and no network; its log goes to
# $tmp/NAME.log (--v=1 logs console messages as :CONSOLE lines and each file fetch).
browse() {
	local name=$1
	shift
	chromium --headless --no-sandbox --disable-gpu --disable-dev-shm-usage --no-first-run \
		--disable-background-networking --disable-component-update --disable-sync --disable-quic \
		--user-data-dir="$tmp/profile-$name" --enable-logging=stderr --v=1 "$@" 2>"$tmp/$name.log"
}

# console_problems NAME PAGE: the log lines of console messages and of fetches of other files than PAGE.
console_problems() {
	grep -F ':CONSOLE' "$tmp/$1.log" || true
	grep -F 'FileURLLoader::Start: ' "$tmp/$1.log" | grep -vF "FileURLLoader::Start: file://$2" || true
}

# probe NAME PAGE: PAGE with a script appended that writes, once it has loaded, "images: N, broken:
# B" into the DOM (B images did not decode); prints that text.
probe() {
	local script='<script>addEventListener("load", () => { const all = [...document.images];
		const broken = all.filter(i => !(i.complete \&\& i.naturalWidth > 0));
		document.body.insertAdjacentHTML("beforeend", `<p>images: ${all.length}, broken: ${broken.length}</p>`); });
		</script></body>'
	sed "s|</body>|$(echo "$script" | tr '\n' ' ')|" "$2" >"$tmp/$1-probe.html"
	browse "$1" --dump-dom "file://$tmp/$1-probe.html" | grep -oE 'images: [0-9]+, broken: [0-9]+' || true
}

# The detectors catch a broken page: a console message, an uncaught exception, a missing file and
# an image that does not decode.
cat >"$tmp/broken.html" <<'PAGE'
<!DOCTYPE html><html><head><meta charset="utf-8"><title>broken</title></head><body>
<img src="missing.png" alt="a missing file"><img src="data:image/png;base64,AAAA" alt="not a PNG">
<script>console.log("hello"); undefined_function();</script></body></html>
PAGE
[ "$(probe broken "$tmp/broken.html")" = "images: 2, broken: 2" ] || fail "the image probe misses broken images"
problems=$(console_problems broken "$tmp/broken.html")
for expected in '"hello"' 'Uncaught ReferenceError' 'missing.png'; do
	grep -qF "$expected" <<<"$problems" || fail "the console check misses $expected on a broken page: $problems"
done

# The report of the stubs.
LAB_BUILD_DIR=$build "$root/lab" report "$tmp/report" >"$tmp/lab.out" 2>"$tmp/lab.err" ||
	{ tail -30 "$tmp/lab.err" >&2; fail "./lab report failed"; }
page=$tmp/report/index.html
[ "$(tail -1 "$tmp/lab.out")" = "$page" ] || fail "./lab report did not print the page's path: $(cat "$tmp/lab.out")"
cat "$tmp/lab.err"

# (a) The DOM: every task with its status, messages and images; (b) no console message, no fetch.
browse page --dump-dom "file://$page" >"$tmp/dom.html"
problems=$(console_problems page "$page")
[ -z "$problems" ] || fail "loading the page logged console messages or fetched files: $problems"
images=$(grep -o '<img src="data:image/png;base64,' "$tmp/dom.html" | wc -l)
for n in 1 2 3 4 5 6 7; do
	grep -qE "<tr><td><a href=\"#task$n\">Task $n: [^<]*</a></td><td><span class=\"badge FAIL\">FAIL</span>" \
		"$tmp/dom.html" || fail "the summary does not show task $n as FAIL"
	section=$(sed -n "/<section id=\"task$n\">/,/<\/section>/p" "$tmp/dom.html")
	grep -qF "<h2><span class=\"badge FAIL\">FAIL</span> Task $n: " <<<"$section" ||
		fail "the section of task $n is missing or does not show FAIL"
	grep -qF 'class="message"' <<<"$section" || fail "task $n shows no failure message"
	for caption in 'Your render of' 'The reference image' 'Where they differ'; do
		grep -qF "<figcaption>$caption" <<<"$section" || fail "task $n has no image captioned '$caption'"
	done
	[ "$(grep -o '<img src="data:image/png;base64,' <<<"$section" | wc -l)" -ge 3 ] ||
		fail "task $n shows fewer than 3 embedded images"
done
[ "$(probe probe "$page")" = "images: $images, broken: 0" ] || fail "some of the $images images do not decode"
echo "report test: every task is shown failing, with messages and $images images that decode; no console message"

# (c) The screenshot: FAIL badges #cf222e, the heat map's too-dark blue #2166ac.
browse shot --screenshot="$tmp/shot.png" --window-size=1280,2000 "file://$page" >/dev/null
"$check_screenshot" "$tmp/shot.png" 64 cf222e 2166ac || fail "the screenshot is not a render of the report"
cp "$tmp/shot.png" "$build/tests/grading/report_screenshot.png"
echo "report test: the screenshot shows the page (kept as $build/tests/grading/report_screenshot.png)"

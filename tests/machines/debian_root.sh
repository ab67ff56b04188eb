# Sourced by the tests that run the lab in a fresh Debian root (tests/machines/): make one with
# debootstrap, add a student, enter it. Needs root and the host's debootstrap.
#
#   make_root SUITE DIR LOG         a minimal Debian SUITE (bookworm, trixie) in DIR, with git and sudo
#   add_student DIR                 the user "student" (uid 1000), who may use sudo without a password,
#                                   as the owner of a laptop may
#   in_root MODE DIR COMMAND...     runs COMMAND in DIR as root, with a clean environment, in a mount
#                                   namespace of its own (nothing stays mounted afterwards). MODE:
#     machine    DIR becomes the namespace's root (pivot_root), as on a Debian machine: bubblewrap
#                can make its namespaces there
#     container  DIR is entered with chroot, where the kernel refuses new user namespaces, as most
#                Docker containers do: bubblewrap cannot start
#   student MODE DIR SCRIPT         runs the bash SCRIPT as the student, in ~/lab (in_root's MODE)
#   view_page MODE DIR PORT LOG     `./lab view --port PORT` as the student: waits for its URL (it
#                                   builds first), prints the page curl fetches there, stops it

make_root() {
	local suite=$1 dir=$2 log=$3
	rm -rf "$dir"
	mkdir -p "$dir"
	debootstrap --variant=minbase --include=git,sudo,ca-certificates "$suite" "$dir" http://deb.debian.org/debian \
		>"$log" 2>&1 || { tail -20 "$log" >&2; return 1; }
}

add_student() {
	in_root machine "$1" useradd --create-home --uid 1000 --shell /bin/bash student
	echo "student ALL=(ALL) NOPASSWD: ALL" >"$1/etc/sudoers.d/student"
	chmod 440 "$1/etc/sudoers.d/student"
}

in_root() {
	local mode=$1 dir=$2
	shift 2
	cp /etc/resolv.conf "$dir/etc/resolv.conf"
	unshare --mount --fork -- bash -c '
		set -e
		mode=$1 dir=$2
		shift 2
		mount --make-rprivate /
		mount --bind "$dir" "$dir"
		mount -t proc proc "$dir/proc"
		mount -t sysfs sys "$dir/sys"
		mount --rbind /dev "$dir/dev"
		clean=(env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8)
		if [ "$mode" = container ]; then
			exec chroot "$dir" "${clean[@]}" "$@"
		fi
		cd "$dir"
		mkdir -p .host
		pivot_root . .host
		umount -l /.host
		rmdir /.host
		exec "${clean[@]}" "$@"' bash "$mode" "$dir" "$@"
}

student() {
	in_root "$1" "$2" runuser -u student -- env HOME=/home/student PATH=/usr/bin:/bin LANG=C.UTF-8 \
		bash -c "cd ~/lab || exit; $3"
}

view_page() {
	local mode=$1 dir=$2 port=$3 log=$4 url='' viewer
	rm -f "$dir/home/student/view.pid"
	student "$mode" "$dir" "./lab view --port $port & echo \$! >~/view.pid; wait" >"$log" 2>&1 &
	viewer=$!
	for _ in $(seq 900); do
		url=$(grep -o 'http://127\.0\.0\.1:[0-9]*/?token=[A-Za-z0-9_-]*' "$log" || true)
		[ -z "$url" ] && kill -0 "$viewer" 2>/dev/null || break
		sleep 1
	done
	[ -z "$url" ] || curl -fsS --max-time 20 "$url" || true
	[ ! -s "$dir/home/student/view.pid" ] || kill "$(cat "$dir/home/student/view.pid")" 2>/dev/null || true
	wait "$viewer" || true
}

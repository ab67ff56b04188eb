#!/usr/bin/env bash
# The class on Slurm (label slurm): a real one-node cluster (munge, slurmctld, slurmd from Debian's
# slurm-wlm and munge) started on this machine in a scratch folder, the per-submission command as a
# job array (sbatch --array --wait), then the gradebook, which must equal grade-class's
# (test_class.sh). The cluster is stopped afterwards, also when the test fails. If a daemon cannot
# start here, the test fails with the daemon's own log.
#   test_slurm.sh REPOSITORY_ROOT KIT OUT
set -euo pipefail
root=$1 kit=$2 out=$3
fail() { echo "Slurm test: $*" >&2; exit 1; }
for program in munged slurmctld slurmd sbatch scontrol; do
	command -v "$program" >/dev/null || fail "$program is not installed (Debian packages slurm-wlm and munge)"
done
[ -f "$out/gradebook.csv" ] || fail "no gradebook from grade-class in $out (run the class test first)"
dest=$out/slurm
cluster=$out/slurm-cluster
rm -rf "$dest" "$cluster"
mkdir -p "$dest/submissions" "$dest/logs" "$cluster"/{state,spool,log,munge}
host=$(hostname -s)

# munge: its own key and socket.
head -c 1024 /dev/urandom >"$cluster/munge/munge.key"
chmod 400 "$cluster/munge/munge.key"
stop() {
	SLURM_CONF=$cluster/slurm.conf scontrol shutdown >/dev/null 2>&1 || true
	[ -f "$cluster/munge/munged.pid" ] && kill "$(cat "$cluster/munge/munged.pid")" 2>/dev/null || true
}
trap stop EXIT
munged --force --key-file="$cluster/munge/munge.key" --socket="$cluster/munge/munge.socket" \
	--pid-file="$cluster/munge/munged.pid" --log-file="$cluster/munge/munged.log" \
	--seed-file="$cluster/munge/munged.seed" || fail "munged did not start: $(cat "$cluster/munge/munged.log")"

port=$((20000 + RANDOM % 20000))
cat >"$cluster/slurm.conf" <<CONF
ClusterName=lab
SlurmctldHost=$host
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
AuthInfo=socket=$cluster/munge/munge.socket
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$cluster/state
SlurmdSpoolDir=$cluster/spool
SlurmctldPidFile=$cluster/slurmctld.pid
SlurmdPidFile=$cluster/slurmd.pid
SlurmctldLogFile=$cluster/log/slurmctld.log
SlurmdLogFile=$cluster/log/slurmd.log
ReturnToService=2
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=lab Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$cluster/slurm.conf
slurmctld -f "$SLURM_CONF" || fail "slurmctld did not start: $(tail -5 "$cluster/log/slurmctld.log")"
slurmd -f "$SLURM_CONF" || fail "slurmd did not start: $(tail -5 "$cluster/log/slurmd.log")"
for _ in $(seq 30); do
	grep -q idle <<<"$(sinfo -h -o %t 2>/dev/null)" && break
	sleep 1
done
grep -q idle <<<"$(sinfo -h -o %t)" || fail "the node did not come up: $(tail -5 "$cluster/log/slurmd.log")"
echo "Slurm test: a one-node cluster is up: $(sinfo -h -o '%P %D %t %N')"

# The job array: task i grades the i-th submission with the lab's own command.
mapfile -t submissions < <(find "$out/class/submissions" -mindepth 1 -maxdepth 1 -type d | sort)
printf '%s\n' "${submissions[@]}" >"$cluster/submissions.txt"
cat >"$cluster/grade.sbatch" <<JOB
#!/bin/bash
submission=\$(sed -n "\$((SLURM_ARRAY_TASK_ID + 1))p" "$cluster/submissions.txt")
id=\$(basename "\$submission")
LAB_BUILD_DIR=${kit%/grading/kit.env} "$root/lab" grade-submission "\$submission" --out "$dest/submissions/\$id" \\
	>"$dest/logs/\$id.log" 2>&1 || echo failed >"$dest/logs/\$id.error"
JOB
start=$SECONDS
sbatch --wait --array="0-$((${#submissions[@]} - 1))" --output="$cluster/log/job_%A_%a.out" \
	--job-name=lab-grading "$cluster/grade.sbatch" >"$cluster/sbatch.log" 2>&1 ||
	fail "sbatch failed: $(cat "$cluster/sbatch.log")"
echo "Slurm test: $(head -1 "$cluster/sbatch.log"), ${#submissions[@]} array tasks, done in $((SECONDS - start)) s"
cp "$cluster/log/slurmctld.log" "$dest/slurmctld.log"
"$root/grading/bin/gradebook" "$dest" >/dev/null
cmp -s "$out/gradebook.csv" "$dest/gradebook.csv" ||
	{ diff "$out/gradebook.csv" "$dest/gradebook.csv" | head >&2; fail "the gradebook differs from grade-class's"; }
echo "Slurm test: the gradebook equals grade-class's"

#!/usr/bin/env bash
# A sweep run by Slurm: a one-node Slurm (Debian's slurmctld, slurmd and munge, configured and started here in
# a temporary folder on localhost, stopped on exit) runs the job array `selfsim sweep --slurm` writes, then its
# collect job; the results equal a local sweep's byte for byte.
# Skipped (exit 77) unless root with slurmctld, slurmd, munged and sbatch installed (Debian: slurmctld slurmd
# slurm-client munge).
# Nothing system-wide is touched: the munge key, socket, Slurm's configuration, state, logs and ports are
# this test's own.
# usage: check_slurm.sh SELFSIM SOURCE_DIR
set -uo pipefail
selfsim=$(realpath "$1")
if [ "$(id -u)" != 0 ]; then
  echo "skipped: the one-node Slurm test runs its daemons as root"
  exit 77
fi
PATH=$PATH:/usr/sbin
for tool in slurmctld slurmd munged sbatch squeue scancel scontrol sinfo; do
  if ! command -v "$tool" >/dev/null; then
    echo "skipped: $tool not installed (Debian: slurmctld slurmd slurm-client munge)"
    exit 77
  fi
done

tmp=$(mktemp -d)
pids=() # munged, slurmctld, slurmd: the daemons this test started
array='' collect='' # the job ids, once submitted
stop_pid() {
  local i
  kill -TERM "$1" 2>/dev/null || return 0
  for i in $(seq 100); do kill -0 "$1" 2>/dev/null || break; sleep 0.1; done
  kill -KILL "$1" 2>/dev/null
  wait "$1" 2>/dev/null
}
# On exit: this test's jobs cancelled, its daemons stopped (last started first), and any slurmstepd of its
# slurmd (known by the SLURM_CONF it inherited) gone; only processes this test started, by their ids.
stop_all() {
  local i pid
  if [ -n "$array$collect" ]; then
    scancel ${array:+"$array"} ${collect:+"$collect"} 2>/dev/null
    wait_for 10 jobs_gone 2>/dev/null
  fi
  for ((i = ${#pids[@]} - 1; i >= 0; i--)); do stop_pid "${pids[i]}"; done
  for pid in $(pgrep -x slurmstepd); do
    grep -qzx "SLURM_CONF=$tmp/slurm/slurm.conf" "/proc/$pid/environ" 2>/dev/null && stop_pid "$pid"
  done
  rm -rf "$tmp"
}
trap stop_all EXIT
trap 'exit 130' INT TERM
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# Waits up to $1 seconds for the command after it to succeed.
wait_for() {
  local limit=$1 i
  shift
  for i in $(seq $((limit * 10))); do "$@" && return 0; sleep 0.1; done
  "$@"
}
jobs_gone() { [ -z "$(squeue -h -j "$array,$collect" -o %i 2>/dev/null)" ]; }
show_logs() {
  local f
  for f in "$tmp"/munge/out.txt "$tmp"/slurm/slurmctld.log "$tmp"/slurm/slurmd.log; do
    [ -f "$f" ] && { echo "--- $f"; tail -15 "$f"; }
  done
}
cd "$tmp" || exit 1

# munge: a fresh key, and a daemon on its own socket. --force: the socket's folder is root's alone, which
# munged warns about (other users could not reach it) and refuses without it.
mkdir -m 700 munge
dd if=/dev/urandom of=munge/munge.key bs=1024 count=1 status=none
chmod 400 munge/munge.key
munged --foreground --force --socket="$tmp/munge/socket" --key-file="$tmp/munge/munge.key" \
  --pid-file="$tmp/munge/munged.pid" --log-file="$tmp/munge/munged.log" --seed-file="$tmp/munge/munged.seed" \
  >munge/out.txt 2>&1 &
pids+=($!)
if ! wait_for 10 test -S munge/socket; then
  fail "munged did not start"; show_logs; exit 1
fi

# Two free TCP ports for slurmctld and slurmd, so that a system Slurm (if any) is left alone.
read -r ctld_port node_port < <(/usr/bin/python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*[x.getsockname()[1] for x in s])')
host=$(hostname -s)
mkdir -p slurm/state slurm/spool
cat >slurm/slurm.conf <<CONF
ClusterName=selfsimtest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$node_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$tmp/munge/socket
StateSaveLocation=$tmp/slurm/state
SlurmdSpoolDir=$tmp/slurm/spool
SlurmctldPidFile=$tmp/slurm/slurmctld.pid
SlurmdPidFile=$tmp/slurm/slurmd.pid
SlurmctldLogFile=$tmp/slurm/slurmctld.log
SlurmdLogFile=$tmp/slurm/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/backfill
# A job may start as soon as the one before it ends, not 3 s later.
SchedulerParameters=batch_sched_delay=0
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MailProg=/bin/true
MpiDefault=none
# The node is what this file says (nproc CPUs), whatever slurmd finds in a container.
SlurmdParameters=config_overrides
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$tmp/slurm/slurm.conf
slurmctld -D -c -f "$SLURM_CONF" >slurm/slurmctld.out 2>&1 &
pids+=($!)
slurmd -D -N "$host" -f "$SLURM_CONF" >slurm/slurmd.out 2>&1 &
pids+=($!)
node_idle() { [ "$(sinfo -h -n "$host" -o %t 2>/dev/null)" = idle ]; }
if ! wait_for 60 node_idle; then
  fail "the node never became idle: $(sinfo 2>&1)"; show_logs; exit 1
fi

cat >d.lua <<'LUA'
local curves = require "selfsim.curves"
local level = param("level", 6, { min = 1, max = 16 })
local name = param("name", "dragon", { choices = { "dragon", "terdragon" } })
local c = curves[name]():curve(level)
result("points", c:points())
save(c, "c.svg")
save(c, "c.vtp")
LUA
sets=(--set "level=2..5" --set "name=dragon,terdragon")

# The array and its collect job, submitted with the very command selfsim prints.
"$selfsim" sweep d.lua -o sl "${sets[@]}" --slurm sweep.sbatch >out.txt 2>err.txt || fail "sweep --slurm: $(cat err.txt)"
submit=$(sed -n 's/^  submit: //p' out.txt)
[ "$submit" = "jid=\$(sbatch --parsable $tmp/sl/sweep.sbatch) && sbatch --dependency=afterany:\$jid $tmp/sl/collect-sweep.sbatch" ] ||
  fail "submit command: $(cat out.txt)"
bash -c "$submit; echo \"array \$jid\"" >submit.txt 2>&1 || fail "submitting: $(cat submit.txt)"
array=$(sed -n 's/^array //p' submit.txt)
collect=$(sed -n 's/^Submitted batch job //p' submit.txt)
if [ -z "$array" ] || [ -z "$collect" ]; then fail "job ids: $(cat submit.txt)"; fi
# Both jobs end (they leave the queue) within a minute.
if ! wait_for 60 jobs_gone; then
  fail "jobs still queued: $(squeue 2>&1)"; show_logs
fi
state() { scontrol show job "$1" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | sort -u | tr '\n' ' '; }
[ "$(state "$collect")" = "JobState=COMPLETED " ] || fail "collect job: $(state "$collect"); $(cat sl/slurm/collect.out 2>&1)"
[ "$(state "$array")" = "JobState=COMPLETED " ] || fail "array job: $(state "$array")"
logs=(sl/slurm/run-*.out)
[ "${#logs[@]}" = 8 ] || fail "8 array task logs expected: ${logs[*]}"
runs=(sl/level=*)
[ "${#runs[@]}" = 8 ] || fail "8 run folders expected: ${runs[*]}"
for dir in "${runs[@]}"; do
  [ "$(cat "$dir/selfsim.exit" 2>/dev/null)" = 0 ] || fail "$dir/selfsim.exit: $(cat "$dir/selfsim.log" 2>&1)"
done
[ -f sl/sheet_c.svg ] || fail "the collect job wrote no sheet_c.svg: $(cat sl/slurm/collect.out 2>&1)"
[ -f sl/c_sweep.pvd ] || fail "the collect job wrote no c_sweep.pvd"
# results.csv: a row per run, each the run's number of points (2^level + 1 for both curves).
/usr/bin/python3 - sl <<'PY' || fail "the collect job's results.csv: $(cat sl/results.csv 2>&1)"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1] + "/results.csv", newline="")))
assert [(r["level"], r["name"]) for r in rows] == [(str(l), n) for l in range(2, 6) for n in ("dragon", "terdragon")]
for r in rows:
    assert r["status"] == "ok" and r["folder"] == "level=%s,name=%s" % (r["level"], r["name"]), r
    assert int(r["points"]) == (2 ** int(r["level"]) if r["name"] == "dragon" else 3 ** int(r["level"])) + 1, r
PY

# The same sweep here: the same bytes but for the runs' logs, the job list, the Slurm scripts and their logs;
# each run's view.py names its own folder and is otherwise the same.
"$selfsim" run d.lua -o lo "${sets[@]}" --jobs 2 -q || fail "local sweep"
diff -r -x selfsim.log -x jobs.txt -x view.py -x slurm -x '*.sbatch' lo sl >diff.txt ||
  fail "Slurm's sweep differs from the local one: $(head -5 diff.txt)"
for dir in lo/level=*; do
  run=${dir#lo/}
  sed "s|\"$tmp/lo/$run\"|\"$tmp/sl/$run\"|" "$dir/view.py" | cmp -s - "sl/$run/view.py" || fail "sl/$run/view.py differs"
done

# An output folder holding %j and %a: its #SBATCH lines double each '%', which Slurm reads back as one, so
# every log lands in that very folder (not in one named after the job or the task, which does not exist).
pct='p%j%a'
"$selfsim" sweep d.lua -o "$pct" --set level=2,3 --slurm s.sbatch >out.txt 2>err.txt || fail "sweep -o $pct: $(cat err.txt)"
submit=$(sed -n 's/^  submit: //p' out.txt)
bash -c "$submit; echo \"array \$jid\"" >submit.txt 2>&1 || fail "submitting $pct: $(cat submit.txt)"
array=$(sed -n 's/^array //p' submit.txt)
collect=$(sed -n 's/^Submitted batch job //p' submit.txt)
if [ -z "$array" ] || [ -z "$collect" ]; then fail "job ids of $pct: $(cat submit.txt)"; fi
wait_for 60 jobs_gone || fail "$pct: jobs still queued: $(squeue 2>&1)"
[ "$(state "$array")" = "JobState=COMPLETED " ] || fail "$pct: array job: $(state "$array")"
[ "$(state "$collect")" = "JobState=COMPLETED " ] || fail "$pct: collect job: $(state "$collect")"
for f in run-0.out run-1.out collect.out; do [ -f "$pct/slurm/$f" ] || fail "no $pct/slurm/$f: $(ls "$pct/slurm")"; done
[ -f "$pct/sheet_c.svg" ] || fail "$pct: the collect job wrote no sheet_c.svg"
# One number varies there: the collect job plots the result against it.
[ "$(grep -c '<circle ' "$pct/plot_points.svg" 2>/dev/null)" = 2 ] || fail "$pct: the collect job's plot: $(ls "$pct")"

echo "$failures failures"
[ "$failures" = 0 ]

#!/usr/bin/env bash
# A sweep's job list and Slurm scripts hand paths and values to a shell. Whatever bytes the recipe's path,
# the output folder and the --set values hold ($( ), backticks, ;, quotes, a leading -, non-UTF-8), each line
# run by bash (as the Slurm script runs it, and by GNU parallel when installed) runs exactly its own run and
# nothing else; a line break, which no line can hold, is refused before anything is written.
# usage: check_job_lines.sh SELFSIM SOURCE_DIR
# shellcheck source=tests/cli/test_lib.sh
source "$(dirname "$0")/test_lib.sh"
selfsim=$(realpath "$selfsim")
cd "$tmp" || exit 1

# The recipe in a folder, and the output folder, named with every kind of payload (the output folder holds
# no '"': an #SBATCH line cannot, which the sweep says itself).
dir=$'d $(touch PWNED1) `touch PWNED2`; touch PWNED3 \'q\' "dq" \xff\xfe'
out=$'o $(touch PWNED4) `touch PWNED5`; touch PWNED6 \'q\' \xff'
mkdir -p "$dir"
recipe="$dir/-r \$x;.lua"
cat >"$recipe" <<'LUA'
local v = param("v", "x")
print("v=[" .. v .. "]")
result("bytes", #v)
save(polyline({ { 0, 0 }, { 1, 1 } }), "p.svg")
LUA
values=('$(touch PWNED7)' '`touch PWNED8`' 'a;touch PWNED9' "it's" '"q"' '-rf' $'\xff\xfe' '$HOME' 'a b')
printf '%s\0' "${values[@]}" >want.bin
list=$(IFS=,; echo "${values[*]}")

# Checks that every run in $out ran once with its own value, exit 0, and that no payload ran.
check_runs() {
  /usr/bin/python3 - "$out" want.bin "$1" <<'PY' || fail "$1: the runs did not each get their own value"
import os, sys
out, want, how = os.fsencode(sys.argv[1]), open(sys.argv[2], "rb").read().split(b"\0")[:-1], sys.argv[3]
got = []
for d in sorted(os.listdir(out)):
    if not d.startswith(b"v="): continue
    log = open(os.path.join(out, d, b"selfsim.log"), "rb").read()
    code = open(os.path.join(out, d, b"selfsim.exit"), "rb").read()
    if code != b"0\n": print("%s: %r exit %r: %r" % (how, d, code, log)); sys.exit(1)
    got.append(log.split(b"v=[", 1)[1].split(b"]\n", 1)[0])
if sorted(got) != sorted(want): print("%s: values %r, expected %r" % (how, got, want)); sys.exit(1)
PY
  [ -z "$(find "$tmp" -name 'PWNED*')" ] || fail "$1: a payload ran: $(find "$tmp" -name 'PWNED*')"
}

"$selfsim" sweep "$recipe" -o "$out" --set "v=$list" --jobs-file jobs.txt --slurm sweep.sbatch >o.txt 2>e.txt ||
  fail "sweep --jobs-file --slurm: $(cat e.txt)"
[ "$(wc -l <"$out/jobs.txt")" = "${#values[@]}" ] || fail "jobs.txt should have ${#values[@]} lines"
# Each line by bash, one at a time.
while IFS= read -r line; do bash -c "$line" </dev/null || fail "bash -c: $line"; done <"$out/jobs.txt"
check_runs "bash"
# Each array task of the Slurm script, by bash without Slurm; then its collect script.
rm -rf "$out"/v=*
for ((i = 0; i < ${#values[@]}; i++)); do
  SLURM_ARRAY_TASK_ID=$i bash "$out/sweep.sbatch" || fail "array task $i"
done
check_runs "sweep.sbatch"
[ "$(wc -l <"$out/sweep.sbatch")" = 8 ] || fail "sweep.sbatch should have 8 lines: $(cat "$out/sweep.sbatch")"
bash "$out/collect-sweep.sbatch" >c.txt 2>&1 || fail "collect-sweep.sbatch: $(cat c.txt)"
[ "$(grep -c '<image ' "$out/sheet_p.svg")" = "${#values[@]}" ] || fail "the collect script's sheet"
[ -z "$(find "$tmp" -name 'PWNED*')" ] || fail "collect: a payload ran"
# results.csv holds each run's value byte for byte, quoted for CSV where it must be, beside its result.
/usr/bin/python3 - "$out" want.bin <<'PY' || fail "the collect script's results.csv: $(cat "$out/results.csv")"
import csv, os, sys
want = open(sys.argv[2], "rb").read().split(b"\0")[:-1]
text = open(os.path.join(os.fsencode(sys.argv[1]), b"results.csv"), "rb").read().decode("utf-8", "surrogateescape")
rows = list(csv.reader(text.splitlines(keepends=True)))
assert rows[0] == ["v", "bytes", "status", "folder"], rows[0]
got = sorted((r[0].encode("utf-8", "surrogateescape"), r[1], r[2]) for r in rows[1:])
assert got == sorted((v, str(len(v)), "ok") for v in want), got
PY
if command -v parallel >/dev/null; then
  rm -rf "$out"/v=*
  parallel --will-cite --jobs 2 <"$out/jobs.txt" || fail "parallel ran the job list with failures"
  check_runs "parallel"
else
  echo "note: GNU parallel not installed; the job list was run by bash only"
fi

# A line break in the recipe's path or in a value: refused, naming it, and nothing written.
mkdir -p $'n\nl'
cp "$recipe" $'n\nl/r.lua'
for flag in --jobs-file --slurm; do
  "$selfsim" sweep $'n\nl/r.lua' -o nl1 --set v=a,b "$flag" x.txt >o.txt 2>e.txt
  [ $? = 2 ] || fail "$flag: a recipe path with a line break should be refused"
  grep -qF "selfsim: the recipe's path '$tmp/n\\nl/r.lua' holds a line break" e.txt || fail "message: $(cat e.txt)"
  "$selfsim" sweep "$recipe" -o nl2 --set $'v=a\nb,c' "$flag" x.txt >o.txt 2>e.txt
  [ $? = 2 ] || fail "$flag: a value with a line break should be refused"
  grep -qF "selfsim: --set 'v=a\\nb,c' holds a line break" e.txt || fail "message: $(cat e.txt)"
done
[ -e nl1 ] || [ -e nl2 ] && fail "a refused job list wrote its output folder"
# The output folder in the scripts' #SBATCH --output lines, which sbatch reads itself: Slurm expands %j, %a,
# ... in a file name and reads %% as %, so each '%' is doubled (quotes, '#' and spaces sit inside the quoting).
here=$(pwd -P)
pct=$'p %j 100% \'q\' #x'
"$selfsim" sweep "$recipe" -o "$pct" --set v=a,b --slurm s.sbatch >o.txt 2>e.txt ||
  fail "--slurm with a '%' in the output folder: $(cat e.txt)"
logs="$here/$(printf '%s' "$pct" | sed 's/%/%%/g')/slurm"
grep -qxF "#SBATCH --output=\"$logs/run-%a.out\"" "$pct/s.sbatch" ||
  fail "the array's log line: $(grep SBATCH "$pct/s.sbatch")"
grep -qxF "#SBATCH --output=\"$logs/collect.out\"" "$pct/collect-s.sbatch" ||
  fail "the collect job's log line: $(grep SBATCH "$pct/collect-s.sbatch")"
# sbatch -v prints the options it read from the script before it tries to reach a controller (here one that
# is not there: a port nothing listens on, 1 s a try), so its own reading of the line is checked where it is
# installed (Slurm's expansion of %% on a node is checked by cli.slurm).
if command -v sbatch >/dev/null; then
  port=$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
  printf '%s\n' ClusterName=joblines SlurmctldHost=localhost "SlurmctldPort=$port" AuthType=auth/none \
    CredType=cred/none MessageTimeout=1 TCPTimeout=1 'NodeName=localhost CPUs=1' \
    'PartitionName=p Nodes=localhost Default=YES' >slurm.conf
  SLURM_CONF=$here/slurm.conf timeout 60 sbatch -v --test-only "$pct/s.sbatch" >sbatch.txt 2>&1 </dev/null
  if grep -q '^sbatch: end of defined options' sbatch.txt; then
    [ "$(sed -n 's/^sbatch: output *: //p' sbatch.txt)" = "$logs/run-%a.out" ] ||
      fail "sbatch read the log line as: $(grep 'output' sbatch.txt)"
  else
    echo "note: sbatch printed no options here, so only the line's text was checked: $(tail -1 sbatch.txt)"
  fi
else
  echo "note: sbatch not installed; the #SBATCH lines were checked as text only"
fi
# A '\' is an escape to sbatch and, in a file name, turns off Slurm's %a (every task would write one log),
# and a '"' would end the quoting: an output folder holding either is refused for --slurm before anything is
# written, naming what it holds; --jobs-file alone takes them.
for bad in 'b\s' 'b"q'; do
  "$selfsim" sweep "$recipe" -o "$bad" --set v=a,b --slurm s.sbatch >o.txt 2>e.txt
  [ $? = 2 ] || fail "--slurm: an output folder holding ${bad:1:1} should be refused"
  grep -qF "selfsim: --slurm: the output folder's path holds a '${bad:1:1}', which" e.txt ||
    fail "--slurm, ${bad:1:1}: $(cat e.txt)"
  [ -e "$bad" ] && fail "--slurm: a refused output folder holding ${bad:1:1} was written"
  "$selfsim" sweep "$recipe" -o "$bad" --set v=a,b --jobs-file jobs.txt >o.txt 2>e.txt ||
    fail "--jobs-file with ${bad:1:1} in the output folder: $(cat e.txt)"
done

# A sweep run here passes them as arguments, with no shell: both reach their runs whole.
"$selfsim" run $'n\nl/r.lua' -o loc --set $'v=a\nb,c' -q || fail "a local sweep with line breaks"
[ "$(head -2 loc/v=a_b/selfsim.log)" = $'v=[a\nb]' ] || fail "the value with a line break reached its run whole"

finish

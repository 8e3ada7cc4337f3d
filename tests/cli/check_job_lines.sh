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
# A sweep run here passes them as arguments, with no shell: both reach their runs whole.
"$selfsim" run $'n\nl/r.lua' -o loc --set $'v=a\nb,c' -q || fail "a local sweep with line breaks"
[ "$(head -2 loc/v=a_b/selfsim.log)" = $'v=[a\nb]' ] || fail "the value with a line break reached its run whole"

finish

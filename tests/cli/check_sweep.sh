#!/usr/bin/env bash
# Sweeps: one run per combination of --set values, each in its own folder, N at a time; failures reported
# while the others go on; Ctrl-C stops all; a job list that GNU parallel runs gives the same bytes.
# usage: check_sweep.sh SELFSIM SOURCE_DIR
# shellcheck source=tests/cli/test_lib.sh
source "$(dirname "$0")/test_lib.sh"
cd "$tmp" || exit 1

cat >d.lua <<'LUA'
local curves = require "selfsim.curves"
local level = param("level", 6, { min = 1, max = 16 })
local name = param("name", "dragon", { choices = { "dragon", "terdragon" } })
local c = curves[name]():curve(level)
save(c, "c.svg")
save(c, "c.vtp")
LUA

# A 4 x 2 sweep, two at a time.
"$selfsim" run d.lua -o sw --set level=2..5 --set name=dragon,terdragon --jobs 2 >out.txt 2>err.txt
[ $? = 0 ] || fail "sweep exited non-zero: $(cat err.txt)"
grep -qF "sweep: 8 runs of d.lua, 2 at a time" out.txt || fail "sweep header: $(head -2 out.txt)"
grep -qF "sweep: 8 of 8 runs ok" out.txt || fail "sweep summary: $(tail -2 out.txt)"
for level in 2 3 4 5; do
  for name in dragon terdragon; do
    dir="sw/level=$level,name=$name"
    [ "$(cat "$dir/selfsim.exit" 2>/dev/null)" = 0 ] || fail "$dir/selfsim.exit"
    # Each run's files are those of the same run made alone.
    "$selfsim" run d.lua -o "one/$level$name" --set level=$level --set name=$name -q
    cmp -s "$dir/c.svg" "one/$level$name/c.svg" || fail "$dir/c.svg differs from a single run's"
    cmp -s "$dir/c.vtp" "one/$level$name/c.vtp" || fail "$dir/c.vtp differs from a single run's"
  done
done
# The sheet: a cell per run with its caption, laid out as levels x names; the series: time = nothing
# single (two keys vary), so the run index.
grep -c '<image ' sw/sheet_c.svg | grep -qx 8 || fail "sheet_c.svg should have 8 images"
grep -qF 'href="level=3,name=terdragon/c.svg"' sw/sheet_c.svg || fail "sheet links a run's SVG"
grep -qF '>level=3, name=terdragon</text>' sw/sheet_c.svg || fail "sheet captions a run"
grep -c '<DataSet ' sw/c_sweep.pvd | grep -qx 8 || fail "c_sweep.pvd should list 8 steps"
/usr/bin/python3 - sw <<'PY' || fail "sweep.json"
import json, sys
d = json.load(open(sys.argv[1] + "/sweep.json"))
assert d["keys"] == ["level", "name"], d["keys"]
assert [r["folder"] for r in d["runs"]][:3] == ["level=2,name=dragon", "level=2,name=terdragon", "level=3,name=dragon"]
assert d["runs"][5]["set"] == {"level": "4", "name": "terdragon"}
PY

# One key varying: the series' times are its values.
"$selfsim" run d.lua -o sw1 --set level=3..5 -q || fail "one-key sweep"
grep -qF '<DataSet timestep="5" group="" part="0" file="level=5/c.vtp"/>' sw1/c_sweep.pvd ||
  fail "series time is the swept value: $(cat sw1/c_sweep.pvd)"

# A failed run is reported and the others go on; the exit code says one failed.
cat >f.lua <<'LUA'
local n = param("n", 1)
if n == 2 then error("two is bad") end
save(polyline({ { 0, 0 }, { n, 1 } }), "p.svg")
LUA
"$selfsim" run f.lua -o fw --set n=1,2,3 >out.txt 2>err.txt
[ $? = 1 ] || fail "a sweep with a failed run should exit 1"
grep -qF "n=2: failed (exit 1): f.lua:2: two is bad" err.txt || fail "failed run line: $(cat err.txt)"
grep -qF "1 of 3 runs failed (n=2;" err.txt || fail "failed summary: $(cat err.txt)"
[ -f fw/n=1/p.svg ] && [ -f fw/n=3/p.svg ] || fail "the other runs went on"
grep -qF 'failed (exit 1)</text>' fw/sheet_p.svg || fail "the sheet marks the failed run"

# Values outside a parameter's range are refused before any run starts.
"$selfsim" run d.lua -o bad --set level=15..17 >out.txt 2>err.txt
[ $? = 2 ] || fail "out-of-range sweep should exit 2"
grep -qF "selfsim: --set level=17: 'level' must be in [1, 16]" err.txt || fail "range message: $(cat err.txt)"
[ -e bad ] && fail "a refused sweep made its output folder"

# The job list, run by GNU parallel, then collected: the same bytes as the local sweep.
"$selfsim" sweep d.lua -o pw --set level=2..5 --set name=dragon,terdragon --jobs-file jobs.txt >out.txt 2>err.txt ||
  fail "sweep --jobs-file: $(cat err.txt)"
[ "$(wc -l <pw/jobs.txt)" = 8 ] || fail "jobs.txt should have 8 lines"
grep -qF "parallel --jobs 2 <" out.txt || fail "jobs-file says how to run it"
if command -v parallel >/dev/null; then
  parallel --will-cite --jobs 2 <pw/jobs.txt || fail "parallel ran the job list with failures"
  "$selfsim" sweep d.lua -o pw --set level=2..5 --set name=dragon,terdragon --collect -q || fail "sweep --collect"
  # Each run's view.py names its own folder; every other byte is the same.
  diff -r -x selfsim.log -x jobs.txt -x sweep.json -x view.py sw pw >diff.txt || fail "parallel's sweep differs: $(head -5 diff.txt)"
else
  echo "note: GNU parallel not installed (make deps installs it); job list not run"
fi

# Ranges with a step end where the steps reach the end, to 12 digits; "\," is a comma inside a value.
printf 'local f = param("factor", 0.5)\nlocal t = param("title", "x")\n' >r.lua
"$selfsim" sweep r.lua -o rw --set factor=0.3..0.9:0.1 --set 'title=a\,b,c' --jobs-file j.txt -q || fail "range plan"
/usr/bin/python3 - rw <<'PY' || fail "range values"
import json, sys
runs = json.load(open(sys.argv[1] + "/sweep.json"))["runs"]
got = [(r["set"]["factor"], r["set"]["title"]) for r in runs]
want = [("%g" % (f / 10), t) for f in range(3, 10) for t in ("a,b", "c")]
assert got == want, got
assert runs[0]["folder"] == "factor=0.3,title=a_b", runs[0]["folder"]
PY

# An escaped comma reaches the run as part of its one value; an escaped ".." is text, not a range.
printf 'local m = param("m", "a")\nprint("m=[" .. m .. "]")\nsave(polyline({ { 0, 0 }, { 1, 1 } }), "p.svg")\n' >m.lua
"$selfsim" run m.lua -o ew --set 'm=a\,b,1\.\.3' -q || fail "escaped values"
grep -qxF "m=[a,b]" ew/m=a_b/selfsim.log || fail "a\\,b should reach the run as a,b: $(cat ew/m=a_b/selfsim.log)"
grep -qxF "m=[1..3]" ew/m=1..3/selfsim.log || fail "1\\.\\.3 should reach the run as 1..3"
[ -d ew/m=a_b/m=a ] && fail "a run started a sweep of its own"
# A range ending at the largest integer is counted, not stepped past it.
"$selfsim" sweep r.lua -o big --set factor=9223372036854775800..9223372036854775807 --jobs-file j.txt -q ||
  fail "range to 2^63-1"
[ "$(wc -l <big/j.txt)" = 8 ] || fail "range to 2^63-1 should give 8 runs"
# A link where a run's folder goes is refused before anything starts; nothing is written through it.
elsewhere=$(mktemp -d)
mkdir -p lw && ln -s "$elsewhere" lw/n=1
"$selfsim" run f.lua -o lw --set n=1,3 >out.txt 2>err.txt
[ $? = 2 ] || fail "a linked run folder should be refused"
grep -qF "'lw/n=1' is a link" err.txt || fail "linked folder message: $(cat err.txt)"
[ -z "$(ls "$elsewhere")" ] || fail "a sweep wrote through a link"
rm -rf "$elsewhere"
# --collect reads only regular exit files (a FIFO would block it).
mkdir -p fifo/n=1 && mkfifo fifo/n=1/selfsim.exit
timeout 20 "$selfsim" sweep f.lua -o fifo --set n=1,3 --collect -q 2>/dev/null
[ $? = 1 ] || fail "--collect with a FIFO exit file should report the run as not run"

# Outputs a.vtp and a.vtu: a series each, named by the whole output name as they share a stem. A 251-byte
# output name (valid: 255 is the limit): its sheet's and series' names are cut to fit, with a hash of the
# whole name, and the sweep ends as its runs did.
cat >v.lua <<'LUA'
local n = param("n", 1)
local c = polyline({ { 0, 0 }, { n, 1 } })
local long = string.rep("b", 247)
for _, name in ipairs({ "a.svg", "a.vtp", "a.vtu", long .. ".svg", long .. ".vtp" }) do save(c, name) end
LUA
"$selfsim" run v.lua -o vw --set n=1,2 -q 2>err.txt || fail "a sweep with a.vtp, a.vtu and long names: $(cat err.txt)"
grep -qF 'file="n=2/a.vtp"' vw/a.vtp_sweep.pvd || fail "a.vtp_sweep.pvd: $(cat vw/a.vtp_sweep.pvd 2>&1)"
grep -qF 'file="n=2/a.vtu"' vw/a.vtu_sweep.pvd || fail "a.vtu_sweep.pvd: $(cat vw/a.vtu_sweep.pvd 2>&1)"
[ -e vw/a_sweep.pvd ] && fail "a_sweep.pvd would be one series for two outputs"
b=$(printf 'b%.0s' $(seq 247))
sheet=(vw/sheet_"${b:0:236}"~????????.svg)
series=(vw/"${b:0:236}"~????????_sweep.pvd)
[ -f "${sheet[0]}" ] && [ "$(basename "${sheet[0]}" | wc -c)" = 256 ] || fail "long sheet name: $(ls vw)"
[ -f "${series[0]}" ] && [ "$(basename "${series[0]}" | wc -c)" = 256 ] || fail "long series name: $(ls vw)"
grep -qF "file=\"n=1/$b.vtp\"" "${series[0]}" || fail "the long series names its runs' files"

# Names a .pvd (XML) cannot give byte for byte (not UTF-8, U+FFFF) get no series, with one warning each, and
# every XML file the sweep writes still parses; sweep.json is still JSON.
printf 'local l = param("level", 1)\nlocal name = param("name", "a")\nsave(polyline({ { 0, 0 }, { l, 1 } }), name .. ".vtp")\n' >u.lua
"$selfsim" sweep u.lua -o uw --set level=1,2 --set name=$'\xff\xfe',$'\xef\xbf\xbf',ok --no-sheet -q 2>err.txt ||
  fail "a sweep of names XML cannot hold: $(cat err.txt)"
[ "$(grep -c "warning: no ParaView series of" err.txt)" = 2 ] || fail "one warning per name: $(cat err.txt)"
[ -f uw/ok_sweep.pvd ] && [ "$(find uw -maxdepth 1 -name '*_sweep.pvd' | wc -l)" = 1 ] || fail "series: $(ls uw)"
"$selfsim" sweep u.lua -o uw --set level=1,2 --set name=$'\xff\xfe',$'\xef\xbf\xbf',ok --collect -q 2>/dev/null
/usr/bin/python3 - uw <<'PY' || fail "a sweep's XML or JSON does not parse"
import glob, json, sys, xml.dom.minidom
files = glob.glob(sys.argv[1] + "/*.pvd") + glob.glob(sys.argv[1] + "/*.svg")
assert len(files) == 4, files  # ok_sweep.pvd and three sheets
for f in files:
    xml.dom.minidom.parse(f)
json.load(open(sys.argv[1] + "/sweep.json", "rb"))
PY
# A plain run: view.py says which dataset it leaves out, and with none left writes none.
"$selfsim" run u.lua -o uv --set name=$'\xff' -q 2>err.txt || fail "a run saving a non-UTF-8 name"
grep -qF "warning: view.py leaves out" err.txt || fail "view.py left a dataset out silently: $(cat err.txt)"
[ -e uv/view.py ] && fail "a view.py naming no dataset"

# A job list or Slurm script may not take a name the sweep writes or keeps, now or at --collect.
for name in c_sweep.pvd .selfsim-lock view.py sheet_c.svg sweep.json previews selfsim.exit; do
  "$selfsim" sweep d.lua -o jr --set level=2,3 --jobs-file "$name" >out.txt 2>err.txt
  [ $? = 2 ] && grep -qF "'$name' is a name the sweep uses itself" err.txt || fail "--jobs-file $name: $(cat err.txt)"
  "$selfsim" sweep d.lua -o jr --set level=2,3 --slurm "$name" >out.txt 2>err.txt
  [ $? = 2 ] || fail "--slurm $name was taken"
done
[ -e jr ] && fail "a refused job list made its output folder"

# Ranges whose ends and step are whole are counted in integers and written whole, exact near 2^63.
printf 'local k = param("k", 3)\nlocal name = param("name", "a")\n' >i.lua
for range in 0..4000000000000:1000000000000 0..4e12:1e12; do
  "$selfsim" sweep i.lua -o iw --set k=$range --jobs-file j.txt -q 2>err.txt || fail "k=$range: $(cat err.txt)"
  [ "$(grep -c -- "--set k=" iw/j.txt)" = 5 ] && grep -qF -- "--set k=4000000000000 " iw/j.txt ||
    fail "k=$range: $(cut -c1-200 iw/j.txt)"
done
"$selfsim" sweep i.lua -o iw --set k=9223372036854775800..9223372036854775807:3 --jobs-file j.txt -q 2>err.txt ||
  fail "a whole step near 2^63: $(cat err.txt)"
[ "$(grep -o -- "--set k=[0-9]*" iw/j.txt | tr '\n' ' ')" = \
  "--set k=9223372036854775800 --set k=9223372036854775803 --set k=9223372036854775806 " ] ||
  fail "values near 2^63: $(grep -o -- "--set k=[0-9]*" iw/j.txt)"

# A job line longer than a job list holds (32768 bytes: GNU parallel and Slurm refuse longer) is refused,
# naming the value, before anything is written.
long=$(head -c 40000 /dev/zero | tr '\0' x)
"$selfsim" sweep i.lua -o lj --set k=1,2 --set "name=$long" --jobs-file j.txt >out.txt 2>err.txt
[ $? = 2 ] || fail "a 40 KB job line should be refused"
grep -qF "selfsim: --set name=xxxx" err.txt && grep -qF "at most 32768 in a job list" err.txt ||
  fail "long job line message: $(cut -c1-300 err.txt)"
[ -e lj ] && fail "a refused job list made its output folder"

# --no-sheet is sweep's: run says the command that takes it; sweep writes no sheet with it.
"$selfsim" run f.lua -o ns --set n=1,3 --no-sheet >out.txt 2>err.txt
[ $? = 2 ] || fail "run --no-sheet should be a usage error"
grep -qF "selfsim: --no-sheet is an option of sweep, not run: selfsim sweep f.lua -o ns --set n=1,3 --no-sheet" err.txt ||
  fail "run --no-sheet message: $(cat err.txt)"
[ -e ns ] && fail "a refused run made its output folder"
"$selfsim" sweep f.lua -o ns --set n=1,3 --no-sheet -q || fail "sweep --no-sheet"
[ -f ns/n=3/p.svg ] && [ ! -e ns/sheet_p.svg ] || fail "sweep --no-sheet: $(ls ns)"

# Ctrl-C (SIGINT to the sweep) stops every run: exit 130, no run left behind, no partial file.
cat >slow.lua <<'LUA'
local n = param("n", 1)
local curves = require "selfsim.curves"
local c = curves.dragon():curve(n + 2)
local t = os.clock()
while os.clock() - t < 30 do end
save(polyline({ { 0, 0 }, { n, 1 } }), "p.svg")
LUA
"$selfsim" run slow.lua -o cw --set n=1..4 --jobs 2 >out.txt 2>err.txt &
pid=$!
for _ in $(seq 1 100); do [ "$(children $pid slow.lua | wc -l)" = 2 ] && break; sleep 0.1; done
runs=$(children $pid slow.lua)
[ "$(echo $runs | wc -w)" = 2 ] || fail "the sweep's 2 runs did not start: $runs"
kill -INT $pid
code=0
wait $pid || code=$?
[ "$code" = 130 ] || fail "interrupted sweep exit $code, expected 130"
sleep 0.2
for r in $runs; do running "$r" slow.lua && fail "runs still alive after Ctrl-C"; done
grep -qF "sweep interrupted" err.txt || fail "interrupt message: $(cat err.txt)"
[ -n "$(find cw -name '*.svg')" ] && fail "an interrupted run left a file"

# A misspelt key where the recipe stops at a heavy step before its params (selfsim params reads no further):
# its text, every param() a literal, tells that no such parameter exists, so nothing runs (exit 2; the
# message itself is errors/sweep_unknown_parameter_later). Where the text cannot tell (a computed name, an
# alias of param, a module of the recipe's own) the key may still be declared later: a warning, then the runs.
cat >later.lua <<'LUA'
local c = lsystem { axiom = "F", rules = { F = "F+F" }, angle = 90 }:curve(3)
local n = param("n" .. "um", 1)
save(c, "c.svg")
LUA
"$selfsim" run later.lua -o lt --set num=1,2 -q >out.txt 2>err.txt
[ $? = 0 ] || fail "a computed param name: the sweep should run: $(cat err.txt)"
grep -qF "warning: --set num: no param 'num' is read before later.lua:1" err.txt || fail "computed name warning: $(cat err.txt)"
[ -s "lt/num=2/c.svg" ] || fail "a computed param name: the runs did not run"
printf 'local p = param\nlocal c = lsystem { axiom = \"F\", rules = { F = \"F+F\" }, angle = 90 }:curve(3)\nlocal k = p("k", 1)\nsave(c, "c.svg")\n' >alias.lua
"$selfsim" run alias.lua -o al --set k=1,2 -q >out.txt 2>err.txt
[ $? = 0 ] && [ -s "al/k=2/c.svg" ] || fail "param aliased: the sweep should run: $(cat err.txt)"
printf 'local c = lsystem { axiom = \"F\", rules = { F = \"F+F\" }, angle = 90 }:curve(3)\nlocal g = _G.param("g", 1)\nsave(c, "c.svg")\n' >global.lua
"$selfsim" run global.lua -o gl --set g=1,2 -q >out.txt 2>err.txt
[ $? = 0 ] && [ -s "gl/g=2/c.svg" ] || fail "_G.param: the sweep should run: $(cat err.txt)"
mkdir -p lib && printf 'return param("width", 1)\n' >lib/w.lua
printf 'local c = lsystem { axiom = \"F\", rules = { F = \"F+F\" }, angle = 90 }:curve(3)\nlocal w = require "lib.w"\nsave(c, "c.svg")\n' >mod.lua
"$selfsim" run mod.lua -o md --set width=1,2 -q >out.txt 2>err.txt
[ $? = 0 ] && [ -s "md/width=2/c.svg" ] || fail "a param in the recipe's module: the sweep should run: $(cat err.txt)"
printf 'local c = lsystem { axiom = \"F\", rules = { F = \"F+F\" }, angle = 90 }:curve(3)\nlocal w = param("width", 1)\nsave(c, "c.svg")\n' >lit.lua
"$selfsim" run lit.lua -o li --set widht=1,2 -q >out.txt 2>err.txt
code=$?
[ $code = 2 ] || fail "a misspelt key, every param literal: exit $code, expected 2"
grep -qF "(did you mean 'width'?)" err.txt || fail "a misspelt key: no suggestion: $(cat err.txt)"
[ -e li ] && fail "a misspelt key: the sweep made its folder"

# SIGKILL to the sweep: its runs stop too (they are told to stop with their parent).
"$selfsim" run slow.lua -o kw --set n=1..2 --jobs 2 >out.txt 2>err.txt &
pid=$!
for _ in $(seq 1 100); do [ "$(children $pid slow.lua | wc -l)" = 2 ] && break; sleep 0.1; done
runs=$(children $pid slow.lua)
[ "$(echo $runs | wc -w)" = 2 ] || fail "the sweep's 2 runs did not start: $runs"
kill -9 $pid
wait $pid 2>/dev/null
alive() { for r in $runs; do running "$r" slow.lua && return 0; done; return 1; }
for _ in $(seq 1 100); do alive || break; sleep 0.1; done
alive && fail "runs kept going after the sweep was killed"
for r in $runs; do running "$r" slow.lua && kill -9 "$r"; done

finish

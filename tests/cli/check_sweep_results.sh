#!/usr/bin/env bash
# A sweep's numbers in one table and the plot: result(name, value) in a recipe, each run's results.json, the
# sweep's results.csv (a row per run: swept values, results, status, folder) and plot_NAME.svg when one
# numeric key varies; the same table after GNU parallel (or bash) and --collect; the sheet links them.
# usage: check_sweep_results.sh SELFSIM SOURCE_DIR
# shellcheck source=tests/cli/test_lib.sh
source "$(dirname "$0")/test_lib.sh"
cd "$tmp" || exit 1

# x = 3 fails; square is given only above 1; sum is a sum whose exact double the table must keep.
cat >s.lua <<'LUA'
local x = param("x", 1.0)
if x == 3 then error("three is bad") end
local d = result("twice", 2 * x)
assert(d == 2 * x, "result returns its value")
if x > 1 then result("square", x * x) end
result("sum", x + 0.1)
save(polyline({ { 0, 0 }, { x, 1 } }), "p.svg")
LUA

# One run: results.json beside the outputs, said in the run's wrote line; a run giving none writes none.
"$selfsim" run s.lua -o one --set x=2 >out.txt 2>err.txt || fail "one run: $(cat err.txt)"
grep -qF "wrote one/results.json (twice = 4, square = 4, sum = 2.1)" out.txt || fail "wrote line: $(cat out.txt)"
/usr/bin/python3 - one/results.json <<'PY' || fail "results.json"
import json, sys
d = json.load(open(sys.argv[1]))
assert list(d["results"].items()) == [("twice", 4), ("square", 4), ("sum", 2.1)], d
assert d["provenance"]["set"] == {"x": "2"} and d["provenance"]["name"] == "results.json", d
PY
printf 'save(polyline({ { 0, 0 }, { 1, 1 } }), "p.svg")\n' >none.lua
"$selfsim" run none.lua -o none -q || fail "a run without results"
[ -e none/results.json ] && fail "a run that gave no result wrote results.json"
# A later run into the same folder that gives none, or fails, takes the earlier run's results.json away: it
# would stand for numbers this run never gave.
"$selfsim" run none.lua -o one -q || fail "a run without results into a folder with results"
[ -e one/results.json ] && fail "a run that gave no result left an earlier run's results.json"
"$selfsim" run s.lua -o one --set x=2 -q || fail "the run with results again"
printf 'result("x", 1)\nerror("no")\n' >fails.lua
"$selfsim" run fails.lua -o one -q 2>/dev/null && fail "a failing recipe succeeded"
[ -e one/results.json ] && fail "a failed run left an earlier run's results.json"

# A local sweep: one row per run, in run order, values exact, the failed run's cells empty.
check_table() { # FOLDER
  /usr/bin/python3 - "$1" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1] + "/results.csv", newline="")))
# The names in the order first seen over the runs: square is first given by the third run.
assert rows[0] == ["x", "twice", "sum", "square", "status", "folder"], rows[0]
xs = ["0.5", "1", "2", "3", "4.25"]
assert [r[0] for r in rows[1:]] == xs, rows
for r in rows[1:]:
    x = float(r[0])
    if x == 3:
        assert r[1:] == ["", "", "", "failed", "x=3"], r
        continue
    assert float(r[1]) == 2 * x and float(r[2]) == x + 0.1, r  # exact: the shortest text reads back the same
    assert (float(r[3]) == x * x) if x > 1 else r[3] == "", r
    assert r[4:] == ["ok", "x=" + r[0]], r
PY
}
check_plot() { # FOLDER NAME: the points are the table's, placed linearly, joined in order of x
  /usr/bin/python3 - "$1" "$2" <<'PY'
import csv, sys, xml.etree.ElementTree as ET
folder, name = sys.argv[1:]
ns = "{http://www.w3.org/2000/svg}"
rows = list(csv.DictReader(open(folder + "/results.csv", newline="")))
want = sorted((float(r["x"]), float(r[name])) for r in rows if r[name] != "")
svg = ET.parse(folder + "/plot_" + name + ".svg").getroot()
circles = svg.findall(ns + "circle")
got = [(float(c.get("data-x")), float(c.get("data-y"))) for c in circles]
assert got == want, (got, want)
cx = [float(c.get("cx")) for c in circles]
cy = [float(c.get("cy")) for c in circles]
for i in range(2, len(got)):  # x and y are each mapped by one linear map, y upwards
    sx = (cx[i] - cx[0]) / (got[i][0] - got[0][0]) - (cx[1] - cx[0]) / (got[1][0] - got[0][0])
    assert abs(sx) < 1e-3, "x scale"
    if got[i][1] != got[0][1] and got[1][1] != got[0][1]:
        sy = (cy[i] - cy[0]) / (got[i][1] - got[0][1]) - (cy[1] - cy[0]) / (got[1][1] - got[0][1])
        assert abs(sy) < 1e-3, "y scale"
assert (cy[-1] - cy[0]) * (got[-1][1] - got[0][1]) < 0 or got[-1][1] == got[0][1], "y grows upwards"
line = svg.find(ns + "polyline")
if len(got) > 1:
    pts = [tuple(map(float, p.split(","))) for p in line.get("points").split()]
    assert all(abs(a - c) < 1e-3 and abs(b - d) < 1e-3 for (a, b), c, d in zip(pts, cx, cy)), "the line joins the points"
texts = {t.get("class"): t.text for t in svg.iter(ns + "text") if t.get("class") in ("title", "xlabel", "ylabel")}
assert texts == {"title": name + " against x", "xlabel": "x", "ylabel": name}, texts
assert len([t for t in svg.iter(ns + "text") if t.get("class") == "xtick"]) >= 2, "x ticks"
assert len([t for t in svg.iter(ns + "text") if t.get("class") == "ytick"]) >= 2, "y ticks"
PY
}
"$selfsim" run s.lua -o sw --set x=0.5,1,2,3,4.25 --jobs 2 >out.txt 2>err.txt
[ $? = 1 ] || fail "a sweep with a failed run exits 1"
check_table sw || fail "local results.csv: $(cat sw/results.csv)"
for name in twice square sum; do check_plot sw $name || fail "plot_$name.svg"; done
grep -qF "wrote sw/results.csv" out.txt && grep -qF "wrote sw/plot_square.svg" out.txt || fail "wrote lines: $(cat out.txt)"
grep -qF 'href="plot_twice.svg"' sw/sheet_p.svg && grep -qF 'href="results.csv"' sw/sheet_p.svg ||
  fail "the sheet links the table and the plots"

# The job list run by GNU parallel (or line by line by bash), then --collect: the same table and plots,
# byte for byte; a run that never ran is "not run".
"$selfsim" sweep s.lua -o pw --set x=0.5,1,2,3,4.25 --jobs-file jobs.txt -q || fail "sweep --jobs-file"
if command -v parallel >/dev/null; then
  parallel --will-cite --jobs 2 <pw/jobs.txt
else
  bash pw/jobs.txt
fi
"$selfsim" sweep s.lua -o pw --set x=0.5,1,2,3,4.25 --collect -q 2>/dev/null
for f in results.csv plot_twice.svg plot_square.svg plot_sum.svg sheet_p.svg; do
  cmp -s "sw/$f" "pw/$f" || fail "--collect's $f differs from the local sweep's"
done
rm pw/x=2/selfsim.exit
echo '{"results": {"twice": nan}}' >pw/x=1/results.json
"$selfsim" sweep s.lua -o pw --set x=0.5,1,2,3,4.25 --collect -q 2>err.txt
grep -qF "warning: cannot read 'pw/x=1/results.json': expected a finite number for \"twice\", found 'nan}}" err.txt ||
  fail "a bad results.json is said: $(cat err.txt)"
/usr/bin/python3 - pw <<'PY' || fail "not run and unreadable rows: $(cat pw/results.csv)"
import csv, sys
rows = {r["folder"]: r for r in csv.DictReader(open(sys.argv[1] + "/results.csv", newline=""))}
assert rows["x=2"]["status"] == "not run" and rows["x=2"]["twice"] == "", rows["x=2"]
assert rows["x=1"]["status"] == "ok" and rows["x=1"]["twice"] == "", rows["x=1"]
PY

# A results.json edited to give a result named like the swept key: refused as unreadable (its cells empty),
# not a second column x that a reader of the table would take for the key.
sed -i 's/{"results": {/{"results": {"x": 99, /' pw/x=4.25/results.json
"$selfsim" sweep s.lua -o pw --set x=0.5,1,2,3,4.25 --collect -q 2>err.txt
grep -qF "warning: cannot read 'pw/x=4.25/results.json': it gives a result named 'x', as the swept key" err.txt ||
  fail "a result named like the key is said: $(cat err.txt)"
[ "$(head -1 pw/results.csv | tr -d '\r' | tr ',' '\n' | grep -c '^x$')" = 1 ] && [ ! -e pw/plot_x.svg ] ||
  fail "one column x, no plot of x: $(head -1 pw/results.csv)"

# Two keys vary: the table has both, and no plot, said in the summary and on the sheet. A key whose values
# are not numbers: no plot either. Plots an earlier sweep left in the folder go.
printf 'local a = param("a", 1)\nlocal b = param("b", "u")\nresult("r", a * 10)\nsave(polyline({ { 0, 0 }, { a, 1 } }), "p.svg")\n' >ab.lua
"$selfsim" run ab.lua -o two --set a=1,2 --set b=u,v >out.txt 2>err.txt || fail "two-key sweep: $(cat err.txt)"
grep -qF "no plot of the results: 2 keys vary (a, b): a plot needs one" out.txt || fail "no-plot line: $(cat out.txt)"
grep -qF "no plot: 2 keys vary" two/sheet_p.svg || fail "the sheet says there is no plot"
[ -z "$(find two -maxdepth 1 -name 'plot_*')" ] || fail "a plot with two keys varying"
[ "$(head -1 two/results.csv | tr -d '\r')" = "a,b,r,status,folder" ] && [ "$(grep -c ',ok,' two/results.csv)" = 4 ] ||
  fail "two-key table: $(cat two/results.csv)"
"$selfsim" run ab.lua -o words --set b=u,v >out.txt 2>err.txt || fail "a sweep of words"
grep -qF "no plot of the results: 'b' is not a number in every run ('u')" out.txt || fail "words: $(cat out.txt)"
"$selfsim" run ab.lua -o sw --set a=1,2 -q 2>/dev/null || fail "a second sweep into sw"
[ -f sw/plot_r.svg ] && [ ! -e sw/plot_twice.svg ] || fail "stale plots: $(ls sw)"

# A result named like the table's own columns pushes them aside; values with commas are quoted.
printf 'local t = param("t", "a")\nresult("status", 1)\nresult("folder", 2)\n' >own.lua
"$selfsim" run own.lua -o own --set 't=a\,b,c' -q || fail "own columns"
/usr/bin/python3 - own <<'PY' || fail "own columns: $(cat own/results.csv)"
import csv, sys
rows = list(csv.reader(open(sys.argv[1] + "/results.csv", newline="")))
assert rows[0] == ["t", "status", "folder", "_status", "_folder"], rows[0]
assert rows[1] == ["a,b", "1", "2", "ok", "t=a_b"], rows[1]
PY

# Numbers a unit in the last place apart are a plot too (the tick loop never ended: std::bad_alloc, exit 2).
"$selfsim" run s.lua -o ulp --set x=1,1.0000000000000002 -q 2>err.txt || fail "x one ulp apart: $(cat err.txt)"
[ -f ulp/plot_twice.svg ] || fail "x one ulp apart: no plot"

# A job list may not take the table's or a plot's name.
for name in results.csv plot_x.svg; do
  "$selfsim" sweep s.lua -o jr --set x=1,2 --jobs-file "$name" >out.txt 2>err.txt
  [ $? = 2 ] && grep -qF "'$name' is a name the sweep uses itself" err.txt || fail "--jobs-file $name: $(cat err.txt)"
done

finish

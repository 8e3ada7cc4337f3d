#!/usr/bin/env bash
# Every output records how it was made (recipe path and SHA-256, --set values, seed, version); info shows
# it, rerun repeats the run into a new folder and says whether the bytes match.
# usage: check_provenance.sh SELFSIM SOURCE_DIR
# shellcheck source=tests/cli/test_lib.sh
source "$(dirname "$0")/test_lib.sh"
# A folder whose name holds "--", which an XML comment may not: the SVG must still parse.
dir="$tmp/a--b"
mkdir -p "$dir" && cd "$dir" || exit 1
cat >r.lua <<'LUA'
local curves = require "selfsim.curves"
local level = param("level", 3)
local c = curves.dragon():curve(level)
save(c, "c.svg"); save(c, "c.vtp"); save(c, "c.vtu"); save(c:levels(), "g.pvd")
local s = develop(curves.dragon(), { levels = 3, thickness = 0.05 })
save(s, "s.stl"); save(s, "s.ply"); save(s, "s.obj"); save(s, "s.3mf"); save(s, "s.vdb")
LUA
"$selfsim" run r.lua -o out --set level=5 --seed 3 -q || fail "the run failed"
sha=$(sha256sum r.lua | cut -d' ' -f1)
for f in c.svg c.vtp c.vtu g.pvd s.stl s.ply s.obj s.3mf s.vdb; do
  "$selfsim" info "out/$f" >info.txt 2>&1 || fail "info $f: $(cat info.txt)"
  grep -qF "made by: selfsim " info.txt || fail "info $f shows no provenance: $(tail -2 info.txt)"
  grep -qF "from $dir/r.lua (sha256 ${sha:0:12}), --set level=5, seed 3" info.txt ||
    fail "info $f provenance: $(grep 'made by' info.txt)"
done
# Read by other tools: VTK's own reader, Python's XML parser, and the JSON beside the STL.
/usr/bin/python3 - "$dir" "$sha" <<'PY' || fail "provenance as other tools read it"
import json, sys, vtk, xml.dom.minidom
d, sha = sys.argv[1], sys.argv[2]
want = {"recipe": d + "/r.lua", "sha256": sha, "set": {"level": "5"}, "seed": 3}
def check(p, name):
    for k, v in want.items():
        assert p[k] == v, (name, k, p[k], v)
    assert p["name"] == name, (p["name"], name)
r = vtk.vtkXMLPolyDataReader(); r.SetFileName(d + "/out/c.vtp"); r.Update()
check(json.loads(r.GetOutput().GetFieldData().GetAbstractArray("selfsim_provenance").GetValue(0)), "c.vtp")
svg = xml.dom.minidom.parse(d + "/out/c.svg")
comments = [n for n in svg.documentElement.childNodes if n.nodeType == n.COMMENT_NODE]
check(json.loads(comments[0].data.strip().split(" ", 1)[1]), "c.svg")
check(json.load(open(d + "/out/s.stl.json")), "s.stl")
PY

# rerun: the same bytes, in a new folder.
"$selfsim" rerun out/c.svg >out.txt 2>err.txt || fail "rerun c.svg: $(cat out.txt err.txt)"
grep -qF "same bytes: rerun/c.svg is out/c.svg byte for byte" out.txt || fail "rerun message: $(cat out.txt)"
"$selfsim" rerun out/s.3mf -o again >out.txt 2>err.txt || fail "rerun s.3mf: $(cat out.txt err.txt)"
cmp -s again/s.3mf out/s.3mf || fail "rerun's s.3mf differs"
"$selfsim" rerun out/s.stl >out.txt 2>err.txt || fail "rerun s.stl: $(cat out.txt err.txt)"
grep -qF "rerun-2/s.stl" out.txt || fail "a second rerun takes a new folder: $(cat out.txt)"
"$selfsim" rerun out/c.vtp -o again >out.txt 2>err.txt
[ $? = 2 ] || fail "rerun into a folder that is not empty should exit 2"
grep -qF "is not an empty folder" err.txt || fail "non-empty folder message: $(cat err.txt)"
# A changed recipe: a warning, and different bytes (its fingerprint is in the file).
echo "-- changed" >>r.lua
"$selfsim" rerun out/c.svg -o changed >out.txt 2>err.txt
[ $? = 1 ] || fail "rerun of a changed recipe should exit 1"
grep -qF "has changed since 'out/c.svg' was made" err.txt || fail "changed recipe warning: $(cat err.txt)"
grep -qF "different: changed/c.svg differs from out/c.svg" out.txt || fail "changed recipe result: $(cat out.txt)"
# A crafted record: a name outside the run's folder, a key no --set could have.
sed 's|"name": "c.svg"|"name": "../c.svg"|' out/c.svg >crafted.svg
"$selfsim" rerun crafted.svg -o c1 >/dev/null 2>err.txt
[ $? = 2 ] || fail "rerun of a record naming ../c.svg should exit 2"
grep -qF "not a file inside a run's folder" err.txt || fail "crafted name message: $(cat err.txt)"
sed 's|"set": {"level": "5"}|"set": {"level=1,2": "5"}|' out/c.svg >crafted2.svg
"$selfsim" rerun crafted2.svg -o c2 >/dev/null 2>err.txt
[ $? = 2 ] || fail "rerun of a record with a key holding = should exit 2"
[ -e c2 ] && fail "a refused rerun made its folder"
# Crafted strings: a NUL in the recipe path (it ran the path cut at the NUL: r.lua) and a bad \u escape (it
# read as a NUL, and rerun blamed a recipe "not there") are refused, naming the field.
sed 's|/r.lua"|/r.lua\\u0000/x.lua"|' out/c.svg >nul.svg
"$selfsim" rerun nul.svg -o c3 >out.txt 2>err.txt
[ $? = 2 ] || fail "rerun of a record with a NUL in its recipe path should exit 2: $(cat out.txt err.txt)"
grep -qF "nul.svg': its provenance record: the field \"recipe\" holds a NUL character" err.txt ||
  fail "NUL message: $(cat err.txt)"
[ -e c3 ] && fail "a rerun of the path cut at the NUL ran"
sed 's|/r.lua"|/r\\uzzzz.lua"|' out/c.svg >zzzz.svg
"$selfsim" rerun zzzz.svg -o c4 >/dev/null 2>err.txt
[ $? = 2 ] || fail "rerun of a record with a bad \\u escape should exit 2"
grep -qF "the field \"recipe\" holds a bad escape '\\uzzzz' (\\u takes 4 hex digits)" err.txt ||
  fail "bad escape message: $(cat err.txt)"
[ "$(wc -l <err.txt)" = 1 ] || fail "one line: $(cat err.txt)"
# A value a run would refuse is refused at the record, naming the field (a seed of -1 reached --seed, and
# rerun said only "the rerun failed", exit 1); a number in "set" is named, not called "records no recipe".
sed 's|"seed": 3|"seed": -1|' out/c.svg >negative.svg
"$selfsim" rerun negative.svg -o c5 >out.txt 2>err.txt
[ $? = 2 ] || fail "rerun of a record with seed -1 should exit 2: $(cat out.txt err.txt)"
grep -qF "negative.svg': its provenance record: the field \"seed\" holds -1, not a whole number in [0, 2^63)" err.txt ||
  fail "seed -1 message: $(cat err.txt)"
[ -e c5 ] && fail "a rerun with seed -1 ran"
sed 's|"set": {"level": "5"}|"set": {"level": 5}|' out/c.svg >number.svg
"$selfsim" info number.svg >/dev/null 2>err.txt
[ $? = 2 ] || fail "info of a record with a number in set should exit 2"
grep -qF "the \"set\" value of 'level' is 5, not a string" err.txt || fail "set number message: $(cat err.txt)"
mkfifo fifo.svg
timeout 10 "$selfsim" rerun fifo.svg >/dev/null 2>err.txt
[ $? = 2 ] || fail "rerun of a FIFO should exit 2 at once"

# A file with no record, and one whose recipe is gone.
printf '<svg xmlns="http://www.w3.org/2000/svg"><path d="M0 0L1 1"/></svg>\n' >plain.svg
"$selfsim" rerun plain.svg >/dev/null 2>err.txt
[ $? = 2 ] || fail "rerun of a file with no record should exit 2"
grep -qF "records no recipe" err.txt || fail "no record message: $(cat err.txt)"
mv r.lua gone.lua
"$selfsim" rerun out/c.svg -o g2 >/dev/null 2>err.txt
[ $? = 2 ] || fail "rerun with the recipe gone should exit 2"
grep -qF "which is not there any more" err.txt || fail "recipe gone message: $(cat err.txt)"

finish

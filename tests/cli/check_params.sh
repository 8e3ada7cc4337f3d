#!/usr/bin/env bash
# `selfsim params`: a recipe's annotated parameters as JSON, read without building or writing anything.
# usage: check_params.sh SELFSIM SOURCE_DIR
# shellcheck source=tests/cli/test_lib.sh
source "$(dirname "$0")/test_lib.sh"

cat >"$tmp/r.lua" <<'LUA'
local curves = require "selfsim.curves"
local factor = param("factor", 0.8, { min = 0.05, max = 1, step = 0.05, doc = "radius \"factor\" per level" })
local mode = param("mode", "clamp", { choices = { "clamp", "repeat", "rotate" } })
local level = param("level", 6, { min = 1, max = 14 })
local show = param("show", true)
print("a recipe's print must not reach the JSON")
local c = curves.dragon():curve(level)
local late = param("late", 2)
save(c, "d.svg")
LUA
cd "$tmp" || exit 1
"$selfsim" params r.lua >"$tmp/json" 2>"$tmp/err" || fail "params exited $?: $(cat "$tmp/err")"
[ -s "$tmp/err" ] && fail "params wrote to stderr: $(cat "$tmp/err")"
[ -e "$tmp/out" ] && fail "params made an output folder"
/usr/bin/python3 - "$tmp/json" <<'PY' || failures=$((failures + 1))
import json, sys
d = json.load(open(sys.argv[1]))
p = {x["name"]: x for x in d["parameters"]}
want = {
    "factor": {"name": "factor", "type": "number", "default": 0.8, "min": 0.05, "max": 1, "step": 0.05,
               "doc": 'radius "factor" per level'},
    "mode": {"name": "mode", "type": "string", "default": "clamp", "choices": ["clamp", "repeat", "rotate"]},
    "level": {"name": "level", "type": "integer", "default": 6, "min": 1, "max": 14},
    "show": {"name": "show", "type": "boolean", "default": True},
}
errors = []
if [x["name"] for x in d["parameters"]] != ["factor", "mode", "level", "show"]:
    errors.append("names/order: %s" % [x["name"] for x in d["parameters"]])
for name, w in want.items():
    if p.get(name) != w: errors.append("%s: %s, expected %s" % (name, p.get(name), w))
if d["complete"] is not False or d.get("stopped_at") != "r.lua:7":
    errors.append("complete/stopped_at: %s %s" % (d["complete"], d.get("stopped_at")))
for e in errors: print("FAIL: params json " + e)
sys.exit(1 if errors else 0)
PY

# --set reaches params read later; a recipe that builds nothing is complete.
printf 'local a = param("a", 1)\nlocal b = param("b" .. a, "x")\n' >"$tmp/s.lua"
"$selfsim" params s.lua --set a=2 >"$tmp/json2" 2>"$tmp/err" || fail "params --set: $(cat "$tmp/err")"
/usr/bin/python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
ok = d["complete"] is True and "stopped_at" not in d and [x["name"] for x in d["parameters"]] == ["a", "b2"]
sys.exit(0 if ok else 1)' "$tmp/json2" || fail "params with --set: $(cat "$tmp/json2")"

# A bad annotation is the recipe's error, as in run.
printf 'local a = param("a", 1, { min = 2 })\n' >"$tmp/bad.lua"
"$selfsim" params bad.lua >"$tmp/o.txt" 2>"$tmp/err"
[ $? = 1 ] || fail "params of a bad annotation should exit 1"
grep -qF "bad.lua:1: param: 'a': the default 1 is outside its range: it must be at least 2" "$tmp/err" ||
  fail "bad annotation message: $(cat "$tmp/err")"
[ -s "$tmp/o.txt" ] && fail "params printed JSON for a failed recipe"

# params builds and writes nothing: a sweep, --watch, -o and --jobs are refused.
for args in "--set level=1..3" "--watch" "-o elsewhere" "--jobs 2"; do
  # shellcheck disable=SC2086
  "$selfsim" params r.lua $args >/dev/null 2>"$tmp/err"
  [ $? = 2 ] || fail "params $args should be a usage error"
done
[ -e "$tmp/elsewhere" ] || [ -e "$tmp/out" ] && fail "params made a folder"

finish

#!/usr/bin/env bash
# run --watch: re-runs when the recipe or a module beside it changes (inotify), stops a run still going,
# keeps the last good files when a re-run fails, and stops at Ctrl-C leaving nothing behind. The waits
# below are bounds against a hang, not timings: speed is measured in bench/watch_latency.py.
# usage: check_watch.sh SELFSIM SOURCE_DIR
set -uo pipefail
selfsim=$1
tmp=$(mktemp -d)
pid=
trap '[ -n "$pid" ] && kill -9 $pid 2>/dev/null; rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
cd "$tmp" || exit 1
# until COMMAND: retries for up to 20 s.
until_ok() {
  for _ in $(seq 1 200); do "$@" && return 0; sleep 0.1; done
  return 1
}
# Whether two SVGs draw the same (their provenance comments name different recipes).
same_drawing() { cmp -s <(grep -v selfsim_provenance "$1") <(grep -v selfsim_provenance "$2"); }
# Writes a file as editors do: a temporary renamed over it.
save_as() { printf '%s\n' "$2" >".$1.new" && mv ".$1.new" "$1"; }

cat >shape.lua <<'LUA'
return { level = 3 }
LUA
save_as r.lua 'local curves = require "selfsim.curves"
local shape = require "shape"
save(curves.dragon():curve(shape.level), "c.svg")'
"$selfsim" run r.lua --watch -o out >log.txt 2>err.txt &
pid=$!
until_ok test -f out/c.svg || fail "the first run wrote nothing: $(cat log.txt err.txt)"
# The files the runs below should give, made by plain runs.
printf 'local curves = require "selfsim.curves"\nsave(curves.dragon():curve(5), "c.svg")\n' >ref.lua
"$selfsim" run ref.lua -o ref5 -q
printf 'local curves = require "selfsim.curves"\nsave(curves.dragon():curve(7), "c.svg")\n' >ref.lua
"$selfsim" run ref.lua -o ref7 -q
rm ref.lua

# A module the recipe requires changes: the run starts again and its files replace the old ones.
save_as shape.lua 'return { level = 5 }'
until_ok same_drawing out/c.svg ref5/c.svg || fail "a module's change did not re-run: $(tail -3 log.txt)"
grep -qF "shape.lua changed" log.txt || fail "the change is named: $(cat log.txt)"

# A failed re-run says why and keeps the last good files.
save_as r.lua 'error("boom")'
until_ok grep -qF "the last good files stay in out" err.txt || fail "no failure line: $(cat err.txt)"
grep -qF "r.lua:1: boom" err.txt || fail "the run's error line: $(cat err.txt)"
same_drawing out/c.svg ref5/c.svg || fail "a failed run changed the last good file"

# A run still going is stopped by the next change.
save_as r.lua 'local t = os.clock()
while os.clock() - t < 60 do end'
until_ok pgrep -f "selfsim run r.lua -o out/.selfsim-next" >/dev/null || fail "the slow run did not start"
save_as r.lua 'local curves = require "selfsim.curves"
save(curves.dragon():curve(7), "c.svg")'
until_ok same_drawing out/c.svg ref7/c.svg || fail "the slow run was not stopped for the change: $(tail -3 log.txt)"
grep -qF "run stopped, starting again" log.txt || fail "the stopped run is said: $(cat log.txt)"

# A run whose file cannot go in (a folder is where it goes) fails; watching goes on.
mkdir -p out/blocked.svg
save_as r.lua 'local curves = require "selfsim.curves"
save(curves.dragon():curve(3), "blocked.svg")'
until_ok grep -qF "is a folder where the run's file goes" err.txt || fail "a file that cannot go in: $(tail -2 err.txt)"
kill -0 $pid 2>/dev/null || fail "watching stopped when a run's file could not go in"
rmdir out/blocked.svg

# A second watcher on the same output folder is refused (they would remove each other's staging).
"$selfsim" run r.lua --watch -o out >/dev/null 2>err2.txt
[ $? = 2 ] || fail "a second watcher on one output folder should be refused"
grep -qF "another studio or --watch is using the output folder" err2.txt || fail "lock message: $(cat err2.txt)"

# Ctrl-C stops watching: exit 130, no run left, no staging folder.
kill -INT $pid
code=0
wait $pid || code=$?
pid=
[ "$code" = 130 ] || fail "watch exit $code at Ctrl-C, expected 130"
[ -e out/.selfsim-next ] && fail "the staging folder is left behind"
pgrep -f "out/.selfsim-next" >/dev/null && fail "a run is left behind"

# --watch with a sweep is refused.
"$selfsim" run r.lua --watch --set level=1,2 >/dev/null 2>err.txt
[ $? = 2 ] || fail "--watch with a sweep should be a usage error"

echo "$failures failures"
[ "$failures" = 0 ]

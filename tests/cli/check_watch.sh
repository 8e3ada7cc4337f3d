#!/usr/bin/env bash
# run --watch: re-runs when the recipe or a module beside it changes (inotify), stops a run still going,
# keeps the last good files when a re-run fails, and stops at Ctrl-C leaving nothing behind. The waits
# below are bounds against a hang, not timings: speed is measured in bench/watch_latency.py.
# usage: check_watch.sh SELFSIM SOURCE_DIR
# shellcheck source=tests/cli/test_lib.sh
source "$(dirname "$0")/test_lib.sh"
pid='' pid2=''
trap 'for w in $pid $pid2; do kill -9 "$w" 2>/dev/null; done; rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
# until COMMAND: retries for up to 20 s.
until_ok() {
  for _ in $(seq 1 200); do "$@" && return 0; sleep 0.1; done
  return 1
}
# Whether two SVGs draw the same (their provenance comments name different recipes).
same_drawing() { cmp -s <(grep -v selfsim_provenance "$1") <(grep -v selfsim_provenance "$2"); }
# Whether the watcher has a run going (its own child, not any selfsim on the machine).
slow_run_started() { [ -n "$(children "$pid" out/.selfsim-next)" ]; }
# changes LOG: how many changes a watcher's log names; more_changes LOG N: whether more than N;
# last_run_wrote LOG: whether the last line is a run that ended writing c.svg.
changes() { grep -c ' changed' "$1"; }
more_changes() { [ "$(changes "$1")" -gt "$2" ]; }
last_run_wrote() { tail -1 "$1" | grep -qF "wrote c.svg"; }
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
until_ok slow_run_started || fail "the slow run did not start"
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

# Ctrl-C during a run stops watching: exit 130, that run stopped, no staging folder.
save_as r.lua 'local t = os.clock()
while os.clock() - t < 60 do end'
until_ok slow_run_started || fail "the slow run did not start"
run=$(children "$pid" out/.selfsim-next)
kill -INT $pid
code=0
wait $pid || code=$?
pid=
[ "$code" = 130 ] || fail "watch exit $code at Ctrl-C, expected 130"
[ -e out/.selfsim-next ] && fail "the staging folder is left behind"
for r in $run; do running "$r" out/.selfsim-next && fail "a run is left behind" && kill -9 "$r"; done

# --watch with a sweep is refused.
"$selfsim" run r.lua --watch --set level=1,2 >/dev/null 2>err.txt
[ $? = 2 ] || fail "--watch with a sweep should be a usage error"

# The recipe becomes a link after watching started (an editor or stow replaces it by one): edits to the
# link's target start a run, and so do edits at the end of a chain of links whose middle changed.
mkdir -p lw other third && cd lw || exit 1
printf 'local curves = require "selfsim.curves"\nsave(curves.dragon():curve(3), "c.svg")\n' >../third/u.lua
"$selfsim" run ../third/u.lua -o ../ref3 -q
printf 'local curves = require "selfsim.curves"\nsave(curves.dragon():curve(7), "c.svg")\n' >r.lua
"$selfsim" run r.lua --watch -o out >../log2.txt 2>../err2.txt &
pid2=$!
until_ok same_drawing out/c.svg ../ref7/c.svg || fail "the first run of the linked case: $(cat ../err2.txt)"
printf 'local curves = require "selfsim.curves"\nsave(curves.dragon():curve(5), "c.svg")\n' >../other/t.lua
ln -s ../other/t.lua .r.lua.link && mv -T .r.lua.link r.lua
until_ok same_drawing out/c.svg ../ref5/c.svg || fail "replacing the recipe by a link did not re-run"
printf 'local curves = require "selfsim.curves"\nsave(curves.dragon():curve(7), "c.svg")\n' >../other/t.lua
until_ok same_drawing out/c.svg ../ref7/c.svg || fail "an edit to the link's target did not re-run: $(cat ../log2.txt)"
ln -s ../third/u.lua ../other/.t.link && mv -T ../other/.t.link ../other/t.lua
until_ok same_drawing out/c.svg ../ref3/c.svg || fail "pointing the link's target elsewhere did not re-run"
printf 'local curves = require "selfsim.curves"\nsave(curves.dragon():curve(5), "c.svg")\n' >../third/u.lua
until_ok same_drawing out/c.svg ../ref5/c.svg || fail "an edit at the end of a chain of links did not re-run"
kill -INT $pid2
wait $pid2
pid2=

# A folder on the way to the recipe is a link, re-pointed while watched (stow folds folders this way, a
# `current` link moves to the next version): the run follows it, and edits in the new target start runs.
# A link loop on the way fails its run with the loop named; watching goes on and follows the loop's repair.
cd "$tmp" && mkdir -p fl/v2 fl/v3 fl/v4 && cd fl || exit 1
printf 'local curves = require "selfsim.curves"\nsave(curves.dragon():curve(3), "c.svg")\n' >v2/r.lua
printf 'local curves = require "selfsim.curves"\nsave(curves.dragon():curve(5), "c.svg")\n' >v3/r.lua
printf 'local curves = require "selfsim.curves"\nsave(curves.dragon():curve(5), "c.svg")\n' >v4/r.lua
ln -s v2 cur
"$selfsim" run cur/r.lua --watch -o out >../log3.txt 2>../err3.txt &
pid2=$!
until_ok same_drawing out/c.svg ../ref3/c.svg || fail "the first run through a folder link: $(cat ../err3.txt)"
ln -s v3 .cur.new && mv -T .cur.new cur
until_ok same_drawing out/c.svg ../ref5/c.svg || fail "re-pointing a folder link on the way did not re-run"
# The old target is no longer the recipe's folder: writes there start no run (the sleep, as below).
until_ok last_run_wrote ../log3.txt || fail "the run of the re-pointed folder link did not end"
before=$(changes ../log3.txt)
printf 'local curves = require "selfsim.curves"\nsave(curves.dragon():curve(7), "c.svg")\n' >v2/r.lua
echo 1 >v2/unrelated.lua
sleep 1
printf 'local curves = require "selfsim.curves"\nsave(curves.dragon():curve(7), "c.svg")\n' >v3/r.lua
until_ok same_drawing out/c.svg ../ref7/c.svg || fail "an edit in the folder link's new target did not re-run"
[ "$(changes ../log3.txt)" = $((before + 1)) ] ||
  fail "writes in a folder link's old target started runs: $(grep ' changed' ../log3.txt | tail -n +$((before + 1)))"
ln -s cur loop && ln -s loop .cur.new && mv -T .cur.new cur
until_ok grep -qF "cannot open recipe 'cur/r.lua': Too many levels of symbolic links" ../err3.txt ||
  fail "a link loop on the way is not named: $(cat ../err3.txt)"
until_ok grep -qF "the run failed" ../err3.txt || fail "a link loop on the way: no failure line"
kill -0 "$pid2" 2>/dev/null || fail "watching stopped at a link loop on the way"
ln -s v4 .cur.new && mv -T .cur.new cur
until_ok same_drawing out/c.svg ../ref5/c.svg || fail "repairing a link loop on the way did not re-run"
kill -INT "$pid2"
wait "$pid2"
pid2=

# A link's old target folder is no longer watched once the link goes: r.lua a link to ../e/t.lua, then a
# regular file again; writes in ../e start no run, so the next run logged is the next real edit's, and the
# only one. The sleep gives a wrongly counted write room to start its own run (the fixed watcher needs none).
cd "$tmp" && mkdir -p sw e && cd sw || exit 1
printf 'local curves = require "selfsim.curves"\nsave(curves.dragon():curve(3), "c.svg")\n' >r.lua
"$selfsim" run r.lua --watch -o out >../log4.txt 2>../err4.txt &
pid2=$!
until_ok same_drawing out/c.svg ../ref3/c.svg || fail "the first run of the old-target case: $(cat ../err4.txt)"
printf 'local curves = require "selfsim.curves"\nsave(curves.dragon():curve(5), "c.svg")\n' >../e/t.lua
ln -s ../e/t.lua .r.lua.link && mv -T .r.lua.link r.lua
until_ok same_drawing out/c.svg ../ref5/c.svg || fail "replacing the recipe by a link to ../e did not re-run"
save_as r.lua 'local curves = require "selfsim.curves"
save(curves.dragon():curve(7), "c.svg")'
until_ok same_drawing out/c.svg ../ref7/c.svg || fail "the recipe a regular file again did not re-run"
until_ok last_run_wrote ../log4.txt || fail "the run of the regular file again did not end"
before=$(changes ../log4.txt)
for i in 1 2 3; do echo "$i" >"../e/unrelated$i.txt"; done
printf 'local curves = require "selfsim.curves"\nsave(curves.dragon():curve(3), "c.svg")\n' >../e/t.lua
sleep 1
save_as r.lua 'local curves = require "selfsim.curves"
save(curves.dragon():curve(5), "c.svg")'
until_ok same_drawing out/c.svg ../ref5/c.svg || fail "an edit after the writes in the old target did not re-run"
[ "$(changes ../log4.txt)" = $((before + 1)) ] ||
  fail "writes in a link's old target folder started runs: $(grep ' changed' ../log4.txt | tail -n +$((before + 1)))"
grep ' changed' ../log4.txt | tail -1 | grep -qF "r.lua changed" || fail "the last run is not the edit's: $(tail -3 ../log4.txt)"

# A recipe linked to a character device (/dev/null, whose folder every process writes in) runs once and does
# not run again by itself, nor for writes to the device; the next run is the next real edit's.
until_ok last_run_wrote ../log4.txt || fail "the run of the edit did not end"
n=$(changes ../log4.txt)
ln -s /dev/null .r.lua.link && mv -T .r.lua.link r.lua
until_ok more_changes ../log4.txt "$n" || fail "a link to /dev/null is no change"
until_ok grep -qF "the run failed" ../err4.txt || fail "the run of /dev/null did not end: $(tail -2 ../log4.txt)"
grep -qF "cannot open recipe 'r.lua'" ../err4.txt || fail "a recipe linked to /dev/null: $(cat ../err4.txt)"
before=$(changes ../log4.txt)
for i in 1 2 3; do echo "$i" >/dev/null; done
sleep 1
save_as r.lua 'local curves = require "selfsim.curves"
save(curves.dragon():curve(7), "c.svg")'
until_ok same_drawing out/c.svg ../ref7/c.svg || fail "an edit after a link to /dev/null did not re-run"
[ "$(changes ../log4.txt)" = $((before + 1)) ] ||
  fail "a recipe linked to /dev/null ran by itself: $(grep ' changed' ../log4.txt | tail -n +$((before + 1)) | head -5)"
kill -INT "$pid2"
wait "$pid2"
pid2=

# An output folder spelt with a trailing slash, absolute: the first run's files are published (walking up from
# a file to "DIR/" once never stopped, at 100% CPU) and Ctrl-C still ends the watcher.
"$selfsim" run r.lua --watch -o "$tmp/slash/" >../log5.txt 2>../err5.txt &
pid2=$!
until_ok test -f "$tmp/slash/c.svg" || fail "-o DIR/ published nothing: $(tail -3 ../log5.txt ../err5.txt)"
kill -INT "$pid2"
wait "$pid2"
pid2=

finish

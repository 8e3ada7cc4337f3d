#!/usr/bin/env bash
# Preview PNGs go through the one confined writer (kernels/io/output_file.h), as `save` does: a link at any
# folder on the way (previews/level=1 in a local sweep, previews under `sweep --collect`, a folder in
# `preview --as`) is refused with a message naming it and a non-zero exit, and nothing appears where the
# link points. The studio's .studio link is in studio_previews.py. Skips (77) without an X display or Xvfb
# (before the fix, the PNGs were drawn and written through the links).
# usage: preview_links.sh SELFSIM SOURCE_DIR
selfsim=$1
src=$2
source "$src/tests/robustness/lib.sh"
[ -n "${DISPLAY:-}" ] || command -v Xvfb >/dev/null || { echo "skipped: no X display and no Xvfb"; exit 77; }
cd "$tmp" || exit 1
mkdir outside
cat >m.lua <<'LUA'
local curves = require "selfsim.curves"
local level = param("level", 1, { min = 1, max = 4 })
save(develop(curves.dragon(), { levels = level, smooth = 1 }), "m.vtp")
LUA
nothing_outside() { [ -z "$(ls -A outside)" ]; }

# A local sweep, a link at previews/level=1 (previews itself a real folder).
mkdir -p sw/previews
ln -s "$tmp/outside" sw/previews/level=1
run_selfsim sweep m.lua -o sw --set level=1,2 -q
check "sweep with a previews/level=1 link fails (got $code)" test "$code" != 0
check "its message names the link: $(first_err)" grep -q "previews/level=1'.*link" "$tmp/err"
check "nothing written through previews/level=1" nothing_outside

# sweep --collect, previews itself a link (the runs made without sheets first).
run_selfsim sweep m.lua -o co --set level=1,2 -q --no-sheet
check "a sweep without sheets runs: $(first_err)" test "$code" = 0
ln -s "$tmp/outside" co/previews
run_selfsim sweep m.lua -o co --set level=1,2 --collect -q
check "sweep --collect with a previews link fails (got $code)" test "$code" != 0
check "its message names the link: $(first_err)" grep -q "co/previews'.*link" "$tmp/err"
check "nothing written through previews" nothing_outside

# Links planted after the sweep's checks (check_sweep_folders) and after it made the run's folder: the run
# holds (its recipe waits for go.lua after its first step) while the test puts a link in place of level=1 and of previews/level=2.
# The run, whose -o names level=1, refuses its own folder as a link (--confined-output), the sweep writes
# no selfsim.exit through it, and the previews' folder is refused by the writer, not by the first check.
cat >hold.lua <<'LUA'
local curves = require "selfsim.curves"
local level = param("level", 1, { min = 1, max = 4 })
local shape = develop(curves.dragon(), { levels = level, smooth = 1 })  -- reading the parameters ends here
while not pcall(require, "go") do end
save(shape, "m.vtp")
LUA
"$selfsim" sweep hold.lua -o late --set level=1,2 --jobs 1 -q >"$tmp/out" 2>"$tmp/err" &
sweep=$!
for _ in $(seq 1200); do [ -e late/level=1/selfsim.log ] && break; sleep 0.05; done
check "the first run started" test -e late/level=1/selfsim.log
rm -rf late/level=1
ln -s "$tmp/outside" late/level=1
mkdir -p late/previews
ln -s "$tmp/outside" late/previews/level=2
echo 'return true' >go.lua
wait "$sweep"
code=$?
check "a sweep with links planted late fails (got $code)" test "$code" != 0
check "the run folder's link is named: $(head -3 "$tmp/err" | tr '\n' ' ')" grep -q "late/level=1'.*link" "$tmp/err"
check "the previews folder's link is named" grep -q "late/previews/level=2'.*link" "$tmp/err"
check "nothing written through the late links" nothing_outside
check "the second run wrote its own folder" test -s late/level=2/m.vtp
rm -f go.lua

# The same for `run --watch` (and the studio, which runs the same way): a link put in place of its staging
# folder after it was made is refused by the run, not written through. The hold is a/b/c/go/ahead.lua, four
# folders below the recipe's: the watcher watches three levels of subfolders (file_watcher.h), and a change it
# saw would start a second run, which makes a real staging folder and publishes m.vtp (before, the hold was
# one folder down, and a second run could publish before the test's Ctrl-C reached the watcher).
mkdir -p wt/a/b/c/go
sed 's/require, "go"/require, "a.b.c.go.ahead"/' hold.lua >wt/hold.lua
"$selfsim" run wt/hold.lua -o wo --watch -q >"$tmp/out" 2>"$tmp/err" &
watch=$!
for _ in $(seq 1200); do [ -d wo/.selfsim-next ] && break; sleep 0.05; done
check "the watched run started" test -d wo/.selfsim-next
rm -rf wo/.selfsim-next
ln -s "$tmp/outside" wo/.selfsim-next
echo 'return true' >wt/a/b/c/go/ahead.lua
for _ in $(seq 600); do grep -q "link" "$tmp/err" && break; sleep 0.05; done
kill -INT "$watch"
wait "$watch"
check "the watched run names the link: $(head -2 "$tmp/err" | tr '\n' ' ')" grep -q "selfsim-next'.*link" "$tmp/err"
check "nothing written through the staging link" nothing_outside
check "nothing published" test ! -e wo/m.vtp

# The writer itself: `preview --as` with a link two folders down.
mkdir -p pv/a
ln -s "$tmp/outside" pv/a/b
run_selfsim preview -o pv --as a/b/m.png co/level=1/m.vtp
check "preview through a link fails (got $code)" test "$code" != 0
check "its message names the link: $(first_err)" grep -q "pv/a/b'.*link" "$tmp/err"
check "nothing written through a/b" nothing_outside
run_selfsim preview -o pv --as a/c/m.png co/level=1/m.vtp
check "preview --as into a new folder works: $(first_err)" test -s pv/a/c/m.png
finish

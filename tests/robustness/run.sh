#!/usr/bin/env bash
# `selfsim run` under a hostile user: signals at any moment, links planted in the output folder, SIGKILL
# mid-write, finalizers that write after the end, runs that must give the same bytes every time.
# usage: run.sh SELFSIM SOURCE_DIR
selfsim=$1 src=$2
source "$(dirname "$0")/lib.sh"
cd "$tmp" || exit 1

recipe() { printf '%s\n' "$2" >"$1.lua"; }
empty_dir() { [ ! -e "$1" ] || [ -z "$(ls -A "$1")" ]; }

# --- Signals: SIGTERM and SIGINT stop a kernel, a writer, a finalizer and the closing state ---------------
# Each recipe first saves started.svg, so the signal comes once the run is under way, however busy the
# machine. The time bounds below tell "stops" from "hangs" (the promise is about a second); they are not
# speed measurements.
marker='save(polyline { { 0, 0 }, { 1, 0 } }, "started.svg")'
recipe big "$marker"'; local c = require("selfsim.curves").dragon():curve(24); save(c, "big.vtp"); save(c, "big.svg")'
recipe gc_loop "$marker"'; setmetatable({}, { __gc = function() while true do end end }); collectgarbage()'
recipe close_loop "$marker"'; setmetatable({}, { __gc = function() while true do end end })'
recipe c_call "$marker"'; print(("a"):rep(3e5):find(".-b"))'
# whole_files DIR: no temporary (dot-file) in DIR, and every file there reads back whole.
whole_files() {
  [ -z "$(ls -A "$1" 2>/dev/null | grep '^\.')" ] || return 1
  local f
  for f in "$1"/*; do [ -e "$f" ] || continue; "$selfsim" info "$f" >/dev/null 2>&1 || return 1; done
}
for sig in TERM INT HUP; do
  for r in big gc_loop close_loop c_call; do
    "$selfsim" run $r.lua -o "out_$r$sig" -q 2>"err_$r$sig" &
    pid=$!
    for _ in $(seq 200); do [ -e "out_$r$sig/started.svg" ] && break; sleep 0.05; done
    sleep 0.2
    started=$(date +%s%N)
    kill -$sig $pid
    wait $pid
    code=$?
    ms=$(( ($(date +%s%N) - started) / 1000000 ))
    check "$r: SIG$sig exits 130 (got $code)" [ "$code" = 130 ]
    check "$r: SIG$sig ends, not hangs (took $ms ms)" [ "$ms" -lt 5000 ]
    check "$r: SIG$sig leaves no partial file ($(ls -A "out_$r$sig" 2>/dev/null | tr '\n' ' '))" whole_files "out_$r$sig"
    check "$r: SIG$sig prints one line ($(head -c 200 "err_$r$sig"))" [ "$(wc -l <"err_$r$sig")" = 1 ]
    check "$r: SIG$sig says interrupted" grep -q "interrupted" "err_$r$sig"
  done
done

# --- --timeout wins whatever the recipe does, also when pcall catches it -------------------------------
recipe pcall_loop 'while true do pcall(function() while true do end end) end'
recipe xpcall_loop 'while true do xpcall(function() while true do end end, function(e) return e end) end'
recipe wrap_loop 'while true do pcall(coroutine.wrap(function() while true do end end)) end'
for r in pcall_loop xpcall_loop wrap_loop gc_loop close_loop c_call big; do
  started=$(date +%s%N)
  run_selfsim run $r.lua -o "out_t$r" -q --timeout 0.5
  ms=$(( ($(date +%s%N) - started) / 1000000 ))
  check "$r: --timeout exits 1 (got $code)" [ "$code" = 1 ]
  check "$r: --timeout 0.5 ends, not hangs (took $ms ms)" [ "$ms" -lt 5000 ]
  check "$r: --timeout message ($(first_err))" grep -q "stopped: --timeout of 0.5 s reached" "$tmp/err"
  # a file finished before the deadline may stay; nothing partial or temporary may
  check "$r: --timeout leaves no partial file ($(ls -A "out_t$r" 2>/dev/null | tr '\n' ' '))" whole_files "out_t$r"
done

# --- An interrupted parallel expansion (several threads drawing) stops and leaves no file -----------------
# Repeated dragons keep the threads drawing whenever the signal comes; the file is written only at the end.
recipe parallel "$marker"'; local g = require("selfsim.curves").dragon(); local c; for i = 1, 200 do c = g:curve(23) end; save(c, "late.vtp")'
for threads in 2 7; do
  "$selfsim" run parallel.lua -o "out_par$threads" -q --threads $threads 2>"err_par$threads" &
  pid=$!
  for _ in $(seq 200); do [ -e "out_par$threads/started.svg" ] && break; sleep 0.05; done
  sleep 0.3
  kill -INT $pid
  wait $pid
  code=$?
  check "parallel expansion, $threads threads: SIGINT exits 130 (got $code)" [ "$code" = 130 ]
  check "parallel expansion, $threads threads: no file but the marker ($(ls -A "out_par$threads" | tr '\n' ' '))" \
    [ "$(ls -A "out_par$threads")" = started.svg ]
  check "parallel expansion, $threads threads: says interrupted" grep -q "interrupted" "err_par$threads"
done

# --- SIGKILL mid-write leaves no partial file, and no temporary ------------------------------------------
# The recipe never ends (a loop after its saves), so the kill always finds it running however fast the
# machine writes: a run that finished first wrote view.py, a whole file, and failed the check by a race.
recipe write_big 'local c = require("selfsim.curves").dragon():curve(20); for i = 1, 40 do save(c, "big" .. i .. ".vtp") end; while true do end'
"$selfsim" run write_big.lua -o out_kill -q 2>/dev/null &
pid=$!
sleep 1.5
kill -KILL $pid
wait $pid 2>/dev/null
check "SIGKILL leaves no temporary ($(ls -A out_kill | grep -v '^big[0-9]*\.vtp$' | tr '\n' ' '))" \
  bash -c '[ -z "$(ls -A out_kill | grep -v "^big[0-9]*\.vtp$")" ]'
for f in out_kill/big*.vtp; do
  [ -e "$f" ] || continue
  check "SIGKILL: $f is whole" "$selfsim" info "$f"
done

# --- Links planted inside the output folder never lead a write outside ------------------------------------
mkdir -p out_links elsewhere
ln -s "$tmp/elsewhere" out_links/dir_link
ln -s "$tmp/elsewhere/target.svg" out_links/planted.svg
for name in dir_link/x.svg dir_link/sub/x.svg; do
  recipe link "save(polyline { { 0, 0 }, { 1, 0 } }, \"$name\")"
  run_selfsim run link.lua -o out_links -q
  check "save to $name is refused (exit $code)" [ "$code" = 1 ]
  check "save to $name names the link ($(first_err))" grep -q "symbolic link" "$tmp/err"
done
recipe planted 'save(polyline { { 0, 0 }, { 1, 0 } }, "planted.svg")'
run_selfsim run planted.lua -o out_links -q
check "saving over a planted file link works (exit $code)" [ "$code" = 0 ]
check "the planted link is replaced, not written through" [ ! -L out_links/planted.svg ]
check "nothing was written outside ($(ls -A elsewhere | tr '\n' ' '))" empty_dir elsewhere

# --- require never follows a link out of the recipe's folder ----------------------------------------------
mkdir -p req outside
echo 'return { secret = "outside" }' >outside/secret.lua
ln -s "$tmp/outside/secret.lua" req/cfg.lua
recipe req/uses_link 'print(require("cfg").secret)'
run_selfsim run req/uses_link.lua -o out_req -q
check "require through a link out of the folder is refused (exit $code)" [ "$code" = 1 ]
check "and says so ($(first_err))" grep -q "leads outside its folder" "$tmp/err"
check "and prints nothing of the file" bash -c "! grep -q outside '$tmp/out'"

# --- load() reads only inside the recipe's folder, and never waits on a FIFO -------------------------------
mkdir -p ld
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >outside/secret.obj
ln -s "$tmp/outside/secret.obj" ld/linked.obj
mkdir -p ld/sub && ln -s "$tmp/outside" ld/sub/out
recipe ld/via_file_link 'load("linked.obj")'
recipe ld/via_dir_link 'load("sub/out/secret.obj")'
for r in via_file_link via_dir_link; do
  run_selfsim run ld/$r.lua -o out_ld -q
  check "load $r is refused (exit $code)" [ "$code" = 1 ]
  check "load $r says why ($(first_err))" grep -q "goes through a symbolic link, which is not followed" "$tmp/err"
done
mkfifo ld/pipe.stl
recipe ld/fifo 'load("pipe.stl")'
started=$(date +%s%N)
run_selfsim run ld/fifo.lua -o out_ld -q --timeout 10
ms=$(( ($(date +%s%N) - started) / 1000000 ))
check "load of a FIFO is an error (exit $code, $(first_err))" [ "$code" = 1 ]
check "load of a FIFO does not wait for a writer (took $ms ms)" [ "$ms" -lt 5000 ]
check "load of a FIFO says it is not a regular file" grep -q "not a regular file" "$tmp/err"

# --- Nothing is written after the recipe ends -------------------------------------------------------------
recipe late_ok 'setmetatable({}, { __gc = function() save(polyline { { 0, 0 }, { 1, 0 } }, "late.svg") end })'
run_selfsim run late_ok.lua -o out_late -q
check "a finalizer at exit cannot save (exit $code)" empty_dir out_late
check "the refused late save is a one-line warning" grep -q "the recipe has ended" "$tmp/err"
# Lua registers no finalizer for a value made while the state closes: making one is refused, not leaked.
recipe late_make 'setmetatable({}, { __gc = function() polyline { { 0, 0 }, { 1, 0 } } end })'
run_selfsim run late_make.lua -o out_late_make -q
check "a value made by a finalizer at exit is refused (exit $code, $(first_err))" [ "$code" = 0 ]
check "the refused value is a one-line warning" grep -q "polyline: the recipe has ended" "$tmp/err"

# --- Same recipe and seed, same bytes: pairs() order is fixed -------------------------------------------
recipe order 'local pts, names = {}, { pear = 1, apple = 2, fig = 3, kiwi = 4, lime = 5, plum = 6, date = 7, yuzu = 8, sloe = 9 }
for name, i in pairs(names) do pts[#pts + 1] = { #pts + 1, i + math.random() } end
save(polyline(pts), "order.svg")
lsystem { axiom = "F", zulu = 1, alpha = 2, mike = 3, kilo = 4 }'
for i in 1 2 3 4 5 6; do
  "$selfsim" run order.lua -o "out_order$i" -q --seed 7 2>"err_order$i"
  cmp -s out_order1/order.svg "out_order$i/order.svg" || echo "differs $i" >>order_diffs
  cmp -s err_order1 "err_order$i" || echo "message differs $i" >>order_diffs
done
check "six runs give byte-identical files and messages ($(cat order_diffs 2>/dev/null | tr '\n' ' '))" [ ! -e order_diffs ]

finish

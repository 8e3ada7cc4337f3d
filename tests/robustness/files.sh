#!/usr/bin/env bash
# Reading files back through the command line: `selfsim info` and `selfsim diff` on broken, truncated,
# crafted and special files exit 2 with exactly one line on stderr ("selfsim info: cannot read 'F': ..."),
# promptly, with nothing from VTK; never a crash, a hang, or a broken file taken for an empty dataset.
# usage: files.sh SELFSIM SOURCE_DIR
selfsim=$1 src=$2
source "$(dirname "$0")/lib.sh"

good_vtp=$src/tests/golden/plant/plant.vtp
good_svg=$src/tests/golden/plant/plant.svg

# one_error COMMAND ARGS...: exit 2 within 10 seconds, one line on stderr naming the command, no VTK output.
one_error() {
  local command=$1
  timeout 10 "$selfsim" "$@" >"$tmp/out" 2>"$tmp/err"
  code=$?
  local what="$* (exit $code: $(head -c 300 "$tmp/err"))"
  check "$what: exit 2" [ "$code" = 2 ]
  check "$what: one line on stderr" [ "$(wc -l <"$tmp/err")" = 1 ]
  check "$what: a 'cannot read' line" grep -q "^selfsim $command: cannot read '" "$tmp/err"
  check "$what: nothing from VTK" no_vtk_noise
}
differs() { ! cmp -s "$1" "$2"; }
no_vtk_noise() { ! grep -q -e 'ERROR: In' -e '\.cxx' -e $'\e\\[' -e '(0x' "$tmp/err"; }
# ok_or_error ARGS...: exit 0 with nothing on stderr, or exit 2 with one line; within 10 seconds either way.
ok_or_error() {
  timeout 10 "$selfsim" "$@" >"$tmp/out" 2>"$tmp/err"
  code=$?
  local what="$* (exit $code: $(head -c 300 "$tmp/err"))"
  check "$what: exit 0 or 2" [ "$code" = 0 -o "$code" = 2 ]
  if [ "$code" = 2 ]; then check "$what: one line" [ "$(wc -l <"$tmp/err")" = 1 ]; else check "$what: quiet" [ ! -s "$tmp/err" ]; fi
  check "$what: nothing from VTK" no_vtk_noise
}
# header_edit FILE OUT FILTER...: passes the XML part of a .vtp through FILTER (sed, awk), keeping the
# appended binary data byte for byte.
header_edit() {
  local file=$1 out=$2 at
  shift 2
  at=$(grep -abo '<AppendedData' "$file" | head -1 | cut -d: -f1)
  head -c "$at" "$file" | "$@" >"$out"
  tail -c +"$((at + 1))" "$file" >>"$out"
}

# The good files read.
run_selfsim info "$good_vtp"
check "info on a good .vtp (exit $code)" [ "$code" = 0 ]
run_selfsim diff "$good_vtp" "$good_vtp"
check "diff of a good .vtp with itself (exit $code)" [ "$code" = 0 ]
run_selfsim diff "$good_svg" "$good_svg"
check "diff of a good .svg with itself (exit $code)" [ "$code" = 0 ]

# Empty, garbage, directories, missing files.
for ext in vtp svg; do
  : >"$tmp/empty.$ext"
  head -c 3000 /dev/urandom >"$tmp/garbage.$ext"
  printf 'hello\n' >"$tmp/text.$ext"
  mkdir "$tmp/folder.$ext"
  for f in empty garbage text folder missing; do one_error info "$tmp/$f.$ext"; done
done
one_error info "$tmp/garbage.txt"

# Truncated at many byte positions, and cut just before the end.
for good in "$good_vtp" "$good_svg"; do
  size=$(stat -c %s "$good")
  ext=${good##*.}
  for ((n = 1; n < size - 1; n += size / 25 + 1)); do
    head -c "$n" "$good" >"$tmp/cut.$ext"
    one_error info "$tmp/cut.$ext"
  done
  head -c $((size - 3)) "$good" >"$tmp/cut.$ext"
  one_error info "$tmp/cut.$ext"
done

# A diff of two broken files is an error, not "same"; so is a good file against a broken one.
one_error diff "$tmp/empty.vtp" "$tmp/garbage.vtp"
one_error diff "$tmp/empty.svg" "$tmp/empty.svg"
one_error diff "$good_vtp" "$tmp/cut.vtp"
one_error diff "$tmp/folder.vtp" "$good_vtp"

# Crafted headers: declared sizes VTK alone would crash, abort or hang on.
for edit in 's/NumberOfPoints="[0-9]*"/NumberOfPoints="-5"/' 's/NumberOfPoints="[0-9]*"/NumberOfPoints="1e15"/' \
  's/NumberOfPoints="[0-9]*"/NumberOfPoints="1000000000000000"/' \
  's/NumberOfLines="[0-9]*"/NumberOfLines="4294967296"/' \
  's/NumberOfComponents="3"/NumberOfComponents="12345678901234567890"/' \
  's/offset="0"/offset="18446744073709551615"/' 's/type="PolyData"/type="ImageData"/'; do
  header_edit "$good_vtp" "$tmp/crafted.vtp" sed "$edit"
  check "crafted: $edit applies" differs "$good_vtp" "$tmp/crafted.vtp"
  one_error info "$tmp/crafted.vtp"
done
# A compression header announcing 2^40 blocks (UInt64 words: blocks, block size, last block, first size).
blocks=$(printf '\0\0\0\0\0\1\0\0\0\200\0\0\0\0\0\0\110\0\0\0\0\0\0\0\22\0\0\0\0\0\0\0' | base64 -w0)
cat >"$tmp/blocks.vtp" <<EOF
<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian" header_type="UInt64" compressor="vtkZLibDataCompressor">
<PolyData><Piece NumberOfPoints="3" NumberOfLines="0">
<Points><DataArray type="Float64" NumberOfComponents="3" format="binary">${blocks}eJxjYMAHPtjjF0fIAwBSZQOO</DataArray></Points>
</Piece></PolyData></VTKFile>
EOF
one_error info "$tmp/blocks.vtp"
# Every array's data pointed at the first array's, the points' and the last array's: VTK then reads sizes
# from the wrong data. An error or not, never a crash or a hang.
offsets=$(grep -ao 'offset="[0-9]*"' "$good_vtp" | cut -d'"' -f2)
points=$(grep -a -A1 '<Points>' "$good_vtp" | grep -ao 'offset="[0-9]*"' | cut -d'"' -f2)
for i in $(seq 1 "$(echo "$offsets" | wc -l)"); do
  for to in $(echo "$offsets" | head -1) "$points" $(echo "$offsets" | tail -1); do
    header_edit "$good_vtp" "$tmp/pointed.vtp" awk "/offset=\"/ { if (++k == $i) sub(/offset=\"[0-9]*\"/, \"offset=\\\"$to\\\"\") } { print }"
    ok_or_error info "$tmp/pointed.vtp"
  done
done
# An ascii array that VTK cannot parse: VTK's own multi-line message must not reach the terminal.
cat >"$tmp/junk.vtp" <<'EOF'
<VTKFile type="PolyData" version="1.0"><PolyData><Piece NumberOfPoints="2" NumberOfLines="0">
<Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">0 0 0 1 x 0</DataArray></Points>
</Piece></PolyData></VTKFile>
EOF
one_error info "$tmp/junk.vtp"

# SVG path data: NaN, infinity, an odd number of coordinates.
for d in 'M0 0L1 NaN' 'M0 0L1 inf' 'M0 0L1 1e999' 'M0 0L1' 'M0 0L1 1 2'; do
  printf '<svg xmlns="http://www.w3.org/2000/svg"><path d="%s"/></svg>\n' "$d" >"$tmp/bad.svg"
  one_error info "$tmp/bad.svg"
done

# Special files: answered at once, never read forever or waited on.
mkfifo "$tmp/fifo.vtp" "$tmp/fifo.svg"
ln -s /dev/zero "$tmp/zero.svg"
ln -s /dev/zero "$tmp/zero.vtp"
ln -s loop.vtp "$tmp/loop.vtp"
ln -s loop.svg "$tmp/loop.svg"
long=$tmp/$(printf 'n%.0s' $(seq 300)).vtp
for f in "$tmp/fifo.vtp" "$tmp/fifo.svg" "$tmp/zero.svg" "$tmp/zero.vtp" /dev/zero "$tmp/loop.vtp" "$tmp/loop.svg" "$long"; do
  one_error info "$f"
done
one_error diff "$tmp/loop.vtp" "$long"
one_error diff "$good_svg" "$tmp/fifo.svg"

# Found by the second hostile round: well-formed but empty files, and comments VTK parses in quadratic time.
printf '<svg xmlns="http://www.w3.org/2000/svg"></svg>' >"$tmp/empty.svg"
run_selfsim info "$tmp/empty.svg"
check "an empty SVG is exit 2 (got $code)" [ "$code" = 2 ]
check "an empty SVG says it holds no points ($(first_err))" grep -q "holds no points" "$tmp/err"
run_selfsim diff "$tmp/empty.svg" "$tmp/empty.svg"
check "two empty files never diff as same (exit $code)" [ "$code" = 2 ]
python3 -c "import sys; sys.stdout.write('<?xml version=\"1.0\"?>\n<!--' + 'x' * (1 << 20) + '-->\n')" >"$tmp/comment.vtp"
started=$(date +%s%N)
run_selfsim info "$tmp/comment.vtp"
ms=$(( ($(date +%s%N) - started) / 1000000 ))
check "a 1 MiB comment is refused (exit $code, $(first_err))" [ "$code" = 2 ]
check "at once ($ms ms)" [ "$ms" -lt 5000 ]
finish

#!/usr/bin/env bash
# One golden case: run a recipe at a small size, then compare every output with the expected file using
# `selfsim diff` (geometry-aware, relative tolerance). The output folder must hold exactly the expected
# files. With SELFSIM_REGENERATE_GOLDEN=1 the expected files are replaced instead: review them with
# `git diff` before committing, never regenerate to make a failure go away.
# usage: check_golden.sh SELFSIM SOURCE_DIR CASE RECIPE [selfsim run args...]
set -euo pipefail
selfsim=$1 src=$2 case=$3 recipe=$4
shift 4
expected="$src/tests/golden/$case"
actual=$(mktemp -d) again=$(mktemp -d)
trap 'rm -rf "$actual" "$again"' EXIT

"$selfsim" run "$src/$recipe" -o "$actual" -q "$@"
# view.py (the run's ParaView view) names the folder it was written to, so it differs between the two runs
# and is checked by its own test (tests/viewer/check_view.sh), not here.
# Same recipe, same seed: byte-identical files, also on one thread (the first run uses every core).
"$selfsim" run "$src/$recipe" -o "$again" -q --threads 1 "$@"
if ! diff -r -x view.py "$actual" "$again" >/dev/null; then
  echo "$case: two runs (all cores, then --threads 1) wrote different bytes"
  exit 1
fi

if [ "${SELFSIM_REGENERATE_GOLDEN:-0}" = 1 ]; then
  mkdir -p "$expected"
  find "$expected" -mindepth 1 ! -name points.txt -delete
  cp -r "$actual"/* "$expected"/
  rm -f "$expected/view.py" "$expected"/*.stl.json "$expected"/*.vdb.json
  echo "regenerated $expected"
  exit 0
fi

status=0
# Every file, in subfolders too (a time series' steps), by its path in the folder.
want=$(cd "$expected" && find . -type f ! -name points.txt | sed 's|^\./||' | sort)
# The provenance beside .stl and .vdb files (NAME.stl.json) names the recipe's absolute path, which differs
# from checkout to checkout: tests/cli/check_provenance.sh checks it.
got=$(cd "$actual" && find . -type f ! -path ./view.py ! -name '*.stl.json' ! -name '*.vdb.json' | sed 's|^\./||' | sort)
if [ "$want" != "$got" ]; then
  echo "output files differ from $expected:"
  diff <(echo "$want") <(echo "$got") || true
  status=1
fi
for f in $want; do
  [ -f "$actual/$f" ] || continue
  if [[ "$f" == *.csv ]]; then  # the same cells, numbers within the tolerance selfsim diff uses (1e-9 relative)
    awk -F, '{ sub(/\r$/, "") } NR == FNR { want[FNR] = $0; rows = FNR; next }
      { got = FNR; n = split(want[FNR], w, ","); if (n != NF) { bad = 1; exit }
        for (i = 1; i <= NF; ++i) {
          if (w[i] == $i) continue
          if (w[i] !~ /^-?[0-9.eE+-]+$/ || $i !~ /^-?[0-9.eE+-]+$/) { bad = 1; exit }
          d = w[i] - $i; if (d < 0) d = -d; m = w[i] < 0 ? -w[i] : w[i]; if (m < 1) m = 1
          if (d > 1e-9 * m) { bad = 1; exit } } }
      END { exit (bad || got != rows) }' "$expected/$f" "$actual/$f" ||
      { echo "$case/$f: cells differ from the expected file beyond 1e-9"; status=1; }
    continue
  fi
  # selfsim does not read these back as geometry (a series file names its steps, compared one by one):
  # the bytes must match.
  if [[ "$f" == *.eps || "$f" == *.vdb || "$f" == *.pvd || "$f" == *.series ]]; then
    cmp -s "$expected/$f" "$actual/$f" || { echo "$case/$f: bytes differ from the expected file"; status=1; }
    continue
  fi
  if ! out=$("$selfsim" diff "$expected/$f" "$actual/$f" --tol 1e-9); then
    echo "$case/$f:"
    echo "$out"
    status=1
  fi
done
[ $status = 0 ] && echo "$case: $(echo $want | wc -w) files match"
exit $status

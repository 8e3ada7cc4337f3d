#!/usr/bin/env bash
# `make fuzz` after the build: for each target, replay fuzz/regressions/<target>/, fuzz for FUZZ_SECONDS,
# then triage what was found: each new crash, leak, hang or out-of-memory input is reproduced, grouped by
# its signature (lib.sh), minimised (crashes and leaks, -minimize_crash) and copied to
# fuzz/regressions/<target>/ where the replay (and ctest -L fuzz) runs it from then on.
#
# usage: fuzz/run.sh [BUILD_DIR]          (default: build-fuzz)
# env:   FUZZ_SECONDS   seconds of fuzzing per target (default 60)
#        FUZZ_TARGETS   targets to run (default: grammar vtp svg stl obj ply vdb recipe provenance book cpfg)
#        FUZZ_JOBS      libFuzzer -fork jobs (default: the number of cores)
#        FUZZ_TIMEOUT   seconds one input may run before it is a hang (default 10)
# Corpora, artifacts and logs stay under BUILD_DIR/fuzz-work/ (not in git), so later runs start from
# what earlier ones found. Exit status 1 if any regression input still fails or anything new was found.
set -uo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$src/build-fuzz}" && pwd)
# shellcheck source=fuzz/lib.sh
source "$src/fuzz/lib.sh"
seconds=${FUZZ_SECONDS:-60}
targets=${FUZZ_TARGETS:-$FUZZ_TARGETS_ALL}
jobs=${FUZZ_JOBS:-$(nproc)}
work=$build/fuzz-work
max_triage=20  # artifacts reproduced per target and run (each hang costs FUZZ_TIMEOUT seconds)
status=0
report=()
# The targets' scratch files and libFuzzer's -fork folders; a crashed process cannot remove its own.
export TMPDIR=$work/tmp
rm -rf "$TMPDIR"
mkdir -p "$TMPDIR"

for t in $targets; do
  bin=$build/fuzz/fuzz_$t
  if [ ! -x "$bin" ]; then
    echo "fuzz: no $bin (build it first: cmake --build $build --target fuzz_all)" >&2
    exit 2
  fi
  corpus=$work/corpus/$t art=$work/artifacts/$t logs=$work/logs/$t seeds=$work/seeds/$t regressions=$src/fuzz/regressions/$t
  rm -rf "$art" "$logs" "$seeds"
  mkdir -p "$corpus" "$art" "$logs" "$seeds"
  cp "$src"/fuzz/corpus/"$t"/* "$seeds"/ 2>/dev/null
  if [ "$t" = recipe ]; then
    # The project's own recipes, but not those made to run into --timeout: each would stall a job.
    for f in "$src"/examples/*.lua "$src"/tests/errors/*.lua "$src"/tests/lua/*.lua; do
      [ -f "$f" ] && ! grep -q '^-- args:.*--timeout' "$f" && cp "$f" "$seeds/$(basename "$(dirname "$f")")_$(basename "$f")"
    done
  fi

  echo "=== $t: replaying fuzz/regressions/$t"
  signatures=$work/$t.signatures
  : >"$signatures"
  SIGNATURES=$signatures "$src/fuzz/replay.sh" "$bin" "$regressions"
  known=$(wc -l <"$signatures")
  [ "$known" = 0 ] || status=1

  echo "=== $t: fuzzing for $seconds s ($jobs jobs)"
  fuzz_export_env "$t"
  # shellcheck disable=SC2207
  flags=($(fuzz_flags "$t"))
  dict=()
  [ -f "$src/fuzz/$t.dict" ] && dict=(-dict="$src/fuzz/$t.dict")
  start=$(date +%s)
  "$bin" "${flags[@]}" "${dict[@]}" -fork="$jobs" -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
    -max_total_time="$seconds" -artifact_prefix="$art/" "$corpus" "$seeds" >"$logs/fuzz.log" 2>&1
  elapsed=$(($(date +%s) - start))
  execs=$(grep -oE '^#[0-9]+' "$logs/fuzz.log" | tail -1 | tr -d '#')
  execs=${execs:-0}
  counts=$(grep -oE 'oom/timeout/crash: [0-9]+/[0-9]+/[0-9]+' "$logs/fuzz.log" | tail -1 | sed 's/.*: //')
  corpus_size=$(find "$corpus" -type f | wc -l)

  # Triage: reproduce, group by signature, minimise, keep one input per new signature.
  new=()
  n=0
  for a in "$art"/crash-* "$art"/leak-* "$art"/timeout-* "$art"/oom-*; do
    [ -f "$a" ] || continue
    n=$((n + 1))
    [ "$n" -le "$max_triage" ] || break
    kind=$(basename "$a" | sed 's/-.*//')
    timeout -k 5 $((FUZZ_TIMEOUT * 3 + 30)) "$bin" "${flags[@]}" "$a" >"$logs/repro.log" 2>&1
    code=$?
    if [ "$code" = 0 ]; then
      # (an empty crash file is libFuzzer -fork's record of a leak seen while loading the corpus)
      [ -s "$a" ] && echo "  $(basename "$a"): does not reproduce on its own (flaky); left in $art"
      continue
    fi
    [ "$code" = 124 ] || [ "$code" = 137 ] && echo "ERROR: libFuzzer: timeout (killed by run.sh)" >>"$logs/repro.log"
    sig=$(signature "$logs/repro.log")
    if cut -f1 "$signatures" | grep -qxF -- "$sig"; then
      continue  # already known (a regression input, or found earlier in this run)
    fi
    keep=$a
    if [ "$kind" = crash ] || [ "$kind" = leak ]; then
      min=$art/minimized-$(basename "$a")
      timeout -k 5 150 "$bin" "${flags[@]}" -minimize_crash=1 -max_total_time=60 -exact_artifact_path="$min" "$a" \
        >"$logs/minimize.log" 2>&1
      if [ -s "$min" ] && [ "$(stat -c %s "$min")" -lt "$(stat -c %s "$a")" ]; then
        timeout -k 5 $((FUZZ_TIMEOUT * 3 + 30)) "$bin" "${flags[@]}" "$min" >"$logs/repro.log" 2>&1
        [ "$(signature "$logs/repro.log")" = "$sig" ] && keep=$min  # same bug, smaller input
      fi
    fi
    mkdir -p "$regressions"
    dest=$regressions/$kind-$(sha1sum "$keep" | cut -c1-12)
    cp "$keep" "$dest"
    printf '%s\t%s\n' "$sig" "$dest" >>"$signatures"
    new+=("${dest#"$src"/}: $sig")
  done
  [ "${#new[@]}" = 0 ] || status=1

  line="$t: $execs executions in ${elapsed}s ($((execs / (elapsed > 0 ? elapsed : 1)))/s), corpus $corpus_size inputs"
  line+=", oom/timeout/crash inputs ${counts:-0/0/0}; regressions still failing: $known; new findings: ${#new[@]}"
  report+=("$line")
  for f in "${new[@]}"; do report+=("    NEW $f"); done
  while IFS=$'\t' read -r sig input; do
    case $input in "$regressions"/*) ;; *) continue ;; esac
    printf '%s\n' "${new[@]}" | grep -qF "${input#"$src"/}" && continue
    report+=("    still failing ${input#"$src"/}: $sig")
  done <"$signatures"
done

rm -rf "$TMPDIR"
echo
echo "=== fuzz summary (logs and artifacts: $work)"
printf '%s\n' "${report[@]}"
exit $status

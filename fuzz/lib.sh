# Shared by fuzz/run.sh and fuzz/replay.sh: per-target flags, and the one-line signature of a finding.
# shellcheck shell=bash

# shellcheck disable=SC2034  # used by run.sh
FUZZ_TARGETS_ALL="grammar vtp svg stl obj ply vdb recipe provenance book cpfg"
FUZZ_TIMEOUT=${FUZZ_TIMEOUT:-10}   # seconds one input may run before it counts as a hang
FUZZ_RSS_MB=${FUZZ_RSS_MB:-2048}

# libFuzzer flags for TARGET (besides corpus and time). The .vtp target reads through VTK, which is not
# ours: VTK leaks on some malformed files and asks malloc for absurd sizes it then handles, so leaks are
# not checked there and only resident memory (not the size of one malloc) is limited.
fuzz_flags() {
  local flags="-timeout=$FUZZ_TIMEOUT -rss_limit_mb=$FUZZ_RSS_MB"
  case $1 in
    vtp) flags+=" -detect_leaks=0 -malloc_limit_mb=1048576" ;;
  esac
  echo "$flags"
}

# Sanitizer settings for TARGET, exported before running it.
fuzz_export_env() {
  local asan="abort_on_error=0:symbolize=1:detect_stack_use_after_return=0"
  case $1 in
    vtp) asan+=":allocator_may_return_null=1:detect_leaks=0" ;;
  esac
  export ASAN_OPTIONS="$asan${ASAN_OPTIONS_EXTRA:+:$ASAN_OPTIONS_EXTRA}"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
}

# The signature of the finding in LOG (the output of one run on one input), one line, stable across
# inputs that hit the same bug: the kind of failure and where it happened, numbers blurred.
#   FUZZ-FINDING lines (the targets' own checks) give their message;
#   otherwise the sanitizer's or libFuzzer's kind, and the first stack frame in the project's kernels/ or
#   frontend/ (else the first frame outside libFuzzer, the sanitizers and libc).
signature() {
  local log=$1 kind where
  if grep -q '^FUZZ-FINDING: ' "$log"; then
    sed -n 's/^FUZZ-FINDING: //p' "$log" | head -1 | sed -E 's/[0-9]+(\.[0-9]+)?(e[-+]?[0-9]+)?/N/g; s/-?inf|nan/N/g' | cut -c1-200
    return
  fi
  kind=$(grep -m1 -oE 'ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer|UndefinedBehaviorSanitizer): [A-Za-z -]+' "$log" |
         sed -E 's/^ERROR: //; s/ on unknown address.*//; s/ +$//; s/ after$//')
  if [ -z "$kind" ]; then
    kind=$(grep -m1 -oE 'runtime error: .*' "$log" | sed -E 's/[0-9]+/N/g' | cut -c1-120)
  fi
  [ -n "$kind" ] || kind="no crash"
  # Stack frames: "#3 0x55... in selfsim::f(int) /work/main/kernels/x.cpp:12:7" or "#4 0x7f... (/lib/liblua.so+0x1f6)".
  local frames
  frames=$(grep -E '^ +#[0-9]+ 0x[0-9a-f]+ ' "$log" | sed -E 's/ \(BuildId: [0-9a-f]+\)//')
  where=$(echo "$frames" | grep -E '/(kernels|frontend)/' | head -1)
  if [ -z "$where" ]; then
    where=$(echo "$frames" |
            grep -vE 'fuzzer::|__sanitizer|__asan|__ubsan|__lsan|libc\.so|nptl/|stdlib/|signal/|csu/|LLVMFuzzerTestOneInput|selfsim::fuzz::| in (main|_start|malloc|calloc|realloc|free|operator new|operator delete)[ (]' |
            head -1)
  fi
  # -> "selfsim::f(int) kernels/x.cpp:12", or "(liblua5.4-c++.so.0)" for a library without symbols
  where=$(echo "$where" | sed -E 's/^ +#[0-9]+ 0x[0-9a-f]+ +(in )?//; s#\(/[^)]*/([^/)]+)\+0x[0-9a-f]+\)#(\1)#; s#[^ ]*/((kernels|frontend)/)#\1#; s/:([0-9]+):[0-9]+$/:\1/')
  echo "$kind${where:+ in $where}"
}

#!/usr/bin/env bash
# The README's five-minute tutorial, run exactly as written, in a fresh folder outside the checkout: each
# ```lua block (its first line "-- NAME.lua" names the file) is written out, each ```sh block's commands
# run in order with selfsim on PATH, as the tutorial tells the reader to set it. Every command must succeed
# without a warning, and every file the recipes save must exist.
# usage: tutorial.sh SELFSIM SOURCE_DIR
set -uo pipefail
selfsim=$(realpath "$1") src=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/bin" && ln -s "$selfsim" "$work/bin/selfsim"
export PATH="$work/bin:$PATH"
cd "$work" || exit 1

# The tutorial section: from its heading to the next second-level heading.
awk '/^## Five-minute tutorial/ { on = 1; next } /^## / { on = 0 } on' "$src/README.md" >tutorial.md
failures=0 blocks=0 saves=()
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

kind="" body=""
while IFS= read -r line; do
  stripped="${line#"${line%%[![:space:]]*}"}"  # the list item's indentation removed
  if [ -z "$kind" ]; then
    case "$stripped" in
      '```lua') kind=lua body="" ;;
      '```sh') kind=sh body="" ;;
    esac
    continue
  fi
  if [ "$stripped" != '```' ]; then
    body+="${line#   }"$'\n'
    continue
  fi
  blocks=$((blocks + 1))
  if [ "$kind" = lua ]; then
    name=$(head -n 1 <<<"$body" | sed -n 's/^-- \([A-Za-z0-9_]*\.lua\)$/\1/p')
    if [ -z "$name" ]; then
      fail "a lua block does not start with '-- NAME.lua': $(head -n 1 <<<"$body")"
    else
      printf '%s' "$body" >"$name"
      while IFS= read -r f; do saves+=("$f"); done < <(grep -o 'save([^"]*"[^"]*"' "$name" | sed 's/.*"\(.*\)"/\1/')
    fi
  else
    while IFS= read -r cmd; do
      [ -z "$cmd" ] && continue
      bash -c "$cmd" >out.txt 2>err.txt
      status=$?
      if [ $status != 0 ]; then
        fail "'$cmd' exited $status: $(head -n 3 err.txt)"
      elif [ -s err.txt ]; then
        fail "'$cmd' warned: $(head -n 3 err.txt)"
      fi
    done <<<"$body"
  fi
  kind=""
done <tutorial.md

[ "$blocks" -ge 4 ] || fail "found only $blocks code blocks in the tutorial"
[ "${#saves[@]}" -ge 3 ] || fail "found only ${#saves[@]} saved files in the tutorial's recipes"
for f in "${saves[@]}"; do [ -s "out/$f" ] || fail "the tutorial's recipes save $f, but out/$f is missing"; done
# Every output file the tutorial's text names (`out/view.py`, `sweep/sheet_dragon.svg`, ...) is there.
named=$(grep -o '`\(out\|sweep\)/[^` ]*[^/` ]`' tutorial.md | tr -d '`' | sort -u)
for f in $named; do [ -e "$f" ] || fail "the tutorial names $f, but the commands did not make it"; done
[ -n "$named" ] || fail "the tutorial names no output file"
[ $failures = 0 ] && echo "tutorial: $blocks blocks, ${#saves[@]} files written, $(echo $named | wc -w) named files there"
exit $((failures > 0))

#!/bin/sh
# Every C++ file of the project follows .clang-format. Skips (exit 77, which ctest reports as skipped) when
# clang-format is not installed; `make deps` installs it.
src="$1"
command -v clang-format >/dev/null 2>&1 || { echo "clang-format not installed: skipped"; exit 77; }
cd "$src" || exit 1
files=$(git ls-files '*.h' '*.cpp' 2>/dev/null || find kernels interpreter tests bench fuzz -name '*.h' -o -name '*.cpp')
bad=$(clang-format --dry-run $files 2>&1 | grep -o '^[^:]*:[0-9]*:[0-9]*: warning' | cut -d: -f1 | sort -u)
if [ -n "$bad" ]; then
  echo "not formatted (run: clang-format -i FILE):"
  echo "$bad"
  exit 1
fi
echo "$(echo $files | wc -w) files formatted"

#!/usr/bin/env python3
"""ABOP's branch-aware context (section 1.8) checked exactly on Figure 1.31 a-e.

Usage: python3 tests/lsystem/abop_context_check.py SELFSIM SOURCE_DIR [LEVEL]

An independent rewriter of the book's definition of context in bracketed strings, written for this check
only (it shares nothing with selfsim, nor with tests/lsystem/reference_check.py): a module's left context
is the nearest symbol to its left that is not ignored, skipping whole completed branches `[...]` and
stepping out of the module's own branch past its `[` to the parent; its right context is the nearest
symbol to its right that is not ignored, skipping whole branches `[...]`; the `]` that ends the module's
own branch ends it (no right context there, so no rule with one applies). The five figures' rules are
typed here from the book, independently of examples/abop/fig1_31.lua, whose strings (`--set strings=1`)
must equal these at LEVEL (default 30, the book's largest n). Exit 1 on any difference, naming the
figure, the first differing position and the text around it.
"""
import subprocess
import sys
import tempfile

IGNORE = set("+-F")
KEYS = ["000", "001", "010", "011", "100", "101", "110", "111"]  # left, module, right
FIGURES = {  # axiom, successors of 0<0>0 0<0>1 0<1>0 0<1>1 1<0>0 1<0>1 1<1>0 1<1>1 (ABOP p. 35)
    "a": ("F1F1F1", ["0", "1[+F1F1]", "1", "1", "0", "1F1", "0", "0"]),
    "b": ("F1F1F1", ["1", "1[-F1F1]", "1", "1", "0", "1F1", "1", "0"]),
    "c": ("F1F1F1", ["0", "1", "0", "1[+F1F1]", "0", "1F1", "0", "0"]),
    "d": ("F0F1F1", ["1", "0", "0", "1F1", "1", "1[+F1F1]", "1", "0"]),
    "e": ("F1F1F1", ["0", "1[-F1F1]", "1", "1", "0", "1F1", "1", "0"]),
}


def left_context(s, i):
    j, depth = i - 1, 0
    while j >= 0:
        c = s[j]
        if c == "]":
            depth += 1          # a completed branch: skip it whole
        elif c == "[":
            if depth > 0:
                depth -= 1      # the start of the branch being skipped
            # else: the start of the module's own branch: step out to the parent
        elif depth == 0 and c not in IGNORE:
            return c
        j -= 1
    return None


def right_context(s, i):
    j, depth = i + 1, 0
    while j < len(s):
        c = s[j]
        if c == "[":
            depth += 1          # a branch: skip it whole
        elif c == "]":
            if depth == 0:
                return None     # the end of the module's own branch ends its right context
            depth -= 1
        elif depth == 0 and c not in IGNORE:
            return c
        j += 1
    return None


def step(s, table):
    out = []
    for i, c in enumerate(s):
        if c in "01":
            left, right = left_context(s, i), right_context(s, i)
            key = f"{left}{c}{right}"
            out.append(table[key] if key in table else c)
        elif c == "+":
            out.append("-")
        elif c == "-":
            out.append("+")
        else:
            out.append(c)
    return "".join(out)


def derive(name, level):
    axiom, successors = FIGURES[name]
    table = dict(zip(KEYS, successors))
    s = axiom
    for _ in range(level):
        s = step(s, table)
    return s


def main():
    selfsim, src = sys.argv[1], sys.argv[2]
    level = int(sys.argv[3]) if len(sys.argv) > 3 else 30
    with tempfile.TemporaryDirectory() as out:
        run = subprocess.run([selfsim, "run", f"{src}/examples/abop/fig1_31.lua", "-o", out, "-q", "--set",
                              "strings=1", "--set", f"level={level}"], capture_output=True, text=True, timeout=120)
    if run.returncode != 0:
        print(f"selfsim run failed ({run.returncode}): {run.stderr.strip()}")
        return 1
    got = dict(line.split("\t", 1) for line in run.stdout.splitlines() if "\t" in line)
    failures = 0
    for name in FIGURES:
        want = derive(name, level)
        have = got.get(name)
        if have is None:
            print(f"1.31{name}: selfsim printed no string")
            failures += 1
        elif have != want:
            k = next((k for k in range(min(len(have), len(want))) if have[k] != want[k]), min(len(have), len(want)))
            print(f"1.31{name} level {level}: differs at {k} (selfsim {len(have)} symbols, book {len(want)}):\n"
                  f"  selfsim ...{have[max(0, k - 30):k + 30]}\n  book    ...{want[max(0, k - 30):k + 30]}")
            failures += 1
        else:
            print(f"1.31{name} level {level}: {len(want)} symbols, equal")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

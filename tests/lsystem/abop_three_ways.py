#!/usr/bin/env python3
"""Issue 39: each ABOP figure's model gives the same string three ways.

Usage: python3 tests/lsystem/abop_three_ways.py SELFSIM SOURCE_DIR

For every recipe of examples/abop/ and each of its variants, runs abop_three_ways.lua (beside this file) in a
temporary copy of examples/abop/: the recipe's own lsystem{} grammars, the book's text of each sub-figure
(book_texts.lua, read by lsystem.book) and its .l file (read by lsystem.load) must give the same strings at
levels 0-3 and the book's n; every .l file is one of them, and from_l_file.lua draws each. Then it shows the
check can fail: one rule changed in a copy of a .l file, of a book text and of a recipe each makes the run
fail with a message naming that sub-figure. Exit 1 on any difference, naming the figure.
"""
import os
import shutil
import subprocess
import sys
import tempfile

RECIPES = {  # recipe: number of variants (its `variant` parameter), 1 where it has none
    "fig1_8": 1, "fig1_24": 1, "fig1_25": 1, "fig1_26": 1, "fig1_27": 1, "fig1_31": 1,
    "fig2_6": 4, "fig2_7": 4, "fig2_8": 4,
}
# One changed rule each, in a copy: (file, text, replacement, recipe, variant, the sub-figure the failure names).
MUTATIONS = [
    ("fig1_31c.l", "0 < 1 > 1 --> 1[+F1F1]", "0 < 1 > 1 --> 1[-F1F1]", "fig1_31", 1, "fig1_31c"),
    ("book_texts.lua", "p1 : A(l,w) : * → !(w)F(l)[&(a1)B(l*r1,w*wr)]/(180)",
     "p1 : A(l,w) : * → !(w)F(l)[&(a1)B(l*r1,w*wr)]/(181)", "fig2_7", 3, "fig2_7c"),
    ("fig1_24.lua", 'rules = { F = "F[+F]F[-F][F]" }', 'rules = { F = "F[+F]F[-F]F" }', "fig1_24", 1, "fig1_24b"),
]


def run(selfsim, folder, figure, variant):
    result = subprocess.run(
        [selfsim, "run", os.path.join(folder, "abop_three_ways.lua"), "-o", os.path.join(folder, "out"), "-q",
         "--set", "figure=" + figure, "--set", "variant=%d" % variant],
        capture_output=True, text=True, timeout=120)
    return result.returncode, result.stdout, result.stderr


def copy(source, folder):
    abop = os.path.join(source, "examples", "abop")
    for name in os.listdir(abop):
        shutil.copy(os.path.join(abop, name), folder)
    shutil.copy(os.path.join(os.path.dirname(os.path.abspath(__file__)), "abop_three_ways.lua"), folder)


def main():
    selfsim, source = sys.argv[1], sys.argv[2]
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        folder = os.path.join(tmp, "abop")
        os.mkdir(folder)
        copy(source, folder)
        checked = set()
        for figure, variants in RECIPES.items():
            for variant in range(1, variants + 1):
                rc, out, err = run(selfsim, folder, figure, variant)
                if rc != 0:
                    failures.append("%s variant %d: %s" % (figure, variant, err.strip()))
                else:
                    sys.stdout.write(out)
                    checked.update(line.split(":")[0] for line in out.splitlines())
        # Every .l file of the folder is some checked sub-figure's: a new one without its recipe is noticed.
        for name in sorted(os.listdir(folder)):
            if name.endswith(".l") and name[:-2] not in checked:
                failures.append("%s: no recipe of RECIPES makes its figure, so it is not checked" % name)
        # from_l_file.lua (the docs' way to run a .l file) draws each one.
        for name in sorted(os.listdir(folder)):
            if not name.endswith(".l"):
                continue
            out = os.path.join(folder, "drawn_" + name[:-2])
            result = subprocess.run([selfsim, "run", os.path.join(folder, "from_l_file.lua"), "-o", out, "-q",
                                     "--set", "file=" + name[:-2], "--set", "level=2"],
                                    capture_output=True, text=True, timeout=120)
            if result.returncode != 0 or not os.path.isfile(os.path.join(out, name[:-2] + ".vtp")):
                failures.append("from_l_file.lua --set file=%s: rc %d, %s" % (name[:-2], result.returncode,
                                                                               result.stderr.strip()))
        for name, text, changed, figure, variant, names in MUTATIONS:
            shutil.rmtree(folder)
            os.mkdir(folder)
            copy(source, folder)
            path = os.path.join(folder, name)
            with open(path, encoding="utf-8") as f:
                content = f.read()
            if text not in content:
                failures.append("mutation: %r not found in %s (update MUTATIONS)" % (text, name))
                continue
            with open(path, "w", encoding="utf-8") as f:
                f.write(content.replace(text, changed, 1))
            rc, _, err = run(selfsim, folder, figure, variant)
            if rc == 0 or names + ": level" not in err:
                failures.append("a rule changed in %s (%s) was not caught naming %s: rc %d, %s" %
                                (name, changed, names, rc, err.strip()))
            else:
                print("caught: %s changed -> %s" % (name, err.strip().splitlines()[0]))
    for f in failures:
        print("FAIL " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Differential test of selfsim's L-system rewriting against an independent Python reference.

Usage: python3 tests/lsystem/reference_check.py PATH_TO_SELFSIM [--verbose]

The reference below implements the rewriting as documented in docs/curves.md ("L-systems" and "Rules
beyond replacement"): module strings with parameters, rule order (context rules first, then the others,
each in written order), predecessor arity, conditions, branch-aware left and right contexts with an ignore
list, stochastic choice by lineage (hash from kernels/lsystem/module_rewrite.h), and the cut `%`. It does
not share code with the C++ matcher: only the lineage hash (splitmix64 finaliser `mix`, `child_lineage`,
`choose_option`) is taken from the C++ so that the choices can be reproduced.

Many seeded random grammars (deterministic: random.Random(FIXED_SEED)) plus fixed cases from ABOP are
written into one Lua recipe, run once through `selfsim run`, and every printed `g:string(n)` is compared
with the reference. Exit status 1 on any mismatch, with the grammar, level and first differing position.
"""

import math
import os
import random
import re
import subprocess
import sys
import tempfile
import time

FIXED_SEED = 20240611
MAX_MODULES = 20000      # no level of a generated grammar exceeds this many modules
MAX_CHARS = 400000       # nor this many characters of text

# ---------------------------------------------------------------------------------------------------
# Numbers as selfsim prints them: C++ std::to_chars(double) without a format, i.e. the shortest digits
# that read back exactly, in fixed or scientific notation, whichever is shorter (fixed on a tie).
# ---------------------------------------------------------------------------------------------------


def fmt_number(x):
    if x == 0:
        return "-0" if math.copysign(1.0, x) < 0 else "0"
    sign = "-" if x < 0 else ""
    a = abs(x)
    r = repr(a)                       # shortest round-trip digits
    if "e" in r:
        mant, exp = r.split("e")
        exp = int(exp)
    else:
        mant, exp = r, 0
    if "." in mant:
        ip, fp = mant.split(".")
    else:
        ip, fp = mant, ""
    digits = ip + fp
    # value = 0.digits... ; position the decimal exponent of the first significant digit
    e10 = exp + len(ip) - 1
    stripped = digits.lstrip("0")
    e10 -= len(digits) - len(stripped)
    digits = stripped.rstrip("0") or "0"
    sci = digits[0] + ("." + digits[1:] if len(digits) > 1 else "") + "e" + ("+" if e10 >= 0 else "-") + \
        "%02d" % abs(e10)
    if e10 >= len(digits) - 1:
        fixed = digits + "0" * (e10 - len(digits) + 1)
        integral = True
    elif e10 >= 0:
        fixed = digits[:e10 + 1] + "." + digits[e10 + 1:]
        integral = False
    else:
        fixed = "0." + "0" * (-e10 - 1) + digits
        integral = False
    if len(fixed) <= len(sci):
        if integral:
            fixed = str(int(a))       # to_chars writes a large integer's exact value in fixed notation
        return sign + fixed
    return sign + sci


# ---------------------------------------------------------------------------------------------------
# Expressions: numbers, parameters, pi, + - * / ^, comparisons, && || !, parentheses, a few functions.
# ---------------------------------------------------------------------------------------------------

_TOKEN = re.compile(r"\s*(?:(\d+\.?\d*(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?)|([A-Za-z_][A-Za-z_0-9]*)|"
                    r"(==|!=|<=|>=|&&|\|\||[-+*/^()<>!,]))")


class ExprError(Exception):
    pass


def tokenize(text):
    out = []
    pos = 0
    text = text.rstrip()
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if not m or m.end() == pos:
            raise ExprError("bad expression %r at %d" % (text, pos))
        if m.group(1):
            out.append(("num", float(m.group(1))))
        elif m.group(2):
            out.append(("id", m.group(2)))
        else:
            out.append(("op", m.group(3)))
        pos = m.end()
    out.append(("end", None))
    return out


def _b(v):
    return 1.0 if v else 0.0


def _deg(f):
    return lambda v: f(math.radians(v))


FUNCS = {
    "sin": _deg(math.sin), "cos": _deg(math.cos), "tan": _deg(math.tan),
    "asin": lambda v: math.degrees(math.asin(v)), "acos": lambda v: math.degrees(math.acos(v)),
    "atan": lambda v: math.degrees(math.atan(v)),
    "atan2": lambda y, x: math.degrees(math.atan2(y, x)),
    "sqrt": math.sqrt, "abs": abs, "floor": lambda v: float(math.floor(v)),
    "ceil": lambda v: float(math.ceil(v)), "exp": math.exp, "log": math.log, "min": min, "max": max,
    "pow": lambda a, b: math.pow(a, b),
}


class Parser:
    """Recursive descent; returns a closure env -> float."""

    def __init__(self, text):
        self.text = text
        self.toks = tokenize(text)
        self.i = 0

    def peek(self):
        return self.toks[self.i]

    def take(self):
        t = self.toks[self.i]
        self.i += 1
        return t

    def expect(self, op):
        t = self.take()
        if t != ("op", op):
            raise ExprError("expected %r in %r" % (op, self.text))

    def parse(self):
        e = self.p_or()
        if self.peek()[0] != "end":
            raise ExprError("trailing input in %r" % self.text)
        return e

    def p_or(self):
        a = self.p_and()
        while self.peek() == ("op", "||"):
            self.take()
            b = self.p_and()
            a = (lambda a, b: lambda env: _b(a(env) != 0 or b(env) != 0))(a, b)
        return a

    def p_and(self):
        a = self.p_eq()
        while self.peek() == ("op", "&&"):
            self.take()
            b = self.p_eq()
            a = (lambda a, b: lambda env: _b(a(env) != 0 and b(env) != 0))(a, b)
        return a

    def p_eq(self):
        a = self.p_rel()
        while self.peek() in (("op", "=="), ("op", "!=")):
            op = self.take()[1]
            b = self.p_rel()
            if op == "==":
                a = (lambda a, b: lambda env: _b(a(env) == b(env)))(a, b)
            else:
                a = (lambda a, b: lambda env: _b(a(env) != b(env)))(a, b)
        return a

    def p_rel(self):
        a = self.p_add()
        ops = {"<": lambda x, y: x < y, "<=": lambda x, y: x <= y, ">": lambda x, y: x > y,
               ">=": lambda x, y: x >= y}
        while self.peek()[0] == "op" and self.peek()[1] in ops:
            f = ops[self.take()[1]]
            b = self.p_add()
            a = (lambda a, b, f: lambda env: _b(f(a(env), b(env))))(a, b, f)
        return a

    def p_add(self):
        a = self.p_mul()
        while self.peek() in (("op", "+"), ("op", "-")):
            op = self.take()[1]
            b = self.p_mul()
            if op == "+":
                a = (lambda a, b: lambda env: a(env) + b(env))(a, b)
            else:
                a = (lambda a, b: lambda env: a(env) - b(env))(a, b)
        return a

    def p_mul(self):
        a = self.p_unary()
        while self.peek() in (("op", "*"), ("op", "/")):
            op = self.take()[1]
            b = self.p_unary()
            if op == "*":
                a = (lambda a, b: lambda env: a(env) * b(env))(a, b)
            else:
                def div(env, a=a, b=b):
                    d = b(env)
                    if d == 0:
                        raise ExprError("division by zero")
                    return a(env) / d
                a = div
        return a

    def p_unary(self):
        t = self.peek()
        if t == ("op", "-"):
            self.take()
            a = self.p_unary()
            return lambda env: -a(env)
        if t == ("op", "+"):
            self.take()
            return self.p_unary()
        if t == ("op", "!"):
            self.take()
            a = self.p_unary()
            return lambda env: _b(a(env) == 0)
        return self.p_pow()

    def p_pow(self):
        a = self.p_primary()
        if self.peek() == ("op", "^"):
            self.take()
            b = self.p_unary()      # right-associative, binds tighter than a unary minus on its left
            return lambda env: math.pow(a(env), b(env))
        return a

    def p_primary(self):
        t = self.take()
        if t[0] == "num":
            v = t[1]
            return lambda env: v
        if t[0] == "id":
            name = t[1]
            if self.peek() == ("op", "("):
                self.take()
                args = [self.p_or()]
                while self.peek() == ("op", ","):
                    self.take()
                    args.append(self.p_or())
                self.expect(")")
                f = FUNCS[name]
                return lambda env: float(f(*[x(env) for x in args]))
            if name == "pi":
                return lambda env: math.pi
            return lambda env: env[name]
        if t == ("op", "("):
            e = self.p_or()
            self.expect(")")
            return e
        raise ExprError("unexpected %r in %r" % (t, self.text))


def compile_expr(text):
    return Parser(text).parse()


# ---------------------------------------------------------------------------------------------------
# Module strings: a symbol is any byte but whitespace, ( ) and ,; its parameters follow it directly.
# ---------------------------------------------------------------------------------------------------


def split_modules(text):
    """[(symbol, [arg texts])] of a module string (axiom, successor or context pattern)."""
    out = []
    i = 0
    n = len(text)
    while i < n:
        c = text[i]
        if c.isspace():
            i += 1
            continue
        if c in "(),":
            raise ValueError("unexpected %r in %r" % (c, text))
        i += 1
        args = []
        if i < n and text[i] == "(":
            depth = 0
            start = i + 1
            j = i
            while True:
                ch = text[j]
                if ch == "(":
                    depth += 1
                elif ch == ")":
                    depth -= 1
                    if depth == 0:
                        args.append(text[start:j])
                        break
                elif ch == "," and depth == 1:
                    args.append(text[start:j])
                    start = j + 1
                j += 1
            i = j + 1
        out.append((c, args))
    return out


class Call:
    """A module of a successor or axiom: symbol, compiled argument expressions, lineage salt."""
    __slots__ = ("sym", "args", "salt")

    def __init__(self, sym, args, salt):
        self.sym = sym
        self.args = args
        self.salt = salt


def compile_calls(text):
    calls = []
    seen = {}
    for sym, args in split_modules(text):
        k = seen.get(sym, 0)
        seen[sym] = k + 1
        calls.append(Call(sym, [compile_expr(a) for a in args], (ord(sym) << 32) | k))
    return calls


# ---------------------------------------------------------------------------------------------------
# Lineage hash (kernels/lsystem/module_rewrite.cpp: mix, child_lineage, choose_option)
# ---------------------------------------------------------------------------------------------------

M64 = (1 << 64) - 1


def mix(z):
    z = (z + 0x9e3779b97f4a7c15) & M64
    z = ((z ^ (z >> 30)) * 0xbf58476d1ce4e5b9) & M64
    z = ((z ^ (z >> 27)) * 0x94d049bb133111eb) & M64
    return z ^ (z >> 31)


def child_lineage(parent, salt):
    return mix(parent ^ mix(salt))


def choose_option(weights, u):
    total = 0.0
    for w in weights:
        total += w
    below = 0.0
    for k in range(len(weights) - 1):
        below += weights[k]
        if u * total < below:
            return k
    k = len(weights) - 1
    while k > 0 and weights[k] == 0:
        k -= 1
    return k


# ---------------------------------------------------------------------------------------------------
# Rules
# ---------------------------------------------------------------------------------------------------


class Pattern:
    __slots__ = ("sym", "params")

    def __init__(self, sym, params):
        self.sym = sym
        self.params = params


def parse_pattern(text):
    out = []
    for sym, args in split_modules(text):
        params = [a.strip() for a in args]
        out.append(Pattern(sym, params))
    return out


class Rule:
    def __init__(self, lhs_text, left, pred, right, cond):
        self.lhs_text = lhs_text
        self.left = left
        self.pred = pred
        self.right = right
        self.cond = cond
        self.options = []   # [(weight, [Call])]

    @property
    def has_context(self):
        return bool(self.left) or bool(self.right)


_WEIGHT = re.compile(r"^(.*):\s*([0-9.eE+-]+)\s*$", re.S)


def parse_rules(rule_texts):
    """Rules from ABOP rule strings '[left <] pred [> right] [: cond] -> succ [: weight]', grouped."""
    rules = []
    by_lhs = {}
    for text in rule_texts:
        lhs, rhs = text.split("->", 1)
        weight = None
        m = _WEIGHT.match(rhs)
        if m:
            rhs, weight = m.group(1), float(m.group(2))
        key = lhs.strip()
        if ":" in lhs:
            ctx, cond_text = lhs.split(":", 1)
            cond = compile_expr(cond_text)
        else:
            ctx, cond = lhs, None
        left_text = ""
        right_text = ""
        if "<" in ctx:
            left_text, ctx = ctx.split("<", 1)
        if ">" in ctx:
            ctx, right_text = ctx.split(">", 1)
        pred = parse_pattern(ctx)
        assert len(pred) == 1, text
        calls = compile_calls(rhs)
        if weight is not None and key in by_lhs:
            by_lhs[key].options.append((weight, calls))
            continue
        r = Rule(key, parse_pattern(left_text), pred[0], parse_pattern(right_text), cond)
        r.options.append((1.0 if weight is None else weight, calls))
        if weight is not None:
            by_lhs[key] = r
        rules.append(r)
    return rules


# ---------------------------------------------------------------------------------------------------
# Derivation
# ---------------------------------------------------------------------------------------------------

DEFAULT_IGNORE = "+-&^\\/|$"


class Grammar:
    def __init__(self, axiom, rules, seed=0, ignore=None):
        self.axiom_text = axiom
        self.rule_texts = list(rules)
        self.seed = seed
        self.ignore_text = ignore
        self.ignore = set(DEFAULT_IGNORE if ignore is None else ignore)
        self.rules = parse_rules(self.rule_texts)
        self.by_sym = {}
        ordered = [r for r in self.rules if r.has_context] + [r for r in self.rules if not r.has_context]
        for r in ordered:
            self.by_sym.setdefault(r.pred.sym, []).append(r)
        self.axiom_calls = compile_calls(axiom)

    # A level is a list of modules (sym, args tuple, lineage).
    def level0(self):
        root = mix(self.seed)
        s = [(c.sym, tuple(a({}) for a in c.args), child_lineage(root, c.salt)) for c in self.axiom_calls]
        return apply_cut(s)

    def step(self, s):
        match = bracket_match(s)
        out = []
        for i, (sym, args, lin) in enumerate(s):
            rules = self.by_sym.get(sym)
            done = False
            if rules:
                for r in rules:
                    if len(r.pred.params) != len(args):
                        continue
                    env = dict(zip(r.pred.params, args))
                    if r.left and not self.match_left(s, match, i, r.left, env):
                        continue
                    if r.right and not self.match_right(s, match, i, r.right, env):
                        continue
                    if r.cond is not None and r.cond(env) == 0:
                        continue
                    if len(r.options) > 1:
                        k = choose_option([w for w, _ in r.options], (lin >> 11) * 2.0 ** -53)
                    else:
                        k = 0
                    for c in r.options[k][1]:
                        out.append((c.sym, tuple(a(env) for a in c.args), child_lineage(lin, c.salt)))
                    done = True
                    break
            if not done:
                out.append((sym, args, lin))
        return apply_cut(out)

    def match_left(self, s, match, i, pat, env):
        j = i - 1
        k = len(pat) - 1
        while k >= 0:
            if j < 0:
                return False
            sym = s[j][0]
            if sym == "]":
                j = match[j] - 1        # a completed branch
                continue
            if sym == "[" or sym in self.ignore:
                j -= 1                  # the '[' opening the module's own branch, or an ignored symbol
                continue
            p = pat[k]
            if sym != p.sym or len(s[j][1]) != len(p.params):
                return False
            env.update(zip(p.params, s[j][1]))
            k -= 1
            j -= 1
        return True

    def match_right(self, s, match, i, pat, env):
        n = len(s)
        j = i + 1
        entered = 0
        for p in pat:
            if p.sym == "[":
                while j < n and s[j][0] in self.ignore:
                    j += 1
                if j >= n or s[j][0] != "[":
                    return False
                j += 1
                entered += 1
            elif p.sym == "]":
                if entered == 0:
                    raise ValueError("']' in a right context without '['")
                depth = 0
                while j < n:
                    sym = s[j][0]
                    if sym == "[":
                        depth += 1
                    elif sym == "]":
                        if depth == 0:
                            break
                        depth -= 1
                    j += 1
                if j >= n:
                    return False
                j += 1
                entered -= 1
            else:
                while True:
                    if j >= n:
                        return False
                    sym = s[j][0]
                    if sym == "[":
                        j = match[j] + 1      # a branch the pattern does not enter
                        continue
                    if sym == "]":
                        return False          # end of the branch
                    if sym in self.ignore:
                        j += 1
                        continue
                    break
                if sym != p.sym or len(s[j][1]) != len(p.params):
                    return False
                env.update(zip(p.params, s[j][1]))
                j += 1
        return True


def bracket_match(s):
    match = {}
    stack = []
    for i, m in enumerate(s):
        if m[0] == "[":
            stack.append(i)
        elif m[0] == "]":
            if stack:
                o = stack.pop()
                match[o] = i
                match[i] = o
    for o in stack:      # unclosed: the branch runs to the end
        match[o] = len(s) - 1
    return match


def apply_cut(s):
    """'%' removes itself and the rest of its branch (up to, not including, the ']' closing it)."""
    if not any(m[0] == "%" for m in s):
        return s
    out = []
    i = 0
    n = len(s)
    while i < n:
        m = s[i]
        if m[0] != "%":
            out.append(m)
            i += 1
            continue
        depth = 0
        i += 1
        while i < n:
            sym = s[i][0]
            if sym == "[":
                depth += 1
            elif sym == "]":
                if depth == 0:
                    break
                depth -= 1
            i += 1
    return out


def text_of(s):
    parts = []
    for sym, args, _ in s:
        if args:
            parts.append(sym + "(" + ",".join(fmt_number(a) for a in args) + ")")
        else:
            parts.append(sym)
    return "".join(parts)


# ---------------------------------------------------------------------------------------------------
# Random grammars
# ---------------------------------------------------------------------------------------------------


def rand_plain_string(rng, letters, length, turns="+-", branch_p=0.2, depth=0, cut_p=0.0):
    out = []
    for _ in range(length):
        x = rng.random()
        if x < branch_p and depth < 2:
            out.append("[" + rand_plain_string(rng, letters, rng.randint(1, 3), turns, branch_p, depth + 1,
                                               cut_p) + "]")
        elif x < branch_p + 0.2 and turns:
            out.append(rng.choice(turns))
        elif x < branch_p + 0.2 + cut_p:
            out.append("%")
        else:
            out.append(rng.choice(letters))
    return "".join(out)


def gen_plain(rng, cut=False):
    letters = rng.sample("ABCFGXY", rng.randint(2, 4))
    rules = []
    for sym in rng.sample(letters, rng.randint(1, len(letters))):
        rules.append("%s -> %s" % (sym, rand_plain_string(rng, letters, rng.randint(0 if cut else 1, 5),
                                                          cut_p=0.15 if cut else 0.0)))
    axiom = rand_plain_string(rng, letters, rng.randint(1, 5), cut_p=0.1 if cut else 0.0) or letters[0]
    return dict(axiom=axiom, rules=rules, seed=rng.randint(0, 1000))


def rand_weight(rng):
    return rng.choice(["0.1", "0.25", "0.3", "0.5", "0.7", "1", "2", "3", "1.5", "0", "0.33"])


def gen_stochastic(rng, cut=False):
    letters = rng.sample("ABCFGXY", rng.randint(2, 3))
    rules = []
    for sym in rng.sample(letters, rng.randint(1, len(letters))):
        weights = [rand_weight(rng) for _ in range(rng.randint(2, 3))]
        if all(float(w) == 0 for w in weights):
            weights[-1] = "1"
        for w in weights:
            rules.append("%s -> %s : %s" % (sym, rand_plain_string(rng, letters, rng.randint(1, 5),
                                                                   cut_p=0.1 if cut else 0.0), w))
    # sometimes interleave a deterministic rule for another symbol between the choices
    if rng.random() < 0.3 and len(rules) > 2:
        rules.insert(1, "Z -> %s" % rand_plain_string(rng, letters, 2))
        letters = letters + ["Z"]
    axiom = rand_plain_string(rng, letters, rng.randint(1, 5))
    seed = rng.choice([0, 1, 7, 2 ** 53, rng.randint(0, 2 ** 53), rng.randint(0, 100000)])
    return dict(axiom=axiom, rules=rules, seed=seed)


def rand_ctx_string(rng, letters, length, branch_p=0.25):
    return rand_plain_string(rng, letters, length, "+-", branch_p)


def rand_right_pattern(rng, letters):
    kind = rng.random()
    L = lambda: rng.choice(letters)
    if kind < 0.4:
        return L()
    if kind < 0.6:
        return L() + L()
    forms = ["[{a}", "[{a}]{b}", "{a}[{b}]", "[{a}{b}]", "[{a}]", "[{a}][{b}]", "{a}[{b}]{c}", "[{a}[{b}]]{c}"]
    return rng.choice(forms).format(a=L(), b=L(), c=L())


def sample_contexts(rng, text, ignore):
    """A (predecessor, left, right) read off a real neighbourhood of text, so that context rules fire."""
    syms = [m[0] for m in split_modules(text)]
    ign = set(DEFAULT_IGNORE if ignore is None else ignore)
    match = bracket_match([(c, (), 0) for c in syms])
    cands = [i for i, c in enumerate(syms) if c not in "[]+-%" and c not in ign]
    if not cands:
        return None
    i = rng.choice(cands)
    left = ""
    if rng.random() < 0.6:
        j = i - 1
        want = rng.randint(1, 2)
        while j >= 0 and len(left) < want:
            c = syms[j]
            if c == "]":
                j = match[j] - 1
            elif c == "[" or c in ign:
                j -= 1
            else:
                left = c + left
                j -= 1
    right = ""
    if not left or rng.random() < 0.5:
        j = i + 1
        n = len(syms)
        want = rng.randint(1, 3)
        got = 0
        entered = 0
        while j < n and got < want:
            c = syms[j]
            if c in ign:
                j += 1
            elif c == "]":
                if entered and rng.random() < 0.7:
                    right += "]"      # skip the rest of the entered branch
                    entered -= 1
                    j += 1
                    continue
                break
            elif c == "[":
                if rng.random() < 0.5:
                    right += "["
                    entered += 1
                    j += 1
                else:
                    j = match[j] + 1
            else:
                right += c
                got += 1
                j += 1
        right = right.rstrip("[")
    if rng.random() < 0.2:        # perturb one symbol, so the context sometimes fails
        pool = [k for k, c in enumerate(left + right) if c not in "[]"]
        if pool:
            k = rng.choice(pool)
            both = list(left + right)
            both[k] = rng.choice("abc")
            left, right = "".join(both[:len(left)]), "".join(both[len(left):])
    return syms[i], left, right


def gen_context(rng, stochastic=False, cut=False):
    letters = list("abc") + (["d"] if rng.random() < 0.4 else [])
    ignore = rng.choice([None, "+-", "+-c", "", "c", "+", None])
    axiom = rand_ctx_string(rng, letters, rng.randint(5, 12))
    if cut and rng.random() < 0.3:
        k = rng.randint(1, len(axiom))
        axiom = axiom[:k] + "%" + axiom[k:]
    rules = []
    nrules = rng.randint(2, 6)
    for _ in range(nrules):
        sampled = sample_contexts(rng, axiom, ignore) if rng.random() < 0.6 else None
        if sampled:
            pred, left, right = sampled
        else:
            pred = rng.choice(letters)
            kind = rng.random()
            left = right = ""
            if kind < 0.35:
                left = "".join(rng.choice(letters) for _ in range(rng.randint(1, 2)))
            elif kind < 0.7:
                right = rand_right_pattern(rng, letters)
            else:
                left = rng.choice(letters)
                right = rand_right_pattern(rng, letters)
        lhs = pred
        if left:
            lhs = left + " < " + lhs
        if right:
            lhs = lhs + " > " + right
        others = [c for c in letters if c != pred]

        def succ_text():
            t = rand_ctx_string(rng, letters, rng.choice([1, 1, 1, 2, 3]), branch_p=0.15)
            return rng.choice(others) if t == pred else t
        if stochastic and rng.random() < 0.6:
            ws = [rand_weight(rng) for _ in range(rng.randint(2, 3))]
            if all(float(w) == 0 for w in ws):
                ws[0] = "1"
            for w in ws:
                rules.append("%s -> %s : %s" % (lhs, succ_text(), w))
        else:
            succ = succ_text()
            if cut and rng.random() < 0.3:
                succ = succ + "%" if rng.random() < 0.5 else "[" + succ + "%" + rng.choice(letters) + "]"
            rules.append("%s -> %s" % (lhs, succ))
    # context-free rules too (tried after the context rules wherever they are written)
    for _ in range(rng.choice([0, 1, 1, 2])):
        pred = rng.choice(letters)
        succ = rng.choice([c for c in letters if c != pred])
        if rng.random() < 0.3:
            succ += rand_ctx_string(rng, letters, 1)
        rules.insert(rng.randint(0, len(rules)), "%s -> %s" % (pred, succ))
    return dict(axiom=axiom, rules=rules, seed=rng.randint(0, 2 ** 40), ignore=ignore)


def rand_const(rng):
    return rng.choice(["0.5", "1", "2", "3", "0.25", "1.5", "10", "0.1", "4", "0.75", "7"])


def rand_expr(rng, params, depth=0):
    """An arithmetic expression of params, written with the fewest parentheses that keep its order of
    evaluation; divides only by nonzero constants and never multiplies two parameters."""
    return _rand_expr(rng, params, depth)[0]


def _rand_expr(rng, params, depth):
    # returns (text, precedence): 3 atom, 2 product or quotient, 1 sum or difference
    if depth >= 2 or rng.random() < 0.3:
        if params and rng.random() < 0.7:
            return rng.choice(params), 3
        return rand_const(rng), 3
    wrap = lambda e, need: e[0] if e[1] >= need else "(" + e[0] + ")"
    if rng.random() < 0.08:
        return "-" + wrap(_rand_expr(rng, params, depth + 1), 3), 2
    op = rng.choice("+-*/")
    if op in "+-":
        a = _rand_expr(rng, params, depth + 1)
        b = _rand_expr(rng, params, depth + 1)
        return wrap(a, 1) + " " + op + " " + wrap(b, 2), 1
    e = _rand_expr(rng, params, depth + 1)
    c = (rand_const(rng), 3)
    a, b = (c, e) if op == "*" and rng.random() < 0.5 else (e, c)
    return wrap(a, 2) + " " + op + " " + wrap(b, 3), 2


def rand_cond(rng, params):
    def cmp():
        return "%s %s %s" % (rand_expr(rng, params, 1), rng.choice(["<", "<=", ">", ">=", "==", "!="]),
                             rand_const(rng) if rng.random() < 0.7 else rand_expr(rng, params, 1))
    x = rng.random()
    if x < 0.6:
        return cmp()
    if x < 0.8:
        return "%s %s %s" % (cmp(), rng.choice(["&&", "||"]), cmp())
    if x < 0.9:
        return "!(%s)" % cmp()
    return "(%s) || (%s && %s)" % (cmp(), cmp(), cmp())


def gen_parametric(rng, context=False, stochastic=False, cut=False):
    # arities: A takes 1 or 2, B takes 1; written with both arities of A where A has rules for both
    a_arities = rng.choice([[1], [2], [1, 2]])
    names = ["x", "y"]

    def module(sym, arity, params):
        return "%s(%s)" % (sym, ", ".join(rand_expr(rng, params) for _ in range(arity)))

    def successor(params, length):
        parts = []
        for _ in range(length):
            x = rng.random()
            if x < 0.3:
                parts.append(module("A", rng.choice(a_arities), params))
            elif x < 0.45:
                parts.append(module("B", 1, params))
            elif x < 0.65:
                parts.append(module("F", 1, params))
            elif x < 0.75:
                parts.append(rng.choice(["+", "-"]) + ("(%s)" % rand_const(rng) if rng.random() < 0.7 else ""))
            elif x < 0.82 and cut:
                parts.append("%")
            else:
                parts.append("[" + successor(params, rng.randint(1, 2)) + "]")
        return " ".join(parts)

    rules = []
    for sym, arities in (("A", a_arities), ("B", [1])):
        for ar in arities:
            params = names[:ar] if sym == "A" else ["z"]
            for _ in range(rng.randint(1, 3)):
                lhs = "%s(%s)" % (sym, ", ".join(params))
                env_params = list(params)
                if context and rng.random() < 0.5:
                    if rng.random() < 0.5:
                        lhs = "B(w) < " + lhs
                        env_params.append("w")
                    else:
                        lhs = lhs + " > " + rng.choice(["F(v)", "[F(v)", "A(v)" if 1 in a_arities else "B(v)",
                                                        "B(v)"])
                        env_params.append("v")
                if rng.random() < 0.75:
                    lhs += " : " + rand_cond(rng, env_params)
                if stochastic and rng.random() < 0.5:
                    for _ in range(rng.randint(2, 3)):
                        rules.append("%s -> %s : %s" % (lhs, successor(env_params, rng.randint(1, 3)),
                                                        rng.choice(["1", "2", "0.5", "0.3"])))
                else:
                    rules.append("%s -> %s" % (lhs, successor(env_params, rng.randint(1, 3))))
    if rng.random() < 0.4:
        rules.append("F(s) -> F(s * %s)" % rand_const(rng))
    rng.shuffle(rules)
    axiom_parts = []
    for _ in range(rng.randint(1, 4)):
        x = rng.random()
        if x < 0.5:
            ar = rng.choice(a_arities)
            axiom_parts.append("A(%s)" % ", ".join(rng.choice(["1", "2", "0.5", "3", "5", "-1", "0"])
                                                   for _ in range(ar)))
        elif x < 0.8:
            axiom_parts.append("B(%s)" % rng.choice(["1", "2", "4", "0.5"]))
        else:
            axiom_parts.append("F(1)")
    return dict(axiom=" ".join(axiom_parts), rules=rules, seed=rng.randint(0, 2 ** 53))


# ---------------------------------------------------------------------------------------------------
# Fixed cases (ABOP, chapter 1)
# ---------------------------------------------------------------------------------------------------

FIXED = [
    # signal propagation (ABOP 1.8)
    ("abop signal", dict(axiom="baaaaaaa", rules=["b < a -> b", "b -> a"]), 8),
    # ABOP Figure 1.31a (Hogeweg and Hesper)
    ("abop fig 1.31a", dict(axiom="F1F1F1", ignore="+-F", rules=[
        "0 < 0 > 0 -> 0", "0 < 0 > 1 -> 1[+F1F1]", "0 < 1 > 0 -> 1", "0 < 1 > 1 -> 1",
        "1 < 0 > 0 -> 0", "1 < 0 > 1 -> 1F1", "1 < 1 > 0 -> 0", "1 < 1 > 1 -> 0",
        "+ -> -", "- -> +"]), 12),
    ("abop fig 1.31b", dict(axiom="F1F1F1", ignore="+-F", rules=[
        "0 < 0 > 0 -> 1", "0 < 0 > 1 -> 1[-F1F1]", "0 < 1 > 0 -> 1", "0 < 1 > 1 -> 1",
        "1 < 0 > 0 -> 0", "1 < 0 > 1 -> 1F1", "1 < 1 > 0 -> 1", "1 < 1 > 1 -> 0",
        "+ -> -", "- -> +"]), 12),
    ("abop fig 1.31c", dict(axiom="F1F1F1", ignore="+-F", rules=[
        "0 < 0 > 0 -> 0", "0 < 0 > 1 -> 1", "0 < 1 > 0 -> 0", "0 < 1 > 1 -> 1[+F1F1]",
        "1 < 0 > 0 -> 0", "1 < 0 > 1 -> 1F1", "1 < 1 > 0 -> 0", "1 < 1 > 1 -> 0",
        "+ -> -", "- -> +"]), 12),
    ("abop fig 1.31d", dict(axiom="F0F1F1", ignore="+-F", rules=[
        "0 < 0 > 0 -> 1", "0 < 0 > 1 -> 0", "0 < 1 > 0 -> 0", "0 < 1 > 1 -> 1F1",
        "1 < 0 > 0 -> 1", "1 < 0 > 1 -> 1[+F1F1]", "1 < 1 > 0 -> 1", "1 < 1 > 1 -> 0",
        "+ -> -", "- -> +"]), 12),
    ("abop fig 1.31e", dict(axiom="F1F1F1", ignore="+-F", rules=[
        "0 < 0 > 0 -> 0", "0 < 0 > 1 -> 1[-F1F1]", "0 < 1 > 0 -> 1", "0 < 1 > 1 -> 1",
        "1 < 0 > 0 -> 0", "1 < 0 > 1 -> 1F1", "1 < 1 > 0 -> 1", "1 < 1 > 1 -> 0",
        "+ -> -", "- -> +"]), 12),
    # the branch-aware context example of ABOP 1.8
    ("abop S context", dict(axiom="ABC[DE][SG[HI[JK]L]MNO]", rules=["BC < S > G[H]M -> X"]), 1),
    ("abop S context left", dict(axiom="ABC[DE][SG[HI[JK]L]MNO]", rules=["BC < S -> X"]), 1),
    ("abop S context right", dict(axiom="ABC[DE][SG[HI[JK]L]MNO]", rules=["S > G[H]M -> X"]), 1),
    # ABOP 1.10.1 parametric example
    ("abop parametric", dict(axiom="B(2)A(4,4)", rules=[
        "A(x,y) : y <= 3 -> A(x*2,x+y)", "A(x,y) : y > 3 -> B(x)A(x/y,0)",
        "B(x) : x < 1 -> C", "B(x) : x >= 1 -> B(x-1)"]), 6),
    # ABOP Figure 1.27 stochastic bush
    ("abop fig 1.27", dict(axiom="F", seed=3, rules=[
        "F -> F[+F]F[-F]F : 0.33", "F -> F[+F]F : 0.33", "F -> F[-F]F : 0.34"]), 5),
    ("docs bush", dict(axiom="F", seed=3, rules=[
        "F -> F[+F]F[-F]F : 1", "F -> F[+F]F : 1", "F -> F[-F]F : 1"]), 5),
    # ABOP Figure 1.25-style parametric tree with the docs' tree rule
    ("docs tree", dict(axiom="A(1)", rules=[
        "A(x) : x > 0.01 -> F(x) [+(30) A(x*0.6)] [-(30) A(x*0.6)]"]), 10),
    # the cut: a branch removing itself after some steps (ABOP 1.10)
    ("cut timer", dict(axiom="A(0)", rules=[
        "A(t) -> F(1) [+ B(t)] A(t+1)", "B(t) : t >= 2 -> %", "B(t) -> F(0.5) B(t+1)"]), 8),
    # lineage salts count the modules of the successor as written, the cut ones too
    ("cut and salt", dict(axiom="XXXXXXXXXXXX", seed=4, rules=[
        "X -> [B%A]A[A]", "A -> P : 1", "A -> Q : 1", "A -> R : 1"]), 2),
    ("cut top", dict(axiom="A B % C [D] E", rules=["A -> A B", "B -> %"]), 3),
    ("cut in successor", dict(axiom="X", rules=["X -> F[+X%F[X]]F[-X]%X"]), 5),
    # ignored symbols in both contexts, the default ignore list
    ("ignore default", dict(axiom="a+b-[c]&b^a", rules=["a < b > a -> X", "b < a -> Y", "c > b -> Z"]), 2),
    # arity: rules for A with one and two parameters, context binds parameters
    ("arity", dict(axiom="A(1) A(1,2) B(3) A(2)", rules=[
        "A(x) -> A(x+1)", "A(x,y) : x < y -> A(y,x)", "B(z) < A(x) : z > x -> C(z-x)"]), 4),
    # a stochastic signal: the a's keep their axiom lineage until the signal reaches them
    ("stochastic signal", dict(axiom="baaaaaaaaaaaaaaa[aaaa]aaaa", seed=11, rules=[
        "b < a -> b : 1", "b < a -> c : 1", "b < a -> d : 1", "b -> e", "c -> b", "d -> b"]), 24),
    ("stochastic condition later", dict(axiom="A(0) A(0) A(0) A(0) A(0) A(0) A(0) A(0)", seed=5, rules=[
        "T(t) -> T(t+1)", "A(t) < T(u) -> T(u)", "A(t) : t < 3 -> A(t+1)", "A(t) -> X : 1", "A(t) -> Y : 2",
        "X -> A(0)", "Y -> A(1)"]), 12),
    # right and left contexts around branches and ignored symbols
    ("ctx ignored before [", dict(axiom="a+[b]", rules=["a > [b -> X"]), 1),
    ("ctx other branch first", dict(axiom="a[c][b]", rules=["a > [b -> X"]), 1),
    ("ctx other branch first closed", dict(axiom="a[c][b]", rules=["a > [b] -> X"]), 1),
    ("ctx branch then ignored", dict(axiom="a[c]+[b]", rules=["a > [c]b -> X"]), 1),
    ("ctx branch then symbol", dict(axiom="a[c]+b", rules=["a > [c]b -> X"]), 1),
    ("ctx skip rest", dict(axiom="a[c[d]e]b", rules=["a > [c]b -> X", "c > [d]e -> Y", "d > e -> Z"]), 1),
    ("ctx nested pattern", dict(axiom="a[c[d]e]b", rules=["a > [c[d]]b -> X", "c > [d] -> Y"]), 1),
    ("ctx enter nested", dict(axiom="a[c[d]e]b", rules=["a > [c[d -> X"]), 1),
    ("ctx skip inner branch", dict(axiom="a[c[d]e]b", rules=["a > [ce -> X"]), 1),
    ("ctx branch end", dict(axiom="[a]b", rules=["a > b -> X"]), 1),
    ("ctx left parent", dict(axiom="b[a]", rules=["b < a -> X"]), 1),
    ("ctx left over branches", dict(axiom="b[c]+[+a]", rules=["b < a -> X"]), 1),
    ("ctx left arity", dict(axiom="b(1)a b(1)a(2) a b(1,2)", rules=[
        "b < a -> X", "b(x) < a(y) -> Y(x,y)", "a > b(x) -> Z(x)"]), 1),
    ("ctx left two", dict(axiom="ab[c][d[e]f]g", rules=["ab < g -> X", "b < d -> Y", "bd < f -> Z", "d < e -> W"]),
     1),
    ("weighted group order", dict(axiom="AAAAAAAAAAAAAAAA", seed=2, rules=["A -> B : 1", "A -> C", "A -> D : 1"]), 1),
    ("context first", dict(axiom="abab", rules=["b -> X", "a < b -> Y", "b > a -> Z"]), 1),
    ("empty successor", dict(axiom="ABAB", rules=["A -> ", "B -> BA"]), 4),
    ("keyed after list", dict(axiom="A(0) A(5)", rules=["A(x) : x > 3 -> L(x)"],
                              keyed={"A(x)": "K(x)", "A(x):x<1": "Q(x)", "b<A(x)": "C(x)"}), 1),
    ("keyed context", dict(axiom="bA(0)cA(0)", rules=["A(x) -> L(x)"],
                           keyed={"b<A(x)": "C(x)", "A(x)>c": "D(x)"}), 1),
    ("keyed weights", dict(axiom="FFFFFFFF", seed=9, rules=[],
                           keyed={"F": [("1", "F[+F]F"), ("2", "F[-F]F"), ("0.5", "FF")]}), 3),
    ("short circuit", dict(axiom="A(0) A(4) A(1)", rules=[
        "A(x) : x != 0 && 1 / x > 0.5 -> B(x)", "A(x) : x == 0 || 1 / x < 0.5 -> C(x)"]), 1),
    ("axiom expressions", dict(axiom="A(1 + 2 * 3, -(4 - 6) / 4, pi) B(2 * pi)", rules=["B(x) -> B(x / pi)"]), 2),
    ("default seed", dict(axiom="FFFFFFFF", rules=["F -> F[+F]F : 1", "F -> F[-F]F : 1", "F -> FF : 1"]), 3),
    # turtle symbols without a rule may be written with or without parameters
    ("turtle symbol arity", dict(axiom="F+(30)F-F-(10)+(5)", rules=["+(a) -> -(a * 2) +(a + 1)"]), 2),
    ("power and precedence", dict(axiom="A(2)", rules=[
        "A(x) -> B(-x^2, 2^3^2, x - 1 - 1, x / 2 / 2, 1 + 2 * 3, (1 + 2) * 3, !0, !(x > 1), 3 > 2 == 1)"]),
     1),
]


# ---------------------------------------------------------------------------------------------------
# Driver
# ---------------------------------------------------------------------------------------------------


def lua_str(s):
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'


def describe(spec):
    parts = ["axiom=%r" % spec["axiom"], "rules=%r" % spec["rules"]]
    if spec.get("keyed"):
        parts.append("keyed=%r" % spec["keyed"])
    if spec.get("seed") is not None:
        parts.append("seed=%d" % spec["seed"])
    if spec.get("ignore") is not None:
        parts.append("ignore=%r" % spec["ignore"])
    return "lsystem{ " + ", ".join(parts) + " }"


def rule_texts(spec):
    """The rules in the order written: the list, then a table's keyed rules by sorted key."""
    texts = list(spec["rules"])
    for key, value in sorted(spec.get("keyed", {}).items(), key=lambda kv: kv[0].encode()):
        if isinstance(value, str):
            texts.append("%s -> %s" % (key, value))
        else:
            if len(value) == 1:
                texts.append("%s -> %s" % (key, value[0][1]))   # one choice: weight irrelevant
            else:
                texts.extend("%s -> %s : %s" % (key, succ, w) for w, succ in value)
    return texts


def derive_levels(spec, max_level, cap=True):
    g = Grammar(spec["axiom"], rule_texts(spec), spec.get("seed", 0) or 0, spec.get("ignore"))
    s = g.level0()
    texts = [text_of(s)]
    for _ in range(max_level):
        s = g.step(s)
        if cap and (len(s) > MAX_MODULES):
            break
        t = text_of(s)
        if cap and len(t) > MAX_CHARS:
            break
        texts.append(t)
    return texts


def build_cases():
    rng = random.Random(FIXED_SEED)
    cases = []   # (name, spec, expected texts)
    for name, spec, levels in FIXED:
        cases.append((name, spec, derive_levels(spec, levels, cap=False)))
    generators = [
        ("plain", 80, lambda: gen_plain(rng), 8),
        ("plain-cut", 30, lambda: gen_plain(rng, cut=True), 8),
        ("stochastic", 80, lambda: gen_stochastic(rng), 8),
        ("stochastic-cut", 20, lambda: gen_stochastic(rng, cut=True), 8),
        ("context", 120, lambda: gen_context(rng), 10),
        ("context-stochastic", 60, lambda: gen_context(rng, stochastic=True), 10),
        ("context-cut", 30, lambda: gen_context(rng, cut=True), 10),
        ("parametric", 80, lambda: gen_parametric(rng), 7),
        ("parametric-context", 60, lambda: gen_parametric(rng, context=True), 7),
        ("parametric-stochastic", 40, lambda: gen_parametric(rng, stochastic=True), 7),
        ("parametric-all", 30, lambda: gen_parametric(rng, context=True, stochastic=True, cut=True), 7),
    ]
    for kind, count, gen, levels in generators:
        for k in range(count):
            spec = gen()
            try:
                texts = derive_levels(spec, levels)
            except (ExprError, OverflowError, ValueError) as e:
                print("skipping %s-%d (%s): %s" % (kind, k, e, describe(spec)))
                continue
            cases.append(("%s-%d" % (kind, k), spec, texts))
    return cases


def write_recipe(cases, path):
    lines = []
    for idx, (name, spec, texts) in enumerate(cases):
        entries = [lua_str(r) for r in spec["rules"]]
        for key, value in spec.get("keyed", {}).items():
            if isinstance(value, str):
                entries.append("[%s] = %s" % (lua_str(key), lua_str(value)))
            else:
                entries.append("[%s] = { %s }" % (lua_str(key), ", ".join(
                    "{ %s, %s }" % (w, lua_str(succ)) for w, succ in value)))
        opts = ["axiom = " + lua_str(spec["axiom"]), "rules = { " + ", ".join(entries) + " }"]
        if spec.get("seed") is not None:
            opts.append("seed = %d" % spec["seed"])
        if spec.get("ignore") is not None:
            opts.append("ignore = " + lua_str(spec["ignore"]))
        lines.append("do local ok, err = pcall(function()")
        lines.append("  local g = lsystem { " + ", ".join(opts) + " }")
        lines.append("  for n = 0, %d do print(\"@@%d \" .. n .. \" \" .. g:string(n)) end" % (len(texts) - 1, idx))
        lines.append("end) if not ok then print(((\"@@ERR %d \" .. tostring(err)):gsub(\"\\n\", \" \"))) end end"
                     % idx)
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def first_diff(a, b):
    n = min(len(a), len(b))
    for i in range(n):
        if a[i] != b[i]:
            return i
    return n


def run_selfsim(selfsim, cases):
    """Runs every case through one recipe; returns ({(case, level): text}, {case: error}, process)."""
    with tempfile.TemporaryDirectory() as tmp:
        recipe = os.path.join(tmp, "reference_check.lua")
        write_recipe(cases, recipe)
        proc = subprocess.run([selfsim, "run", recipe, "-o", os.path.join(tmp, "out"), "-q"],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=600)
    got = {}
    errors = {}
    for line in proc.stdout.decode("utf-8", "replace").split("\n"):
        if line.startswith("@@ERR "):
            _, idx, msg = line.split(" ", 2)
            errors[int(idx)] = msg
        elif line.startswith("@@"):
            head, level, text = (line[2:].split(" ", 2) + [""])[:3]
            got[(int(head), int(level))] = text
    return got, errors, proc


def compare(cases, got, errors, verbose=False, quiet=False):
    """Prints the mismatches (unless quiet); returns (pairs checked, mismatches)."""
    failures = 0
    pairs = 0
    for idx, (name, spec, texts) in enumerate(cases):
        for level, want in enumerate(texts):
            pairs += 1
            have = got.get((idx, level))
            if have == want:
                continue
            failures += 1
            if quiet or failures > 40:
                continue
            print("MISMATCH %s level %d: %s" % (name, level, describe(spec)))
            if have is None:
                print("  selfsim printed nothing: %s" % errors.get(idx, "(no output)"))
                continue
            p = first_diff(want, have)
            print("  first difference at character %d (of %d expected, %d got)" % (p, len(want), len(have)))
            lo = max(0, p - 40)
            print("  expected ...%s" % want[lo:p + 60])
            print("  got      ...%s" % have[lo:p + 60])
            if verbose:
                print("  expected full: %s" % want[:2000])
                print("  got full:      %s" % have[:2000])
    return pairs, failures


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    selfsim = sys.argv[1]
    verbose = "--verbose" in sys.argv[2:]
    t0 = time.time()
    cases = build_cases()
    t1 = time.time()
    got, errors, proc = run_selfsim(selfsim, cases)
    t2 = time.time()
    pairs, failures = compare(cases, got, errors, verbose)
    if proc.returncode != 0:
        print("selfsim exited %d: %s" % (proc.returncode, proc.stderr.decode("utf-8", "replace")[-2000:]))
        failures += 1
    print("%d grammars, %d grammar/level pairs checked, %d mismatches (reference %.1f s, selfsim %.1f s)"
          % (len(cases), pairs, failures, t1 - t0, t2 - t1))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""The lua-language-server definitions (scripts/lua-language-server/) against what the interpreter registers.

usage: check_meta.py SELFSIM SOURCE_DIR

Runs tests/meta/dsl_names.lua with the built selfsim, which prints every global, every field of the DSL's
global tables and modules, and every method of every value type; reads the same names from the definition
files; and fails (exit 1), listing them, when a name is registered but not declared (editors would not
complete it) or declared but not registered (editors would offer what fails). Also fails when the
interpreter's sources name a value type that dsl_names.lua does not build, so a new type cannot go
unchecked.
"""

import os
import re
import subprocess
import sys
import tempfile

# Lua 5.4's own globals (reference manual, section 6), which LuaLS knows already. `load` is not among them:
# the sandbox removes Lua's load, and the `load` recipes see is selfsim's (bind_load.cpp), declared in the
# definitions like any other DSL function.
STANDARD_GLOBALS = {
    "_G", "_VERSION", "assert", "collectgarbage", "dofile", "error", "getmetatable", "ipairs", "loadfile",
    "next", "pairs", "pcall", "print", "rawequal", "rawget", "rawlen", "rawset", "require", "select",
    "setmetatable", "tonumber", "tostring", "type", "warn", "xpcall",
    "coroutine", "debug", "io", "math", "os", "package", "string", "table", "utf8",
}

# The sandbox's rule for module names (sandbox.cpp, valid_module_name): files elsewhere under scripts/
# (this folder of definitions, whose name has hyphens) cannot be required.
MODULE_NAME = re.compile(r"^[A-Za-z0-9_]+(\.[A-Za-z0-9_]+)*$")

# The definition files' declaration forms (selfsim.lua's header lists them), one per line.
META = re.compile(r"^---@meta(?:\s+(\S+))?\s*$")
CLASS = re.compile(r"^---@class\s+([\w.]+)\s*(?::\s*(.+?))?\s*$")
LOCAL_TABLE = re.compile(r"^local\s+(\w+)\s*=\s*\{\}\s*$")
GLOBAL_TABLE = re.compile(r"^(\w+)\s*=\s*\{\}\s*$")
GLOBAL_FUNCTION = re.compile(r"^function\s+(\w+)\s*\([^)]*\)\s*end\s*$")
TABLE_FUNCTION = re.compile(r"^function\s+(\w+)\.(\w+)\s*\([^)]*\)\s*end\s*$")
METHOD = re.compile(r"^function\s+(\w+):(\w+)\s*\([^)]*\)\s*end\s*$")
TABLE_FIELD = re.compile(r"^(\w+)\.(\w+)\s*=\s*\S")
RETURN = re.compile(r"^return\s+(\w+)\s*$")

# A value type the interpreter registers: the metatable name given to register_type, "selfsim.Curve" in
# value_types.h's ValueType<...>::name or a binding's `constexpr const char* volume_type = "selfsim.Volume"`.
TYPE_NAME = re.compile(r'\b(?:\w+_type|name)\s*=\s*"selfsim\.([A-Z]\w*)"')


class Declarations:
    def __init__(self):
        self.globals = set()  # global functions and tables
        self.fields = set()  # "table.field" of global tables
        self.modules = {}  # module name -> set of exported names
        self.classes = {}  # class name -> list of parent classes
        self.methods = {}  # class name -> set of method names declared on it
        self.tables = set()  # classes given a table of their own (value types, shared bases), not modules
        self.problems = []


def read_definitions(folder):
    """Every declaration in the .lua files under folder, by the forms above; any other code line is a
    problem (a declaration in a form this reader skips would go unchecked)."""
    d = Declarations()
    files = sorted(os.path.join(root, f) for root, _, names in os.walk(folder) for f in names if f.endswith(".lua"))
    if not files:
        d.problems.append(f"no definition files in {folder}")
    for path in files:
        read_file(path, os.path.relpath(path, folder), d)
    return d


def read_file(path, shown, d):
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    module = None
    meta_seen = False
    locals_ = {}  # local table variable -> class it was declared for
    global_tables = set()
    pending = None  # a ---@class whose table may follow
    returned = None
    exports = set()
    for number, raw in enumerate(lines, 1):
        line = raw.rstrip()
        where = f"{shown}:{number}"
        if m := META.match(line):
            meta_seen = True
            module = m.group(1) if m.group(1) not in (None, "_") else None
            continue
        if m := CLASS.match(line):
            parents = [p.strip() for p in m.group(2).split(",")] if m.group(2) else []
            parents = [p for p in parents if re.fullmatch(r"[\w.]+", p)]  # not a table literal type
            d.classes[m.group(1)] = parents
            pending = m.group(1)
            continue
        if line.startswith("--"):  # annotations and comments; a ---@class stays pending through its ---@field lines
            if not line.startswith("---"):
                pending = None
            continue
        if not line.strip():
            pending = None
            continue
        if m := LOCAL_TABLE.match(line):
            if pending is None:
                d.problems.append(f"{where}: a local table without a ---@class just above it: {line}")
            else:
                locals_[m.group(1)] = pending
                d.methods.setdefault(pending, set())
        elif m := GLOBAL_TABLE.match(line):
            global_tables.add(m.group(1))
            d.globals.add(m.group(1))
        elif m := GLOBAL_FUNCTION.match(line):
            d.globals.add(m.group(1))
        elif m := METHOD.match(line):
            owner, name = m.groups()
            if owner not in locals_:
                d.problems.append(f"{where}: method of '{owner}', which is no ---@class table: {line}")
            else:
                d.methods[locals_[owner]].add(name)
        elif (m := TABLE_FUNCTION.match(line)) or (m := TABLE_FIELD.match(line)):
            owner, name = m.groups()
            if owner in global_tables:
                d.fields.add(f"{owner}.{name}")
            elif owner in locals_:
                exports.add((owner, name))
            else:
                d.problems.append(f"{where}: field of '{owner}', which is no table declared before it: {line}")
        elif m := RETURN.match(line):
            returned = m.group(1)
        else:
            d.problems.append(f"{where}: not a declaration this check reads (see selfsim.lua's header): {line}")
        pending = None
    if not meta_seen:
        d.problems.append(f"{shown}: no ---@meta line: not a definition file")
    if module is not None:
        if returned is None:
            d.problems.append(f"{shown}: module {module} returns no table (end it with `return <table>`)")
        d.modules[module] = {name for owner, name in exports if owner == returned}
    elif exports:
        d.problems.append(f"{shown}: fields of local tables outside a module file: {sorted(exports)}")
    # A module's own table is no value type: every other class given a table is (or is a shared base).
    d.tables |= {cls for var, cls in locals_.items() if module is None or var != returned}


def methods_of(d, cls, seen=()):
    """The methods of a class with those it inherits from its parents."""
    found = set(d.methods.get(cls, ()))
    for parent in d.classes.get(cls, ()):
        if parent not in seen:
            found |= methods_of(d, parent, seen + (cls,))
    return found


def module_names(scripts):
    names = []
    for root, _, files in os.walk(scripts):
        for f in files:
            if f.endswith(".lua"):
                rel = os.path.relpath(os.path.join(root, f), scripts)[: -len(".lua")]
                name = rel.replace(os.sep, ".")
                if MODULE_NAME.match(name):
                    names.append(name)
    return sorted(names)


def registered_types(frontend):
    types = set()
    for root, _, names in sorted(os.walk(frontend)):
        for f in sorted(names):
            if f.endswith((".cpp", ".h")):
                with open(os.path.join(root, f), encoding="utf-8") as src:
                    types |= set(TYPE_NAME.findall(src.read()))
    return types


def run_recipe(selfsim, src, modules):
    recipe = os.path.join(src, "tests", "meta", "dsl_names.lua")
    # The modules are the ones under src/scripts: the binary is told to load them from there too.
    env = dict(os.environ, SELFSIM_SCRIPTS=os.path.join(src, "scripts"))
    with tempfile.TemporaryDirectory() as out:
        r = subprocess.run([selfsim, "run", recipe, "-o", out, "-q", "--set", "modules=" + " ".join(modules)],
                           capture_output=True, text=True, timeout=120, env=env)
    if r.returncode != 0:
        sys.exit(f"FAIL: {recipe} exited {r.returncode}:\n{r.stderr}{r.stdout}")
    return [line for line in r.stdout.splitlines() if line.strip()]


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    selfsim, src = sys.argv[1], sys.argv[2]
    scripts = os.path.join(src, "scripts")
    modules = module_names(scripts)
    d = read_definitions(os.path.join(scripts, "lua-language-server"))
    problems = list(d.problems)

    # What the interpreter registers, as dsl_names.lua prints it.
    globals_, fields, got_modules, types = set(), set(), {}, {}
    for line in run_recipe(selfsim, src, modules):
        kind, _, rest = line.partition(" ")
        if kind == "global":
            if rest not in STANDARD_GLOBALS:
                globals_.add(rest)
        elif kind == "field":
            fields.add(rest)
        elif kind == "module":
            got_modules[rest] = set()
        elif kind == "export":
            module, _, name = rest.partition(" ")
            got_modules[module].add(name)
        elif kind == "type":
            types[rest] = set()
        elif kind == "method":
            type_name, _, name = rest.partition(" ")
            types[type_name].add(name)
        else:
            problems.append(f"dsl_names.lua printed a line this check does not read: {line}")

    def compare(what, registered, declared, join=" "):
        for name in sorted(registered - declared):
            problems.append(f"{what}{join}{name}: registered by the interpreter, missing from the definitions")
        for name in sorted(declared - registered):
            problems.append(f"{what}{join}{name}: declared in the definitions, not registered by the interpreter")

    compare("global", globals_, d.globals)
    compare("field", fields, d.fields)
    compare("module", set(got_modules), set(d.modules))
    for module in sorted(set(got_modules) & set(d.modules)):
        compare(f"module field {module}", got_modules[module], d.modules[module], ".")

    # Value types: a class named selfsim.<Type> with its own table; classes only inherited from (the methods
    # every geometry value shares) are not types of their own.
    parents = {p for ps in d.classes.values() for p in ps}
    declared_types = {c.removeprefix("selfsim."): c for c in d.tables if c not in parents}
    compare("value type", set(types), set(declared_types))
    for t in sorted(set(types) & set(declared_types)):
        compare(f"method {t}", types[t], methods_of(d, declared_types[t]), ":")
    for t in sorted(registered_types(os.path.join(src, "frontend")) - set(types)):
        problems.append(f"value type {t}: registered in frontend/, but tests/meta/dsl_names.lua builds no "
                        "value of it (add one there, and its class to the definitions)")

    if problems:
        print("FAIL: scripts/lua-language-server/ and the interpreter disagree:")
        for p in problems:
            print("  " + p)
        return 1
    print(f"ok: {len(globals_)} globals, {len(fields)} table fields, {len(got_modules)} modules, "
          f"{len(types)} value types with {sum(len(m) for m in types.values())} methods, all declared")
    return 0


if __name__ == "__main__":
    sys.exit(main())

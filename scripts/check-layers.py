#!/usr/bin/env python3
"""The layering check of src/ (src/README.md, "Layering"): every include and
every call between files must follow the rules written in the folders'
README.md files, and no two files may call each other, directly or through
others.

    scripts/check-layers.py BUILD_DIR

Rules: a folder that holds sources (src/<stage>/ or src/<stage>/<room>/)
has a README.md with one paragraph

    May use: `base/`, `model/`, `engine/assembly/`

naming the folders its files may include and call into, besides their own
folder and the public headers of include/ ("May use: nothing" for none). A
named folder covers the rooms below it (`engine/` = every room of engine/).

Any file may call the functions of the public headers (include/ricochet/),
the command line nothing else. A function is declared in a header of the
folder that defines it. Includes are read from the sources; calls
from the objects that BUILD_DIR
holds (build/obj/<stage>[/<room>]/<file>.o, read with `nm`): a call is an
undefined symbol of one object that another defines. Prints one line per
breach and a closing PASS or FAIL line; exits 1 on any breach.
"""
import os
import re
import subprocess
import sys

SRC = "src"
INCLUDE_RE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
RULE_RE = re.compile(r"^May use:(.*?)(?:\n\s*\n|\Z)", re.M | re.S)


def folders():
    """{folder: [allowed folder prefixes]} for every folder with sources."""
    rules = {}
    for root, _dirs, files in os.walk(SRC):
        if not any(f.endswith((".c", ".h", ".inc")) for f in files):
            continue
        rel = os.path.relpath(root, SRC) + "/"
        readme = os.path.join(root, "README.md")
        if not os.path.exists(readme):
            sys.exit(f"FAIL layers: {root}/ holds sources but no README.md with its 'May use:' line")
        m = RULE_RE.search(open(readme, encoding="utf-8").read())
        if not m:
            sys.exit(f"FAIL layers: {readme} has no 'May use:' line")
        rules[rel] = re.findall(r"`([a-z_]+/(?:[a-z_]+/)?)`", m.group(1))
    return rules


def folder_of(path, rules):
    """The rules' folder of a path relative to src/ (the longest that holds it)."""
    best = None
    for f in rules:
        if path.startswith(f) and (best is None or len(f) > len(best)):
            best = f
    return best


def allowed(src_folder, dst_folder, rules):
    if dst_folder == src_folder:
        return True
    return any(dst_folder.startswith(p) for p in rules[src_folder])


def check_includes(rules):
    bad = []
    for root, _dirs, files in os.walk(SRC):
        for name in sorted(files):
            if not name.endswith((".c", ".h", ".inc")):
                continue
            path = os.path.join(root, name)
            rel = os.path.relpath(path, SRC)
            own = folder_of(rel, rules)
            text = open(path, encoding="utf-8").read()
            for m in INCLUDE_RE.finditer(text):
                inc = m.group(1)
                if inc.startswith("ricochet/"):
                    continue  # the public headers (include/)
                if "/" not in inc:
                    target = own  # a file of its own folder
                    if not os.path.exists(os.path.join(root, inc)):
                        bad.append(f"{path}: includes \"{inc}\", not in its folder")
                        continue
                else:
                    target = folder_of(inc, rules)
                if target is None:
                    bad.append(f"{path}: includes \"{inc}\", outside src/")
                elif not allowed(own, target, rules):
                    line = text.count("\n", 0, m.start()) + 1
                    bad.append(f"{path}:{line}: includes \"{inc}\" ({target}), not among what {own} may use")
    return bad


def symbols(build):
    """{object: (defined set, undefined set)} of the library's objects."""
    out = {}
    base = os.path.join(build, "obj")
    for root, _dirs, files in os.walk(base):
        for name in files:
            if not name.endswith(".o"):
                continue
            path = os.path.join(root, name)
            rel = os.path.relpath(path, base)[:-2]
            if not os.path.exists(os.path.join(SRC, rel + ".c")):
                continue  # a stale object of a file moved or removed since
            nm = subprocess.run(["nm", "-g", path], capture_output=True, text=True, check=True).stdout
            d, u = set(), set()
            for line in nm.splitlines():
                p = line.split()
                if len(p) == 3 and p[1] in "TDBRCV":
                    d.add(p[2])
                elif len(p) == 2 and p[0] == "U":
                    u.add(p[1])
            out[rel] = (d, u)
    return out


def cycles(graph):
    """Strongly connected components of more than one file (Tarjan)."""
    index, low, stack, on, comps = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                comps.append(sorted(comp))

    sys.setrecursionlimit(10000)
    for v in sorted(graph):
        if v not in index:
            visit(v)
    return comps


def public_api():
    """The functions declared in the public headers (include/ricochet/):
    any file may call them, the command line only them."""
    names = set()
    for root, _dirs, files in os.walk("include"):
        for name in files:
            if name.endswith(".h"):
                text = re.sub(r"/\*.*?\*/", "", open(os.path.join(root, name), encoding="utf-8").read(), flags=re.S)
                names |= set(re.findall(r"\b(rc_\w+)\s*\(", text))
    return names


def check_calls(build, rules):
    api = public_api()
    syms = symbols(build)
    if not syms:
        return [f"no objects under {build}/obj: build the library first"], 0
    owner = {}
    for obj, (d, _u) in syms.items():
        for s in d:
            owner[s] = obj
    bad, graph, edges = [], {}, 0
    for obj, (_d, u) in sorted(syms.items()):
        own = folder_of(obj + ".c", rules)
        for s in sorted(u):
            callee = owner.get(s)
            if callee is None or callee == obj:
                continue
            graph.setdefault(obj, set()).add(callee)
            edges += 1
            target = folder_of(callee + ".c", rules)
            if s not in api and not allowed(own, target, rules):
                bad.append(f"src/{obj}.c calls {s} (src/{callee}.c, {target}), not among what {own} may use")
    for comp in cycles(graph):
        bad.append("call cycle between files: " + " <-> ".join(f"src/{c}.c" for c in comp))
    return bad, edges


def check_declarations(build, rules):
    """A library function is declared in a header of the folder that
    defines it (or in the public headers): the engine's API in the engine's
    rooms, never in model/."""
    owner = {}
    for obj, (d, _u) in symbols(build).items():
        for s in d:
            owner[s] = obj
    bad = []
    for root, _dirs, files in os.walk(SRC):
        for name in sorted(files):
            if not name.endswith(".h"):
                continue
            path = os.path.join(root, name)
            text = re.sub(r"/\*.*?\*/", "", open(path, encoding="utf-8").read(), flags=re.S)
            text = re.sub(r"static inline[^{;]*\{(?:[^{}]|\{[^{}]*\})*\}", "", text)
            here = folder_of(os.path.relpath(path, SRC), rules)
            for m in re.finditer(r"\b(rc_\w+)\s*\([^;{]*\)\s*;", text):
                obj = owner.get(m.group(1))
                if obj is not None and folder_of(obj + ".c", rules) != here:
                    bad.append(f"{path}: declares {m.group(1)}, defined in src/{obj}.c ({folder_of(obj + '.c', rules)})")
    return bad


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    os.chdir(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    rules = folders()
    bad = check_includes(rules)
    call_bad, edges = check_calls(sys.argv[1], rules)
    bad += call_bad + check_declarations(sys.argv[1], rules)
    for b in bad:
        print("  " + b)
    if bad:
        print(f"FAIL layers: {len(bad)} breaches of the rules in the folders' README.md files")
        return 1
    print(f"PASS layers: {len(rules)} folders, every include and the {edges} calls between files "
          "follow their rules; no call cycle; every function declared in its own folder")
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Table of the validation errors at the decks' solver settings ("tight"), at
ricochet's default settings (RICOCHET_VAL_SOLVER=default: /SOLVER removed)
and on the IDA path at the decks' settings (RICOCHET_VAL_METHOD=ida).

    scripts/val_table.py [--build DIR] [--all] [PROBLEM ...]   run the checks in the three modes
    scripts/val_table.py --log FILE                             read a scripts/check.sh log

Prints a markdown table: problem, check, error (or the detail when the check
prints no number) and PASS/FAIL in each mode. The error is the number the
check prints: its "rel. error X" (or "max rel. error X", "rel. difference X",
"|error| X", "error / (scale) X", "error X" in e-notation), else the first
e-notation number followed by its bound "(< tol)", else "= X (< tol)", else
the largest "(rel. X)"; a check script that stopped shows its last error line.
"""
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PYTHON = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable  # as scripts/check.sh
NUM = r"([-+]?[0-9]*\.?[0-9]+(?:e[-+]?\d+)?)"
SCI = r"([-+]?[0-9]*\.?[0-9]+e[-+]?\d+)"
PATTERNS = [re.compile(p) for p in (
    r"rel\. error " + NUM,
    r"rel\. difference " + NUM,
    r"\|error\| " + NUM,
    r"error / \([^)]*\) " + SCI,
    r"errors? " + SCI,
    SCI + r"(?: [^\s(]+)?\s*\((?:<|<=) ",
    r"= " + SCI + r"[^;]*?\((?:<|<=) ",
)]
REL = re.compile(r"\(rel\. " + SCI + r"\)")
LINE = re.compile(r"^(PASS|FAIL) (default:|ida:)?(\S+?): (.*)$")


def error_of(detail):
    if detail.startswith("check script exited"):
        return detail if len(detail) <= 150 else detail[:147] + "..."
    for p in PATTERNS:
        m = p.search(detail)
        if m:
            return m.group(1)
    rels = REL.findall(detail)
    if rels:  # "... (rel. X) ... (rel. Y)": the largest
        return max(rels, key=float)
    return detail if len(detail) <= 90 else detail[:87] + "..."


def parse(lines, results, problem=None, mode=None):
    """Collect PASS/FAIL lines into results[(problem, check)][mode]."""
    last_err = ""
    for ln in lines:
        if re.match(r"^(ricochet: |RuntimeError: |\w+Error: )", ln):
            last_err = ln.strip()
        h = re.match(r"^== (validation/\S+?)( \((defaults|ida)\))?$", ln)
        if h:
            problem = os.path.basename(h.group(1))
            mode = {"defaults": "default", "ida": "ida"}.get(h.group(3), "tight")
            continue
        m = LINE.match(ln.rstrip("\n"))
        if not m or problem is None:
            continue
        status, pre, name, detail = m.groups()
        if detail.startswith("check script exited") and last_err and ":" not in detail:
            detail += ": " + last_err
        md = {"default:": "default", "ida:": "ida"}.get(pre or "", mode or "tight")
        key = (problem, name.split("/")[-1])
        results.setdefault(key, {})[md] = (status, error_of(detail))


def run_checks(problems, build, full):
    results = {}
    for prob in problems:
        chk = os.path.join(ROOT, "validation", prob, "check.py")
        for md in ("tight", "default", "ida"):
            env = dict(os.environ, RICOCHET=os.path.join(ROOT, build, "ricochet"),
                       RICOCHET_VAL_SOLVER="default" if md == "default" else "deck",
                       RICOCHET_VAL_METHOD="ida" if md == "ida" else "")
            p = subprocess.run([PYTHON, chk, "--all" if full else "--fast"], capture_output=True,
                               text=True, env=env, cwd=ROOT)
            lines = p.stdout.splitlines()
            if p.returncode != 0 and not any(ln.startswith("FAIL ") for ln in lines):
                err = (p.stderr.strip().splitlines() or ["?"])[-1]
                lines.append(f"FAIL {md + ':' if md != 'tight' else ''}{prob}: check script exited with status "
                             f"{p.returncode}: {err}")
            parse(lines, results, prob, md)
            print(f"{prob} ({md}): {sum(ln.startswith('PASS ') for ln in lines)} passed, "
                  f"{sum(ln.startswith('FAIL ') for ln in lines)} failed", file=sys.stderr)
    return results


def cell(v):
    if v is None:
        return "-"
    status, err = v
    return f"{err.replace('|', chr(92) + '|')} ({status})"


def table(results):
    out = ["| problem | check | error, tight (deck /SOLVER) | error, defaults (no /SOLVER) | error, IDA (--method ida) |",
           "|---|---|---|---|---|"]
    for (prob, name), v in results.items():
        out.append(f"| {prob} | {name} | {cell(v.get('tight'))} | {cell(v.get('default'))} | {cell(v.get('ida'))} |")
    n = {md: sum(1 for v in results.values() if v.get(md, ("",))[0] == "FAIL") for md in ("tight", "default", "ida")}
    out.append("")
    out.append(f"{len(results)} checks; failing: {n['tight']} tight, {n['default']} at defaults, {n['ida']} on IDA")
    return "\n".join(out)


def main(argv):
    build, full, log, problems = "build", False, None, []
    it = iter(argv)
    for a in it:
        if a == "--build":
            build = next(it)
        elif a == "--all":
            full = True
        elif a == "--log":
            log = next(it)
        else:
            problems.append(os.path.basename(os.path.normpath(a)))
    if log:
        results = {}
        with open(log) as f:
            parse(f, results)
    else:
        if not problems:
            problems = sorted(d for d in os.listdir(os.path.join(ROOT, "validation"))
                              if os.path.isfile(os.path.join(ROOT, "validation", d, "check.py")))
            if not full:
                problems = [p for p in problems if not os.path.isfile(os.path.join(ROOT, "validation", p, "SLOW"))]
        results = run_checks(problems, build, full)
    print(table(results))


if __name__ == "__main__":
    main(sys.argv[1:])

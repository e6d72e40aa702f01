"""ricochet.fit (python/ricochet/fit.py): the program's `ricochet fit` from
Python, its JSON report as a dict; errors as the module's exceptions.
    python3 tests/python_fit_test.py BUILD_DIR
Prints PASS/FAIL lines (scripts/check.sh counts them)."""
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
build = sys.argv[1] if len(sys.argv) > 1 else "build"
os.environ.setdefault("RICOCHET_LIB", os.path.join(os.path.abspath(build), "libricochet.so"))
sys.path.insert(0, os.path.join(ROOT, "python"))
import ricochet  # noqa: E402

ex = os.path.join(ROOT, "examples", "calibration")


def check(name, ok, detail):
    print(f"{'PASS' if ok else 'FAIL'} pyfit.{name}: {detail}")


try:
    from ricochet.fit import program
    prog = program()
    rep = ricochet.fit(os.path.join(ex, "ball_drop.rad"), os.path.join(ex, "ball_drop_measured.csv"),
                       log={"/INTER/TYPE6/1:FscaleId": 1e5, "/INTER/TYPE6/1:Visc": 5},
                       free={"/INTER/TYPE6/1:Fric": (0.2, 0.0, 1.0)}, rtol=1e-9)
    by = {q["name"]: q for q in rep["parameters"]}
    k, c, mu = by["/INTER/TYPE6/1:FscaleId"], by["/INTER/TYPE6/1:Visc"], by["/INTER/TYPE6/1:Fric"]
    ok = (rep["converged"] and k["identifiable"] and c["identifiable"] and not mu["identifiable"]
          and mu["reason"] == "zero column" and mu["standard_error"] is None
          and k["lo95"] <= 23500 <= k["hi95"] and c["lo95"] <= 41 <= c["hi95"]
          and rep["fitted"].shape == (251, 3) and len(rep["set"]) == 2 and abs(rep["correlation"][1][2]) > 0.9)
    check("drop", ok, f"program {prog}: k = {k['value']:.6g} +- {k['standard_error']:.3g}, c = {c['value']:.6g} +- "
          f"{c['standard_error']:.3g}, Fric: {mu['reason']}; {rep['iterations']} iterations, fitted {rep['fitted'].shape}")
except Exception as e:  # noqa: BLE001
    check("drop", False, f"{type(e).__name__}: {e}")

try:
    ricochet.fit(os.path.join(ex, "ball_drop.rad"), os.path.join(ex, "ball_drop_measured.csv"),
                 free={"/INTER/TYPE6/1:Frc": 0.2})
    check("input_error", False, "no exception")
except ricochet.InputError as e:
    check("input_error", "no numeric field Frc" in str(e) and e.exit_code == 2, f"InputError: {str(e)[:100]}")
except Exception as e:  # noqa: BLE001
    check("input_error", False, f"{type(e).__name__}: {e}")

try:
    ricochet.fit(os.path.join(ex, "ball_drop.rad"), os.path.join(ex, "ball_drop_measured.csv"),
                 log={"/INTER/TYPE6/1:Visc": 5}, max_iter=1)
    check("not_converged", False, "no exception")
except ricochet.RicochetError as e:
    check("not_converged", "NOT CONVERGED" in str(e) and hasattr(e, "report") and e.report["iterations"] == 1,
          f"{type(e).__name__}: {e}")

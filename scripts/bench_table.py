#!/usr/bin/env python3
"""docs/benchmarks.md's 'Error against time' table from bench/bench.csv (a fixed selection of rows)."""
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1] if len(sys.argv) > 1 else "bench/bench.csv")))
keep_mc = {"1024", "65536", "64"}
print("| table | method | samples / tol | time [s] | evals | bake err max | bake err rms | lookup lin max (off corner) | lookup cubic rms |")
print("|---|---|---|---|---|---|---|---|---|")
for r in rows:
    if r["section"] != "sweep":
        continue
    m, s = r["method"], r["samples_or_tol"]
    if m == "mc-hammersley" and s not in keep_mc:
        continue
    if m == "gauss-legendre" and s not in {"1024", "16384"}:
        continue
    setting = ("tol " + s) if m == "kiln" else ("declared " + s) if m == "kiln-fixed-rule" else s
    f = lambda k: "%.1e" % float(r[k])
    print(f"| {r['table']} {r['size']} | {m} | {setting} | {float(r['seconds']):.3g} | {float(r['evals']):.3g} | "
          f"{f('bake_err_max')} | {f('bake_err_rms')} | {f('lookup_linear_max')} ({f('lookup_linear_max_off_corner')}) | {f('lookup_cubic_rms')} |")

#!/usr/bin/env python3
"""Prints docs/catalogue.md's table (Markdown) from a kiln manifest.json."""
import json
import sys

path = sys.argv[1] if len(sys.argv) > 1 else "luts/manifest.json"
tables = json.load(open(path))["tables"]
print("| table | axes (size, warp) | channels | bytes (f32) | bake error | declared lookup max (linear) "
      "| rms (linear) | max (cubic) | rms (cubic) |")
print("|---|---|---|---|---|---|---|---|---|")
for t in tables:
    axes = " x ".join(f"{a['name']} {a['size']} {a['warp']}" for a in t["axes"])
    le = t["lookup_error"]
    cu = t.get("lookup_error_cubic", {})
    cmax = f"{cu['max']:.1e}" if cu else "-"
    crms = f"{cu['rms']:.1e}" if cu else "-"
    print(f"| {t['name']} | {axes} | {','.join(t['channels'])} | {t['bytes_float32']} | "
          f"{t['bake_error']:.0e} | {le['max']:.1e} | {le['rms']:.1e} | {cmax} | {crms} |")

#!/usr/bin/env python3
"""The tables of docs/results/rtw-ablation.md from scripts/rtw-ablation.sh's CSVs.

Usage: rtw-ablation-table.py OUTDIR SCENE... [--out FILE]   (reads OUTDIR/ablation-SCENE.csv)
The tables go to standard output, or with --out to FILE (scripts/lib/output_policy.py: a FILE
that is one of the CSVs, a folder or a FIFO is refused before any is read, exit 2; FILE is
replaced only when every table was made).
Per scene, one row per configuration: the error at 512, 1024, 2048 (a check mark where it is
no worse than rtw-backward at the same resolution within 1.05 x + 0.005 points), and at 1024
the light frustum's area, the collapsed importance's half-mass widths and the rotation.
"""
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from output_policy import check_outputs, print_or_write, take_option  # noqa: E402

RES = ("512", "1024", "2048")


def label(technique, params):
    rest = [p for p in params.split(";") if p and not p.startswith("resolution=")]
    gateoff = {"rotation.mode=pca", "pca.metric=metres", "pca.min_anisotropy=0",
               "pca.min_spread=0"}
    gated = {"rotation.mode=pca", "pca.min_anisotropy=0.9", "pca.min_spread=0.05"}
    s = set(rest)
    if technique == "rtw-backward":
        return "rtw-backward" + (" " + " ".join(rest) if rest else "")
    if not rest:
        return "**da-rtw (defaults: predicted)**"
    if s == gated:
        return "da-rtw, gated (pca, 0.9 / 0.05)"
    if {"pca.source=im", "light.fit=rotation-invariant", "importance.stride=1"} <= s:
        return "poster (`scenes/papers/000-da-rtw.json`)"
    if s == gateoff:
        return "da-rtw, gate off"
    return "gate off + " + ", ".join(f"`{p}`" for p in rest if p not in gateoff)


def main():
    args = sys.argv[1:]
    table = take_option(args, "--out")
    if not args:
        print("usage: rtw-ablation-table.py OUTDIR SCENE... [--out FILE]", file=sys.stderr)
        sys.exit(2)
    out, scenes = args[0], args[1:]
    if table is not None:
        csvs = [f"{out}/ablation-{s}.csv" for s in scenes]
        check_outputs([("--out", table)], [(f"the CSV '{c}'", c) for c in csvs])
    print_or_write(table, lambda: tables(out, scenes))


def tables(out, scenes):
    for scene in scenes:
        rows = list(csv.DictReader(open(f"{out}/ablation-{scene}.csv")))
        configs = {}
        path = rows[0]["camera"] if rows else ""
        for r in rows:
            params = r["params"].replace(" ", ";")
            res = next((p.split("=")[1] for p in params.split(";")
                        if p.startswith("resolution=")), "")
            key = (r["technique"], ";".join(p for p in params.split(";")
                                            if not p.startswith("resolution=")))
            configs.setdefault(key, {})[res] = r
        base = configs.get(("rtw-backward", ""), {})
        print(f"**`{scene}`** ({path}):\n")
        print("| configuration | 512² | 1024² | 2048² | frustum area m² | half-mass x / y | R |")
        print("|---|---|---|---|---|---|---|")
        for (tech, params), by in configs.items():
            cells = []
            for res in RES:
                r = by.get(res)
                if not r or not r["error_pct"]:
                    cells.append("failed" if r else "")
                    continue
                e = float(r["error_pct"])
                mark = ""
                if tech != "rtw-backward" and res in base and base[res]["error_pct"]:
                    b = float(base[res]["error_pct"])
                    mark = " ✓" if e <= 1.05 * b + 0.005 else " ✗"
                cells.append(f"{e:.3f}{mark}")
            r = by.get("1024", {})
            area = f"{float(r['light_area_m2']):.0f}" if r.get("light_area_m2") else ""
            hm = (f"{float(r['halfmass_x']):.3f} / {float(r['halfmass_y']):.3f}"
                  if r.get("halfmass_x") else "")
            rot = f"{float(r['rotation_deg']):.1f}°" if r.get("rotation_deg") else ""
            print(f"| {label(tech, params)} | " + " | ".join(cells) + f" | {area} | {hm} | {rot} |")
        print(f"\n![ablation on {scene}](../images/rtw/ablation-{scene}.png)\n")


if __name__ == "__main__":
    main()

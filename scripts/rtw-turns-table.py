#!/usr/bin/env python3
"""The tables and the chart of docs/results/rtw-rotation.md from scripts/rtw-turns.sh's output.

Usage: rtw-turns-table.py OUTDIR [--svg FILE.svg] [--regrid DIR] [--out FILE]
The tables go to standard output, or with --out to FILE. --out and --svg follow the output
policy (scripts/lib/output_policy.py): one that is a file read here (a CSV or JSON of OUTDIR or
DIR), the other output, a folder or a FIFO is refused before anything is read (exit 2); each
is replaced only when complete.
Reads OUTDIR/turns-SCENE@VIEW-RES.csv (bench: rtw-backward, fixed turns, da-rtw at its
defaults and with rotation.mode=pca) and OUTDIR/prediction-SCENE@VIEW-RES-{edges,pixels}.json
(the unturned frame's predicted score of every turn). Prints, per view:
  - the true error against the turn, its best turn and the gain available over the unturned
    frame (1 - best / unturned);
  - DA-RTW at its defaults (its angle, its error, its error / the unturned frame's) and the two
    criteria: never worse (<= 1.05 x unturned + 0.005 points) and, where the best turn beats
    the unturned frame by >= 20 %, at least 60 % of that gain captured;
  - PCA's turn (the poster's rule) the same way;
  - for still views, the prediction against the truth: the predicted best turn, and the
    predicted ratio score(turn) / score(unturned) beside the measured error ratio at every
    measured turn.
With --svg, a chart: measured against predicted ratio, one dot per still view and turn.
With --regrid (scripts/rtw-regrid-noise.sh's folder): per still view the spread s of log(error)
over turns of 0..4° (the same texels, only the grid moved), and the gain the best of six turns
shows by chance alone at 95 %: 1 - exp(-3.2 s) (the least of six draws minus one draw of the
unturned frame: mean -1.27 s, standard deviation 1.19 s); an available gain below it is marked
"chance".
"""
import csv
import glob
import json
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from output_policy import (check_outputs, print_or_write, take_option,  # noqa: E402
                           write_atomically)


def fold(a):
    """An angle folded into (-45, 45] (the warp's quarter-turn symmetry)."""
    a = math.fmod(a, 90.0)
    if a > 45.0:
        a -= 90.0
    if a <= -45.0:
        a += 90.0
    return a


def num(s):
    try:
        return float(s)
    except (TypeError, ValueError):
        return float("nan")


def load_view(path):
    rows = list(csv.DictReader(open(path)))
    view = {"fixed": {}, "default": None, "pca": None, "unturned": None, "camera": ""}
    for r in rows:
        view["camera"] = r["camera"]
        params = dict(p.split("=", 1) for p in r["params"].split() if "=" in p)
        err, deg = num(r["error_pct"]), num(r.get("rotation_deg"))
        if r["technique"] == "rtw-backward":
            view["unturned_backward"] = err
        elif params.get("rotation.mode") == "fixed":
            view["fixed"][float(params["rotation.fixed_deg"])] = err
        elif params.get("rotation.mode") == "pca":
            view["pca"] = (err, deg)
        else:
            view["default"] = (err, deg)
    view["unturned"] = view["fixed"].get(0.0, view.get("unturned_backward"))
    return view


def criteria(err, unturned, best):
    never_worse = err <= 1.05 * unturned + 0.005
    gain = 1.0 - best / unturned if unturned > 0 else 0.0
    captured = (unturned - err) / (unturned - best) if unturned - best > 0 else float("nan")
    ok = never_worse and (gain < 0.2 or captured >= 0.6)
    return never_worse, gain, captured, ok


def regrid_spread(folder, scene, view, res):
    """log-sd of the error over the turns 0..4° of one still view, or None."""
    path = os.path.join(folder, f"regrid-{scene}@{view}-{res}.csv") if folder else ""
    if not folder or not os.path.exists(path):
        return None
    e = [num(r["error_pct"]) for r in csv.DictReader(open(path))]
    logs = [math.log(x) for x in e if x > 0]
    if len(logs) < 3:
        return None
    m = sum(logs) / len(logs)
    return math.sqrt(sum((x - m) ** 2 for x in logs) / (len(logs) - 1))


def main():
    args = sys.argv[1:]
    svg = take_option(args, "--svg")
    regrid = take_option(args, "--regrid")
    table = take_option(args, "--out")
    if not args:
        print("usage: rtw-turns-table.py OUTDIR [--svg FILE.svg] [--regrid DIR] [--out FILE]",
              file=sys.stderr)
        sys.exit(2)
    out = args[0]
    inputs = [os.path.join(out, "turns-*.csv"), os.path.join(out, "prediction-*.json")]
    if regrid:
        inputs.append(os.path.join(regrid, "regrid-*.csv"))
    check_outputs([(name, path) for name, path in (("--out", table), ("--svg", svg)) if path],
                  [(f"the input '{p}'", p) for pattern in inputs for p in glob.glob(pattern)])
    print_or_write(table, lambda: tables(out, svg, regrid))


def tables(out, svg, regrid):
    views = []
    for path in sorted(glob.glob(os.path.join(out, "turns-*.csv"))):
        m = re.match(r"turns-(.+)@(.+)-(\d+)\.csv$", os.path.basename(path))
        if not m:
            continue
        scene, view, res = m.groups()
        v = load_view(path)
        v.update(scene=scene, view=view, res=res)
        for w in ("edges", "pixels"):
            p = os.path.join(out, f"prediction-{scene}@{view}-{res}-{w}.json")
            if os.path.exists(p):
                curve = json.load(open(p)).get("published_curves", {}).get("prediction.curve")
                v[w] = curve
        views.append(v)

    print("| scene | view | res | unturned % | best turn | best % | gain available (by chance) | "
          "default: turn, % (× unturned) | criteria | pca: turn, % (× unturned) | pca criteria |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    fails = 0
    for v in views:
        if not v["fixed"] or v["default"] is None or not v["unturned"]:
            print(f"| `{v['scene']}` | {v['view']} | {v['res']} | failed | | | | | | | |")
            continue
        unturned = v["unturned"]
        best_deg = min(v["fixed"], key=lambda a: (v["fixed"][a], abs(a)))
        best = v["fixed"][best_deg]
        d_err, d_deg = v["default"]
        nw, gain, cap, ok = criteria(d_err, unturned, best)
        fails += 0 if ok else 1
        p_err, p_deg = v["pca"] if v["pca"] else (float("nan"), float("nan"))
        pnw, _, pcap, pok = criteria(p_err, unturned, best)
        cap_s = f", {100 * cap:.0f} % of it" if gain >= 0.2 else ""
        pcap_s = f", {100 * pcap:.0f} % of it" if gain >= 0.2 else ""
        view = "path" if v["view"] == "path" else f"camera {v['view']}"
        spread = regrid_spread(regrid, v["scene"], v["view"], v["res"])
        chance = 1.0 - math.exp(-3.2 * spread) if spread is not None else None
        gain_s = f"{100 * gain:.0f} %"
        if chance is not None:
            gain_s += f" ({100 * chance:.0f} %{', chance' if gain < chance else ''})"
        print(f"| `{v['scene']}` | {view} | {v['res']} | {unturned:.3f} | {best_deg:g}° | {best:.3f} | "
              f"{gain_s} | {fold(d_deg) if d_deg == d_deg else 0:.1f}°, {d_err:.3f} "
              f"(× {d_err / unturned:.2f}) | {'✓' if ok else '✗'}{cap_s} | "
              f"{fold(p_deg) if p_deg == p_deg else 0:.1f}°, {p_err:.3f} (× {p_err / unturned:.2f})"
              f" | {'✓' if pok else '✗'}{pcap_s} |")
    print(f"\n{len(views)} views, {fails} where DA-RTW at its defaults misses a criterion.\n")
    # Every policy over every view: the geometric mean of its error over the unturned frame's,
    # how often it is worse (beyond 1.05 x + 0.005 points), its worst ratio.
    print("| policy | geometric mean of error ÷ unturned | views worse | worst |")
    print("|---|---|---|---|")
    for name, get in (("da-rtw at its defaults (predicted)", lambda v: v["default"]),
                      ("da-rtw, rotation.mode=pca (the poster's rule)", lambda v: v["pca"]),
                      ("the best fixed turn of each view (hindsight)",
                       lambda v: (min(v["fixed"].values()), 0.0) if v["fixed"] else None)):
        logs, worse, worst = [], 0, 0.0
        for v in views:
            got = get(v)
            if not got or not v["unturned"] or not got[0] == got[0]:
                continue
            r = got[0] / v["unturned"]
            logs.append(math.log(r))
            worse += got[0] > 1.05 * v["unturned"] + 0.005
            worst = max(worst, r)
        if logs:
            print(f"| {name} | {math.exp(sum(logs) / len(logs)):.3f} | {worse} of {len(logs)} | "
                  f"{worst:.2f} |")
    print()

    # Prediction against truth (still views).
    print("| scene | view | measured error ÷ unturned at −45 / −30 / −15 / 15 / 30 / 45° | "
          "predicted (edges) | predicted (pixels) | best: measured / edges / pixels |")
    print("|---|---|---|---|---|---|")
    points = {"edges": [], "pixels": []}
    for v in views:
        if v["view"] == "path" or not v["fixed"] or not v["unturned"]:
            continue
        angles = [a for a in sorted(v["fixed"]) if -45 <= a <= 45 and a != 0]
        meas = [v["fixed"][a] / v["unturned"] for a in angles]
        cells = [" / ".join(f"{x:.2f}" for x in meas)]
        bests = [f"{min(v['fixed'], key=lambda a: (v['fixed'][a], abs(a))):g}°"]
        for w in ("edges", "pixels"):
            c = v.get(w)
            if not c or not c[18] > 0:
                cells.append("n/a")
                bests.append("n/a")
                continue
            pred = [c[int(round((a + 90) / 5))] / c[18] for a in angles]
            cells.append(" / ".join(f"{x:.2f}" for x in pred))
            i = min(range(len(c)), key=lambda k: (c[k] if c[k] > 0 else 1e300, abs(k - 18)))
            bests.append(f"{fold(-90 + 5 * i):g}°")
            points[w] += [(p, m, f"{v['scene']}@{v['view']}") for p, m in zip(pred, meas)]
        print(f"| `{v['scene']}` | camera {v['view']} | {cells[0]} | {cells[1]} | {cells[2]} | "
              f"{' / '.join(bests)} |")
    for w, pts in points.items():
        if not pts:
            continue
        # Does the prediction order turns as the truth does? Sign agreement of log ratios
        # beyond 5 %, and the log-ratio error.
        agree = sum(1 for p, m, _ in pts
                    if abs(math.log(m)) < math.log(1.05) or (p < 1) == (m < 1))
        errs = sorted(abs(math.log(p) - math.log(m)) for p, m, _ in pts if p > 0 and m > 0)
        med = errs[len(errs) // 2] if errs else float("nan")
        sigma = 1.4826 * med  # a robust standard deviation of log(pred / measured)
        print(f"\n{w}: {len(pts)} turns; the prediction is on the truth's side of 1 (or the "
              f"truth within 5 %) for {agree}; median |log(pred / measured)| = {med:.3f} "
              f"(a factor {math.exp(med):.2f}), robust s = {sigma:.3f}: a predicted gain beyond "
              f"1 - exp(-1.645 s) = {1 - math.exp(-1.645 * sigma):.3f} is a gain with 95 % "
              f"confidence (one-sided)")
    if svg:
        write_svg(svg, points)


def write_svg(path, points):
    """Measured ratio (y) against predicted ratio (x), log-log, 0.05..2, one dot per turn."""
    w, h, pad = 520, 440, 60
    lo, hi = math.log(0.02), math.log(2.5)

    def px(r):
        return pad + (math.log(max(r, 0.02)) - lo) / (hi - lo) * (w - 2 * pad)

    def py(r):
        return h - pad - (math.log(max(r, 0.02)) - lo) / (hi - lo) * (h - 2 * pad)

    parts = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" '
             f'font-family="sans-serif" font-size="12">',
             f'<rect width="{w}" height="{h}" fill="white"/>']
    for t in (0.05, 0.1, 0.2, 0.5, 1, 2):
        parts.append(f'<line x1="{px(t):.1f}" y1="{pad}" x2="{px(t):.1f}" y2="{h - pad}" '
                     f'stroke="#ddd"/><text x="{px(t):.1f}" y="{h - pad + 16}" '
                     f'text-anchor="middle">{t:g}</text>')
        parts.append(f'<line x1="{pad}" y1="{py(t):.1f}" x2="{w - pad}" y2="{py(t):.1f}" '
                     f'stroke="#ddd"/><text x="{pad - 6}" y="{py(t) + 4:.1f}" '
                     f'text-anchor="end">{t:g}</text>')
    parts.append(f'<line x1="{px(0.02)}" y1="{py(0.02)}" x2="{px(2.5)}" y2="{py(2.5)}" '
                 f'stroke="#888" stroke-dasharray="4 3"/>')
    colours = {"edges": "#d4801c", "pixels": "#3a7fc1"}
    for wname, pts in points.items():
        for p, m, label in pts:
            parts.append(f'<circle cx="{px(p):.1f}" cy="{py(m):.1f}" r="3.2" '
                         f'fill="{colours[wname]}" fill-opacity="0.75"><title>{label} '
                         f'{wname}: predicted {p:.3f}, measured {m:.3f}</title></circle>')
    parts.append(f'<text x="{w / 2}" y="{h - 16}" text-anchor="middle">predicted score of '
                 f'the turn ÷ the unturned frame\'s</text>')
    parts.append(f'<text x="16" y="{h / 2}" text-anchor="middle" transform="rotate(-90 16 '
                 f'{h / 2})">measured error of the turn ÷ the unturned frame\'s</text>')
    y = 24
    for wname, c in colours.items():
        parts.append(f'<circle cx="{pad + 8}" cy="{y - 4}" r="4" fill="{c}"/><text x="'
                     f'{pad + 18}" y="{y}">prediction.weight = {wname}</text>')
        y += 16
    parts.append("</svg>")
    write_atomically(path, "\n".join(parts) + "\n")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Writes ds1.model's turn-angle table and ds1-day.problem (issue 11): one day of cruise in
twelve two-hour blocks, each with a Deep Space Network pass at its end, a thrust arc, four
optical-navigation images and a downlink in the pass; four optional science images; and
ds1-4h.problem, its first two blocks. Run from services/planner/examples: python3 ds1_day.py"""
import math
import re

targets = {"earth": (0, 0), "braille": (40, 10), "annefrank": (75, -5), "eros": (110, 20),
           "vesta": (150, 5), "ceres": (185, -15), "ida": (220, 30), "gaspra": (260, -20),
           "mathilde": (300, 15)}


def angle(a, b):
    (l1, b1), (l2, b2) = [tuple(math.radians(x) for x in targets[t]) for t in (a, b)]
    c = math.sin(b1) * math.sin(b2) + math.cos(b1) * math.cos(b2) * math.cos(l1 - l2)
    return max(1, round(math.degrees(math.acos(max(-1.0, min(1.0, c))))))


names = list(targets)
rows = [f"({a}, {b}, {angle(a, b)})" for a in names for b in names if a != b]
lines = ["          " + ", ".join(rows[i:i + 4]) for i in range(0, len(rows), 4)]
model = open("ds1.model").read()
table = ",\n".join(lines)
model = re.sub(r"\(from, to, angle\) in \{\n.*?\n        \}",
               "(from, to, angle) in {\n" + table + "\n        }", model, flags=re.S)
open("ds1.model", "w").write(model)

block, pass_length = 7200, 2400
imaging = [t for t in names if t != "earth"]


def write_problem(path, name, blocks, science):
    """blocks two-hour blocks; science: the optional images' blocks and targets."""
    hours = blocks * block // 3600
    out = [f"// {hours} hours of DS1-like cruise (written by ds1_day.py): {2 * blocks} DSN schedule entries,",
           f"// {blocks} thrust arcs, {blocks} downlinks, {4 * blocks} optical-navigation images"
           + (f" and {len(science)} optional science images." if science else "."),
           f"problem {name}", f"horizon {block * blocks}", "object dsone : Spacecraft",
           "initial dsone.attitude == pointAt(earth)", "initial dsone.camera == ready",
           "initial dsone.engine == off"]
    for k in range(blocks):
        t0, p = k * block, k + 1
        rise = t0 + block - pass_length
        out.append(f"goal hidden{p}: dsone.dsn == hidden() start [{t0}, {t0}] end [{rise}, {rise}]")
        out.append(f"goal pass{p}: dsone.dsn == inView({p}) start [{rise}, {rise}] "
                   f"end [{t0 + block}, {t0 + block}]")
        out.append(f"goal thrust{p}: dsone.engine == thrusting({1 + k % 3}) start [{t0}, {t0 + 3600}] "
                   f"duration [2400, 3000]")
        for i in range(4):
            target = imaging[(4 * k + i) % len(imaging)]
            out.append(f"goal nav{p}_{i + 1}: dsone.camera == picture({target}) "
                       f"start [{t0}, {rise}] end [0, {rise}]")
        out.append(f"goal down{p}: dsone.radio == downlink({p}) start [{rise}, {t0 + block}]")
    for k, target in science:
        t0 = k * block
        out.append(f"optional goal science{k + 1}: dsone.camera == picture({target}) "
                   f"start [{t0}, {t0 + block - pass_length}] penalty 10")
    open(path, "w").write("\n".join(out) + "\n")


write_problem("ds1-day.problem", "ds1_day", 12, list(zip((2, 5, 8, 11), ("ceres", "vesta", "ida", "eros"))))
# The first four hours: what the executive's integration tests fly (services/executive).
write_problem("ds1-4h.problem", "ds1_4h", 2, [])

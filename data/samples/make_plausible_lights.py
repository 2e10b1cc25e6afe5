#!/usr/bin/env python3
"""Plausible lights for the illumination constraint in the synthetic experiment (no randomness).

The lights a scene may be lit by, as the paper's narrow-band sensors (610, 540, 450 nm) see them:
CIE daylight at correlated colour temperatures 4000-25000 K (CIE 15 method, M1 and M2 rounded to
three decimals) and Planckian radiators at 2000-20000 K (c2 = 1.4388e-2 m K), every 500 K,
relative SPD at the three wavelengths written with 10 significant digits.
Writes plausible_lights_610_540_450.csv beside this script.
"""
import csv
import math
from pathlib import Path

here = Path(__file__).resolve().parent
bands = (610, 540, 450)
with open(here.parent / "cie_daylight_basis_S0_S1_S2.csv", newline="") as f:
    basis = {int(float(r["wavelength_nm"])): r for r in csv.DictReader(f)}


def daylight(T):
    t = 1 / T
    if T <= 7000:
        x = -4.6070e9 * t**3 + 2.9678e6 * t**2 + 0.09911e3 * t + 0.244063
    else:
        x = -2.0064e9 * t**3 + 1.9018e6 * t**2 + 0.24748e3 * t + 0.237040
    y = -3 * x * x + 2.87 * x - 0.275
    M = 0.0241 + 0.2562 * x - 0.7341 * y
    m1 = round((-1.3515 - 1.7703 * x + 5.9114 * y) / M, 3)
    m2 = round((0.0300 - 31.4424 * x + 30.0717 * y) / M, 3)
    return [float(basis[w]["S0"]) + m1 * float(basis[w]["S1"]) + m2 * float(basis[w]["S2"]) for w in bands]


def planck(T):
    return [(w * 1e-9) ** -5 / math.expm1(1.4388e-2 / (w * 1e-9 * T)) for w in bands]


def row(v):
    s = max(v)
    return ",".join(f"{x / s:.10g}" for x in v)


lines = ["# plausible lights as narrow-band (610/540/450 nm) sensors see them; see make_plausible_lights.py",
         "r,g,b"]
lines += [row(daylight(T)) for T in range(4000, 25001, 500)]
lines += [row(planck(T)) for T in range(2000, 20001, 500)]
(here / "plausible_lights_610_540_450.csv").write_text("\n".join(lines) + "\n")

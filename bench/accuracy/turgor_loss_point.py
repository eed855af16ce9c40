#!/usr/bin/env python3
"""The turgor-loss point of bench/accuracy/turgor_loss_point.lmp's runs against the membrane law.

  turgor_loss_point.py TAG...     (in the folder of the runs: turgid_TAG.txt, dry_TAG.dat)

The law: at the turgor-loss point the wall is back at its stress-free volume V_f (the fresh cell's
wall volume) and the sap at its reference density, so X*/X0 = V_f / (V_t (1 + P_t/K)) with V_t, P_t
the turgid wall volume and turgor (K = 20 MPa): the membrane law's turgid stretch lambda_t =
(V_t/V_f)^(1/3) as the cell reached it, and van 't Hoff's pi (the crossing needs no pi: P_T = 0
where the wall is unstretched). Also the analytic lambda_t = 1.109 of apple.cellsph's wall at
200 kPa (0.7259). Prints per run the X/X0 where the mean SPH pressure, the wall load, the fix's
P_T cross zero and where the wall volume is back at V_f, each with its error against the law."""
import sys

K = 20e6
ANALYTIC = 1.0 / (1.109 ** 3 * (1.0 + 200e3 / K))


def crossing(rows, col):
    for a, b in zip(rows, rows[1:]):
        if a[col] > 0.0 >= b[col]:
            return a[1] + (b[1] - a[1]) * a[col] / (a[col] - b[col])
    return float("nan")


def main(tags):
    print("| run | lambda_t | law X*/X0 | P_SPH = 0 | P_wall = 0 | fix P_T = 0 | V = V_f |")
    print("|---|---|---|---|---|---|---|")
    for tag in tags:
        words = open(f"turgid_{tag}.txt").read().split()
        v = {words[i]: float(words[i + 1]) for i in range(1, len(words) - 1, 2)}
        law = v["Vf0"] / (v["Vt"] * (1.0 + v["PTt"] / K))
        rows = [[float(w) for w in line.split()] for line in open(f"dry_{tag}.dat")
                if not line.startswith("#")]
        back = next((a[1] for a, b in zip(rows, rows[1:]) if a[3] >= v["Vf0"] > b[3]),
                    float("nan"))
        cells = [f"{x:.4f} ({100 * (x / law - 1):+.1f} %)" for x in
                 (crossing(rows, 5), crossing(rows, 6), crossing(rows, 7), back)]
        lam = (v["Vt"] / v["Vf0"]) ** (1.0 / 3.0)
        print(f"| {tag} | {lam:.4f} | {law:.4f} | " + " | ".join(cells) + " |")
    print(f"(analytic lambda_t 1.109: law {ANALYTIC:.4f})")


if __name__ == "__main__":
    main(sys.argv[1:])

#!/usr/bin/env python3
"""The paper's interplay experiment (Section VI, "Interplay Between Inexplicability Score and
Plan Cost", its figure): design size of the optimal design of one Driverlog problem for
alpha in {0.5, 0.66, 0.75, 1} and T in {1, 10, 20, 30, 40, 50}, with beta 0.25, gamma 0.9
(kappa 0.25, as in Table 1) and at most two modifications.

  python3 tests/benchmarks/paper/run_interplay.py [--envdesign build/bin/envdesign]
      [--problem tests/data/paper/driverlog/01/design-t1.textproto] [--out docs/results]
      [--from-runs]

The problem is the first Driverlog problem (the paper does not say which one it used). Each
(alpha, T) runs `envdesign design --json --workers 1 --max-design-size 2` under `nice -n 10`
on a temporary copy of the spec with those weights. Writes to --out:
  interplay.csv   one row per (alpha, T): design size, design, objective and its terms;
  interplay.png   design size over T, one line per alpha (gnuplot, if installed).
--from-runs redraws the plot from interplay.csv.
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys
import tempfile

from paper_runs import DATA, ENVDESIGN, RESULTS, derived_spec, number, run_design, write_csv

ALPHAS = (0.5, 0.66, 0.75, 1)
HORIZONS = (1, 10, 20, 30, 40, 50)
FIELDS = ["alpha", "horizon", "status", "design_size", "design", "objective", "inexplicability",
          "design_cost", "robot_cost", "baseline_objective", "mean_ie", "mean_plan_cost",
          "wall_s"]


def run(args):
    rows = []
    with tempfile.TemporaryDirectory() as scratch:
        for alpha in ALPHAS:
            for horizon in HORIZONS:
                spec = derived_spec(args.problem, scratch, alpha=alpha, beta=0.25, kappa=0.25,
                                    gamma=0.9, horizon=horizon)
                r = run_design(args.envdesign, spec, args.time_limit, ["--max-design-size", "2"])
                terms = r["terms"]
                f_t = (1 - 0.9 ** horizon) / (1 - 0.9)
                rows.append([alpha, horizon, r["status"], len(r["design"]), "+".join(r["design"]),
                             number(r["objective"]), number(terms["inexplicability"]),
                             number(terms["design_cost"]), number(terms["robot_cost"]),
                             number(r["baseline"]["objective"]),
                             number(terms["inexplicability"]) / f_t,
                             number(terms["robot_cost"]) / horizon, r["wall"]])
                print(f"alpha {alpha} T {horizon}: {r['status']} {r['design']} "
                      f"({r['wall']:.2f} s)", file=sys.stderr)
    return rows


def plot(csv_path, png_path):
    """Design size over the horizon, one line per alpha, as the paper's figure."""
    gnuplot = shutil.which("gnuplot")
    if not gnuplot:
        print("gnuplot not found (apt-get install gnuplot-nox): no plot", file=sys.stderr)
        return
    with open(csv_path) as f:
        rows = list(csv.DictReader(f))
    with tempfile.TemporaryDirectory() as scratch:
        blocks = []
        for i, alpha in enumerate(ALPHAS):
            data = os.path.join(scratch, f"alpha{i}.dat")
            with open(data, "w") as f:
                for row in rows:
                    if float(row["alpha"]) == alpha:
                        f.write(f"{row['horizon']} {row['design_size']}\n")
            # Small vertical offsets keep lines that coincide apart; the axis is whole numbers.
            blocks.append(f"'{data}' using 1:($2+{(i - 1.5) * 0.04:.2f}) with linespoints "
                          f"lw 2 pt {5 + 2 * i} ps 1.3 title 'alpha = {alpha:g}'")
        script = "\n".join([
            "set terminal pngcairo size 800,500 font 'Sans,12'",
            f"set output '{png_path}'",
            "set title 'Driverlog: design size of the optimal design (beta 0.25, gamma 0.9, at "
            "most 2)'",
            "set xlabel 'Horizon T'", "set ylabel 'Design size'",
            "set xrange [-2:52]", "set yrange [-0.3:2.3]", "set ytics 0,1,2",
            "set xtics (1, 10, 20, 30, 40, 50)", "set grid", "set key top right",
            "plot " + ", ".join(blocks)])
        subprocess.run([gnuplot], input=script, text=True, check=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--envdesign", default=ENVDESIGN)
    parser.add_argument("--problem", default=os.path.join(DATA, "driverlog", "01",
                                                          "design-t1.textproto"))
    parser.add_argument("--time-limit", type=float, default=1800)
    parser.add_argument("--out", default=RESULTS)
    parser.add_argument("--from-runs", action="store_true")
    args = parser.parse_args()
    csv_path = os.path.join(args.out, "interplay.csv")
    if not args.from_runs:
        write_csv(csv_path, FIELDS, run(args))
    plot(csv_path, os.path.join(args.out, "interplay.png"))
    with open(csv_path) as f:
        rows = list(csv.DictReader(f))
    print("design size (rows: alpha, columns: T)")
    print("alpha " + " ".join(f"{t:>4}" for t in HORIZONS))
    for alpha in ALPHAS:
        sizes = [r["design_size"] for r in rows if float(r["alpha"]) == alpha]
        print(f"{alpha:<5} " + " ".join(f"{s:>4}" for s in sizes))


if __name__ == "__main__":
    main()

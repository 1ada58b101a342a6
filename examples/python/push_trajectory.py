"""A push trajectory: the Fig 3.18 nanobar pushed over a rough surface, under the thesis'
sign law and under event-located Coulomb stick-slip, plotted with matplotlib.

    python3 push_trajectory.py [--out DIR]      # writes DIR/push_trajectory.png
"""
import argparse
import pathlib

import matplotlib
import matplotlib.pyplot as plt

import nanopush


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=".", help="folder for the figure")
    out = pathlib.Path(ap.parse_args().out)
    out.mkdir(parents=True, exist_ok=True)

    scene = nanopush.Scene.preset("fig3_18")           # mu = 0.06, F = 5 uN at (27.5, 45) nm
    runs = {law: nanopush.run(scene, law=law) for law in ("thesis", "coulomb")}

    fig, (ax_path, ax_theta) = plt.subplots(1, 2, figsize=(10, 4))
    for law, r in runs.items():
        ax_path.plot(r.x * 1e9, r.y * 1e9, label=f"{law} law")
        ax_theta.plot(r.t * 1e9, r.theta, label=f"{law} law ({r.nfcn} RHS evaluations)")
    ax_path.set(xlabel="x [nm]", ylabel="y [nm]", title=f"{scene.name}: path of the centre of mass")
    ax_theta.set(xlabel="t [ns]", ylabel="theta [rad]", title="orientation")
    for ax in (ax_path, ax_theta):
        ax.grid(True)
        ax.legend()
    fig.tight_layout()
    fig.savefig(out / "push_trajectory.png", dpi=100)
    r = runs["coulomb"]
    print(f"{scene.name}: final pose x = {r.x[-1]:.4g} m, y = {r.y[-1]:.4g} m, theta = {r.theta[-1]:.4g} rad "
          f"-> {out / 'push_trajectory.png'}")


if __name__ == "__main__":
    matplotlib.use("Agg")
    main()

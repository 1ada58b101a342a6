"""A friction map over the iCOR plane (thesis Figs 3.10-3.11): the normalised friction force
|f|/(mu N) and moment |mf|/(mu N max(a, b)) of the thesis nanobar (55 x 100 nm contact) for
every iCOR position of a 401 x 401 grid, in one vectorised call.

    python3 friction_map.py [--out DIR]         # writes DIR/friction_map.png
"""
import argparse
import pathlib

import matplotlib
import matplotlib.pyplot as plt
import numpy as np

import nanopush


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=".", help="folder for the figure")
    ap.add_argument("--n", type=int, default=401, help="grid points per axis")
    args = ap.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    a, b = 27.5e-9, 50e-9                                 # half-width, half-length [m]
    cx = np.linspace(-150e-9, 150e-9, args.n)             # iCOR position, body axes [m]
    cy = np.linspace(-150e-9, 150e-9, args.n)[:, None]    # broadcast: an n x n grid
    R = np.hypot(cx, cy)                                  # iCOR at -R (cos alpha, sin alpha)
    alpha = np.arctan2(-cy, -cx)
    fx, fy, mf = nanopush.friction_wrench(a, b, R, alpha)  # mu N = 1 N, counter-clockwise
    force = np.hypot(fx, fy)
    moment = np.abs(mf) / max(a, b)

    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    ext = [cx[0] * 1e9, cx[-1] * 1e9, cy[0, 0] * 1e9, cy[-1, 0] * 1e9]
    for ax, z, title in ((axes[0], force, "|f| / (mu N)"), (axes[1], moment, "|mf| / (mu N max(a, b))")):
        im = ax.imshow(z, origin="lower", extent=ext, cmap="viridis")
        ax.add_patch(plt.Rectangle((-a * 1e9, -b * 1e9), 2 * a * 1e9, 2 * b * 1e9, fill=False, color="w"))
        ax.set(xlabel="iCOR x' [nm]", ylabel="iCOR y' [nm]", title=title)
        fig.colorbar(im, ax=ax)
    fig.tight_layout()
    fig.savefig(out / "friction_map.png", dpi=100)
    print(f"{force.size} iCORs: |f|/(mu N) in [{force.min():.3f}, {force.max():.3f}] -> {out / 'friction_map.png'}")


if __name__ == "__main__":
    matplotlib.use("Agg")
    main()

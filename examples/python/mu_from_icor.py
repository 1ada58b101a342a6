"""The friction coefficient from an observed iCOR (thesis Fig 4.5, eq 4.10): a push of known
force turns the thesis nanorod about an iCOR seen at distance R from its centre of mass;
mu = F b / (W R), with its uncertainty propagated from F, R and the Hamaker constant.

    python3 mu_from_icor.py [--out DIR]         # writes DIR/mu_from_icor.png
"""
import argparse
import pathlib

import matplotlib
import matplotlib.pyplot as plt
import numpy as np

import nanopush
from nanopush import icor


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=".", help="folder for the figure")
    out = pathlib.Path(ap.parse_args().out)
    out.mkdir(parents=True, exist_ok=True)

    rod = icor.nanorod()                                  # L = 590 nm graphite rod
    F, sigma_F = 2.0e-6, 0.1e-6                           # measured push force [N]
    R = np.linspace(0.5e-6, 4e-6, 15)                     # observed iCOR distances [m]
    sigma_R = 0.05 * R                                    # 5 % read-off uncertainty
    est = [nanopush.estimate_mu(F, sigma_F, R=r, sigma_R=s, sigma_H=0.1 * rod.hamaker, rod=rod)
           for r, s in zip(R, sigma_R)]
    mu = np.array([e.mu for e in est])
    sigma = np.array([e.sigma for e in est])
    # The forward model gives the force back from (mu, R): eq 4.10.
    assert np.allclose(icor.force_from_icor(mu, rod.load, R, rod.length), F, rtol=1e-12)

    budget = {c["input"]: c["contribution"] for c in est[len(est) // 2].contributions}
    fig, (ax, ax_b) = plt.subplots(1, 2, figsize=(10, 4))
    ax.errorbar(R * 1e6, mu, yerr=sigma, fmt="o", capsize=3)
    ax.set(xlabel="observed iCOR distance R [um]", ylabel="mu", title=f"mu from F = {F:.2g} N and R (eq 4.10)")
    ax.grid(True)
    ax_b.bar(list(budget), list(budget.values()))
    ax_b.set(ylabel="|d mu/d x| sigma_x", title=f"uncertainty budget at R = {R[len(R) // 2] * 1e6:.2f} um")
    fig.tight_layout()
    fig.savefig(out / "mu_from_icor.png", dpi=100)
    e = est[len(est) // 2]
    print(f"R = {R[len(R) // 2]:.3g} m: mu = {e.mu:.4f} +- {e.sigma:.4f} -> {out / 'mu_from_icor.png'}")


if __name__ == "__main__":
    matplotlib.use("Agg")
    main()

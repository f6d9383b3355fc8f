#!/usr/bin/python3
"""Indentation of a swollen gel layer by a rigid sphere or a flat-ended cylinder, axisymmetric
(prm/indentation_sphere.prm, doc/indentation.md): the force F(t) against Hertz's (sphere) or
Boussinesq's (flat punch) undrained and drained limits, on several grids and depths, and the
normalised relaxation against Hu, Zhao, Vlassak & Suo's fits for linear poroelasticity.

  /usr/bin/python3 contrib/benchmarks/indentation.py [--gelmpm build/gelmpm]
      [--output output/indentation] [--shape sphere|flat] [--size 5] [--cells 100,150,200]
      [--depths 0.02] [--end 2000] [--radius 1] [--permeable] [--contact penalty|nitsche] [--plot doc/figures/indentation_sphere.png]
      [--reuse [--existing-only]]

Each run is the scene with a layer of radius and thickness S (--size; the scene's is 2.5) on
'Background grid/Cells' = n x (n + 2) (h = S/n, even n), the depth delta (the sphere's contact
radius a = sqrt(R delta)) and 'End time'. The indenter is impermeable ('Permeable = false': no
solvent crosses the contact) unless --permeable is given. The limits use the swollen gel's
shear modulus G_s and drained Poisson ratio nu, both computed here from the Flory-Rehner free
energy at the scene's swollen state (mu = 0; small shear and uniaxial stretches at fixed mu):
  sphere:     F = (4/3) E* sqrt(R) delta^(3/2),   E*(0+) = 4 G_s,   E*(inf) = 2 G_s/(1 - nu);
  flat punch: F = 2 E* a delta  (a = 0.25 the punch radius, its edge rounded by 'Edge radius').
F(0+) is the force at the end of the loading (1e-4 of the poroelastic time a^2/c), F(inf) the
force at the end time. The relaxation g = (F(t) - F(inf))/(F(0+) - F(inf)) is plotted against
tau = c t / a^2 with c = 2 (1 - nu)/(1 - 2 nu) G_s kappa the layer's consolidation coefficient
(kappa = (J - 1)/J D N nu the permeability in the model's units); the published fits of linear
poroelasticity (Hu et al., Appl. Phys. Lett. 96, 121904, 2010) are
  sphere:     g = 0.491 exp(-0.908 sqrt(tau)) + 0.509 exp(-1.679 tau),
  flat punch: g = 1.304 exp(-sqrt(tau)) - 0.304 exp(-0.254 tau).
Prints a Markdown table; writes <output>/indentation.csv and the plot.
"""
import argparse
import math
import os
import subprocess

import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "contrib", "plotting"))
from gelmpm_plot import force_relaxation, poroelastic_relaxation_fit  # noqa: E402
SCENE = os.path.join(ROOT, "prm", "indentation_sphere.prm")
CHI, N_NU, RADIUS = 0.1, 7.299e-3, 1.0


def bisect(f, lo, hi):
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if (f(mid) < 0.) == (f(lo) < 0.):
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def gel_constants():
    """lambda_s at mu = 0 (eq. (22)), G_s, the drained nu and the consolidation coefficient c/D."""
    def mu0(l):
        l3 = l ** 3
        return N_NU * (1 / l - 1 / l3) + math.log1p(-1 / l3) + 1 / l3 + CHI / l3 ** 2
    ls = bisect(mu0, 1.01, 10.)

    def stress(F):
        J = np.linalg.det(F)
        dpsi = (math.log1p(-1 / J) + 1 / J + CHI / J ** 2) / N_NU
        Fit = np.linalg.inv(F).T
        return (F - Fit) + dpsi * J * Fit
    eps = 1e-6
    lateral = lambda e: stress(ls * np.diag([1 + eps, 1 + e, 1 + e]))[1, 1]
    nu = -bisect(lateral, -1e-5, 1e-5) / eps
    F = ls * np.eye(3)
    F[0, 1] = ls * eps
    G_s = (stress(F) @ F.T / np.linalg.det(F))[0, 1] / eps
    J = ls ** 3
    c = 2 * (1 - nu) / (1 - 2 * nu) * G_s * (J - 1) / J * N_NU
    return ls, G_s, nu, c


PUNCH_RADIUS = 0.25


def limits(shape, depth, G_s, nu):
    if shape == "sphere":
        a = math.sqrt(RADIUS * depth)
        hertz = 4. / 3. * math.sqrt(RADIUS) * depth ** 1.5
        return a, hertz * 4 * G_s, hertz * 2 * G_s / (1 - nu)
    a = PUNCH_RADIUS
    return a, 2 * a * depth * 4 * G_s, 2 * a * depth * 2 * G_s / (1 - nu)


def fit(shape, tau):
    return np.array([poroelastic_relaxation_fit(shape, t) for t in tau])


def default_contact(shape):
    """The scene's penalty for both shapes. (Nitsche with the traction deciding the active set,
    doc/flat_punch.md "A rigid punch", lifts the sealed face off near its edge here:
    doc/indentation.md.)"""
    return "penalty"


def refinement_box(args, a, n):
    """The box refined round the contact (--levels): from the axis to --box-width a, and from
    --box-depth a below the layer's top to the top of the grid."""
    top = args.size * (n + 2) / n
    return "0, %.12g : %.12g, %.12g" % (args.size - args.box_depth * a, args.box_width * a, top)


def run(args, shape, n, depth, c, levels=0):
    a, _, _ = limits(shape, depth, 1., 0.)
    t_load = 1e-4 * a * a / c
    size = args.size
    directory = os.path.join(args.output, "%s%s_s%g_n%d_d%g%s%s%s" % (
        shape, "" if shape != "sphere" or RADIUS == 1. else "_R%g" % RADIUS, size, n, depth,
        "_permeable" if args.permeable else "",
        "" if args.contact == default_contact(shape) else "_" + args.contact,
        "" if levels == 0 else "_L%d_w%g_d%g" % (levels, args.box_width, args.box_depth)))
    os.makedirs(directory, exist_ok=True)
    sets = ["Output/Directory=" + directory, "Output/Write particles=false",
            "Background grid/Cells=%d, %d" % (n, n + 2),
            "Background grid/Upper corner=%.12g, %.12g" % (size, size * (n + 2) / n),
            "Geometry/Boxes=0, 0 : %g, %g" % (size, size),
            "Contact/indenter/Center=0, %g" % (size + (RADIUS if shape == "sphere" else 0.)),
            "Contact/indenter/Radius=%.12g" % RADIUS,
            "Contact/indenter/Motion/Function expression=0; -%.12g * min(t / %.12g, 1)"
            % (depth, t_load),
            "Time stepping/Initial step=%.12g" % (t_load / 10),
            "Time stepping/Step caps=%.12g: %.12g" % (t_load, t_load / 10),
            "Time stepping/Stop at times=%.12g" % t_load,
            "Time stepping/End time=%g" % args.end,
            "Contact/indenter/Permeable=%s" % ("true" if args.permeable else "false")]
    if levels > 0:
        # The refined grid takes the direct solver (doc/architecture.md, "Local refinement").
        sets += ["Background grid/Refinement boxes=" + refinement_box(args, a, n),
                 "Background grid/Refinement levels=%d" % levels, "Linear solver/Solver=MUMPS"]
    if shape == "flat":
        sets += ["Contact/indenter/Shape=flat punch", "Contact/indenter/Radius=%g" % PUNCH_RADIUS]
    if args.contact == "nitsche":
        # The traction decides the active set under a face (doc/flat_punch.md, "A rigid punch").
        sets += ["Contact/Method=nitsche", "Contact/Active set factor=0.01"]
    else:
        sets += ["Contact/Method=penalty"]
    command = [args.gelmpm]
    for s in sets:
        command += ["--set", s]
    command.append(SCENE)
    log_file = os.path.join(directory, "log.txt")
    done = args.reuse and os.path.exists(log_file) and "reached t/tau_d" in open(log_file).read()
    if not done and args.existing_only:
        return None
    if not done:
        with open(log_file, "w") as log:
            subprocess.run(command, check=True, stdout=log, stderr=subprocess.STDOUT)
    data = np.genfromtxt(os.path.join(directory, "statistics.csv"), delimiter=",", names=True)
    t, F = data["t_over_tau_d"], data["indenter_force_y"]
    i0 = int(np.argmin(np.abs(t - t_load)))
    # g from the row at the end of the loading on (gelmpm-plot --relaxation computes the same).
    relaxation = force_relaxation(list(t), list(F), load_end=t_load)
    return dict(t=t, F=F, t_load=t_load, F0=relaxation["F0"], Finf=relaxation["Finf"],
                g=relaxation["g"], t_after=relaxation["t"], F_after=relaxation["F"], a=a,
                wall=data["wall_time"][-1], radius=data["indenter_contact_radius"][i0],
                unknowns=int(np.nanmax(data["n_dofs_u"] + data["n_dofs_mu"])), levels=levels)


TAUS = [0.001, 0.01, 0.03, 0.1, 0.3, 1, 3, 10, 100]


def print_relaxation_table(results, c):
    """g at the tabulated tau (linear in log tau between the rows), one row per run, and the
    largest difference of g over tau in [0.01, 10] between consecutive runs."""
    print("| a/h | levels | " + " | ".join("%g" % tau for tau in TAUS) + " |")
    print("|---|---|" + "---|" * len(TAUS))
    rows = []
    for r in results:
        tau = c * np.array(r["t_after"]) / r["a"] ** 2
        keep = tau > 0
        g = np.interp(np.log(TAUS), np.log(tau[keep]), np.array(r["g"])[keep],
                      left=np.nan, right=np.nan)
        dense = np.logspace(-2, 1, 61)
        rows.append(np.interp(np.log(dense), np.log(tau[keep]), np.array(r["g"])[keep]))
        print("| %.1f | %d | " % (r["a"] / r["h"], r["levels"]) +
              " | ".join("%.3f" % v for v in g) + " |")
    for k in range(1, len(rows)):
        print("largest |g difference| over tau in [0.01, 10], run %d against %d: %.4f"
              % (k + 1, k, float(np.max(np.abs(rows[k] - rows[k - 1])))))


def main():
    global RADIUS
    parser = argparse.ArgumentParser()
    parser.add_argument("--gelmpm", default=os.path.join(ROOT, "build", "gelmpm"))
    parser.add_argument("--output", default=os.path.join(ROOT, "output", "indentation"))
    parser.add_argument("--shape", default="sphere", choices=["sphere", "flat"])
    parser.add_argument("--size", type=float, default=5.)
    parser.add_argument("--cells", default="100,150,200")
    parser.add_argument("--depths", default="0.02")
    parser.add_argument("--end", type=float, default=2000.)
    parser.add_argument("--contact", choices=["penalty", "nitsche"],
                        help="the contact method (default: penalty; nitsche: with 'Active set "
                        "factor' 0.01)")
    parser.add_argument("--radius", type=float, default=RADIUS,
                        help="the sphere's radius R (default 1; the contact radius is sqrt(R delta))")
    parser.add_argument("--permeable", action="store_true",
                        help="a permeable indenter (the bath reaches the contact); default: "
                        "impermeable, as the published relaxation functions assume")
    parser.add_argument("--levels", default="0",
                        help="comma-separated refinement levels of a box round the contact "
                        "(0: the uniform grid; each level halves h there)")
    parser.add_argument("--box-width", type=float, default=3.5,
                        help="the refined box reaches from the axis to this many contact radii a")
    parser.add_argument("--box-depth", type=float, default=2.5,
                        help="and from this many a below the layer's top to the grid's top")
    parser.add_argument("--plot", default="")
    parser.add_argument("--reuse", action="store_true",
                        help="take the results of runs already completed in --output")
    parser.add_argument("--existing-only", action="store_true",
                        help="with --reuse: leave out the runs not completed in --output")
    args = parser.parse_args()
    if args.contact is None:
        args.contact = default_contact(args.shape)
    RADIUS = args.radius
    ls, G_s, nu, c = gel_constants()
    print("swollen stretch %.6f, G_s = %.6f G, drained nu = %.6f, c = %.6g D, 2(1 - nu) = %.4f"
          % (ls, G_s, nu, c, 2 * (1 - nu)))
    results = []
    print("layer radius and thickness %g" % args.size)
    print("| h (finest) | a/h | levels | unknowns (most) | delta | F(0+) | /closed form | F(end) | "
          "/closed form | F(0+)/F(end) | contact radius at 0+ / a | wall |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for depth in [float(d) for d in args.depths.split(",")]:
        for n in [int(k) for k in args.cells.split(",")]:
            for levels in [int(k) for k in args.levels.split(",")]:
                r = run(args, args.shape, n, depth, c, levels)
                if r is None:
                    continue
                a, F0, Finf = limits(args.shape, depth, G_s, nu)
                h = args.size / n / 2 ** levels
                r.update(n=n, depth=depth, h=h)
                results.append(r)
                print("| %.5f | %.1f | %d | %d | %g | %.6g | %.4f | %.6g | %.4f | %.4f | %.3f | %.0f s |"
                      % (h, a / h, levels, r["unknowns"], depth, r["F0"], r["F0"] / F0, r["Finf"],
                         r["Finf"] / Finf, r["F0"] / r["Finf"], r["radius"] / a, r["wall"]),
                      flush=True)
    print_relaxation_table(results, c)
    with open(os.path.join(args.output, "indentation.csv"), "w") as out:
        out.write("n,levels,depth,t_over_tau_d,tau,force,g\n")
        for r in results:
            for dt, F, g in zip(r["t_after"], r["F_after"], r["g"]):
                out.write("%d,%d,%g,%.10g,%.10g,%.10g,%.10g\n" % (
                    r["n"], r["levels"], r["depth"], r["t_load"] + dt, c * dt / r["a"] ** 2, F, g))
    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6, 4))
        for r in results:
            tau = c * np.array(r["t_after"]) / r["a"] ** 2
            g = np.array(r["g"])
            ax.semilogx(np.maximum(tau, 1e-5), g, marker=".",
                        label="MPM h = %.4f%s, delta = %g%s" % (
                            r["h"], " (%d levels at the contact)" % r["levels"] if r["levels"] else "",
                            r["depth"],
                            ", R = %g (a/h = %.1f)" % (RADIUS, r["a"] * r["n"] / args.size)
                            if RADIUS != 1. else ""))
        tau = np.logspace(-5, 2, 200)
        ax.semilogx(tau, fit(args.shape, tau), "k--", label="Hu et al. 2010 (linear poroelasticity)")
        ax.set_xlabel("c t / a^2")
        ax.set_ylabel("(F(t) - F(inf)) / (F(0+) - F(inf))")
        ax.set_title("%s indentation of a swollen layer" % ("Sphere" if args.shape == "sphere"
                                                              else "Flat punch"))
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(args.plot, dpi=120)
        print("plot:", args.plot)


if __name__ == "__main__":
    main()

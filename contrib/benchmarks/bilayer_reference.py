"""Timoshenko's bimetal curvature for the bilayer actuator (prm/bilayer_actuator.prm), from the
Flory-Rehner law in closed form (independent of GelMPM's code):

  P_ii F_ii = G (F_ii^2 - 1) + (G / N nu) J [ln(1 - 1/J) + 1/J + chi/J^2 - mu/kT]

for diagonal F (paper eq. (19) with the units of doc/method.md). Per layer r, at the common
initial mu_0 (Table 1: lambda_0 = 1.2801) and the bath mu_b, in plane strain (F_33 = lambda_0r):
  lambda_0r  the isotropic stress-free stretch at mu_0 (eq. (22)),
  a_r        the in-plane free-swelling stretch at mu_b relative to the initial state,
  E'_r       the drained in-plane uniaxial modulus about that state (sigma_22 = 0, F_33 fixed),
  h_r        the layer's swollen thickness h_r0 a_r.
The mismatch strain is eps = a_1/a_2 - 1 and Timoshenko's curvature (J. Opt. Soc. Am. 11, 1925)
  kappa = 6 eps (1 + m)^2 / (h [3 (1 + m)^2 + (1 + m n)(m^2 + 1/(m n))]),
with m = h_1/h_2, n = E'_1/E'_2, h = h_1 + h_2: the small-mismatch, linear-elastic limit.
"""
import math

N_NU = 7.299e-3
LAMBDA_0 = 1.2801


def stress_times_stretch(s, J, mu, chi, G=1.0, n_nu=N_NU):
    return G * (s * s - 1.0) + G / n_nu * J * (math.log(1.0 - 1.0 / J) + 1.0 / J + chi / J**2 - mu)


def bisect(f, a, b):
    fa = f(a)
    for _ in range(200):
        m = 0.5 * (a + b)
        fm = f(m)
        if fa * fm <= 0.0:
            b = m
        else:
            a, fa = m, fm
    return 0.5 * (a + b)


def mu_0():
    J0 = LAMBDA_0**3
    return stress_times_stretch(LAMBDA_0, J0, 0.0, 0.1) / (J0 / N_NU)


def layer(chi, mu_b):
    """(lambda_0r, a_r, E'_r) of a layer of the Table 1 gel with chi."""
    m0 = mu_0()
    l0 = bisect(lambda s: stress_times_stretch(s, s**3, m0, chi), 1.0 + 1e-12, 10.0)
    a = bisect(lambda t: stress_times_stretch(l0 * t, l0**3 * t * t, mu_b, chi),
               (1.0 + 1e-12) / l0**1.5, 10.0)

    def cauchy_11(delta):
        F11 = l0 * a * (1.0 + delta)
        b = bisect(lambda u: stress_times_stretch(l0 * a * u, F11 * l0 * a * u * l0, mu_b, chi),
                   0.5, 1.5)
        J = F11 * l0 * a * b * l0
        return stress_times_stretch(F11, J, mu_b, chi) / J  # P_11 F_11 / J

    d = 1e-6
    E = (cauchy_11(d) - cauchy_11(-d)) / (2 * d)
    return l0, a, E


def timoshenko(chi_top, chi_bottom, mu_b, h_top0=0.1, h_bottom0=0.1):
    _, a1, E1 = layer(chi_top, mu_b)
    _, a2, E2 = layer(chi_bottom, mu_b)
    eps = a1 / a2 - 1.0
    h1, h2 = h_top0 * a1, h_bottom0 * a2
    m, n, h = h1 / h2, E1 / E2, h1 + h2
    kappa = 6 * eps * (1 + m)**2 / (h * (3 * (1 + m)**2 + (1 + m * n) * (m * m + 1 / (m * n))))
    return kappa, eps


if __name__ == "__main__":
    for chi in (0.11, 0.12, 0.15):
        k, e = timoshenko(0.1, chi, -0.08)
        print(f"chi_bottom = {chi}: mismatch {e:.5f}, Timoshenko curvature {k:.6f}")

#!/usr/bin/env python3
"""Reference numbers for the Gumbel fits of crates/analysis/src/storm/extremes.rs (its tests quote them): for two
fixed sets of storm maxima, scipy's maximum-likelihood fit, the moment estimates, the most
probable maximum (the mode, = the location) and the 90 % quantile, each printed to 17 figures.

Needs scipy (not part of the repository's tooling); in a throwaway venv:

    python3 -m venv /var/tmp/scipy-venv && /var/tmp/scipy-venv/bin/pip install scipy
    /var/tmp/scipy-venv/bin/python validation/storm/gumbel_reference.py

Maximum likelihood. `scipy.stats.gumbel_r.fit(x)` (scipy ≥ 1.7) does not run a general optimiser
(whose default tolerance is ~1e-4): it solves the profile equation of the scale,

    β = mean(x) − Σ xᵢ e^(−xᵢ/β) / Σ e^(−xᵢ/β),

with `root_scalar(..., rtol=1e-14, xtol=1e-14)` and then takes μ = −β ln(mean(e^(−x/β))). This
script checks that independently: it solves the same equation itself with
`scipy.optimize.brentq` to xtol = rtol = 1e-14, asserts that the two agree to 1e-12 relative, and
that both partial derivatives of the log-likelihood vanish at the fit (to 1e-9 of the terms they
sum). Moments: β = s √6 / π with s the sample standard deviation (n − 1 divisor, ddof=1), and
μ = mean − γ β (γ the Euler–Mascheroni constant) — computed here by hand, since
`gumbel_r.fit(x, method="MM")` matches the population variance (n divisor) instead.
"""

import numpy as np
from scipy import optimize, special, stats

# Largest fairlead tension of each of 10 seeds of a 3-hour storm [kN].
TENSIONS_10 = [1843.2, 1921.7, 1788.4, 2012.9, 1867.5, 1955.1, 1899.8, 2086.3, 1812.6, 1934.0]
# Another line, 7 seeds [kN].
TENSIONS_7 = [412.5, 398.1, 455.7, 431.2, 389.9, 470.3, 420.8]

P = 0.9


def profile(beta, x):
    """The MLE profile equation of the scale: zero at the fit."""
    w = np.exp(-(x - x.min()) / beta)  # shifted by the minimum: the ratio is unchanged, no overflow
    return x.mean() - (x * w).sum() / w.sum() - beta


def location_from_scale(beta, x):
    """μ = −β ln(mean(e^(−x/β))), by log-sum-exp."""
    return -beta * (special.logsumexp(-x / beta) - np.log(len(x)))


def mle_by_brentq(x, start):
    """Solve the profile equation to 1e-14 with brentq, bracketing around the moment estimate."""
    lo, hi = start / 2, start * 2
    while np.sign(profile(lo, x)) == np.sign(profile(hi, x)):
        lo, hi = lo / 2, hi * 2
    beta = optimize.brentq(profile, lo, hi, args=(x,), xtol=1e-14, rtol=1e-14, maxiter=500)
    return location_from_scale(beta, x), beta


def check_stationary(x, mu, beta):
    """Both partial derivatives of the log-likelihood vanish at (μ, β)."""
    z = (x - mu) / beta
    e = np.exp(-z)
    d_mu = (1 - e).sum() / beta  # ∂ℓ/∂μ
    d_beta = (-1 + z - z * e).sum() / beta  # ∂ℓ/∂β
    scale_mu = (1 + e).sum() / beta
    scale_beta = (1 + np.abs(z) + np.abs(z * e)).sum() / beta
    assert abs(d_mu) < 1e-9 * scale_mu, (d_mu, scale_mu)
    assert abs(d_beta) < 1e-9 * scale_beta, (d_beta, scale_beta)


def report(name, values):
    x = np.asarray(values, dtype=float)
    median = float(np.median(x))
    mm_beta = x.std(ddof=1) * np.sqrt(6) / np.pi
    mm_mu = float(x.mean() - np.euler_gamma * mm_beta)
    mm_beta = float(mm_beta)

    sp_mu, sp_beta = (float(v) for v in stats.gumbel_r.fit(x))
    bq_mu, bq_beta = mle_by_brentq(x, mm_beta)
    assert abs(sp_beta - bq_beta) <= 1e-12 * bq_beta, (sp_beta, bq_beta)
    assert abs(sp_mu - bq_mu) <= 1e-12 * abs(bq_mu), (sp_mu, bq_mu)
    check_stationary(x, sp_mu, sp_beta)

    print(f"{name} (n = {len(x)}): {values}")
    for label, mu, beta in [("moments", mm_mu, mm_beta), ("maximum likelihood (scipy)", sp_mu, sp_beta)]:
        print(f"  {label}:")
        print(f"    location μ = most probable maximum = {mu!r}")
        print(f"    scale β                            = {beta!r}")
        print(f"    gumbel_r.ppf({P}, μ, β)            = {float(stats.gumbel_r.ppf(P, mu, beta))!r}")
        print(f"    gumbel_r.cdf(median(x), μ, β)      = {float(stats.gumbel_r.cdf(median, mu, beta))!r}")
    print(f"  brentq MLE (independent check): μ = {float(bq_mu)!r}, β = {float(bq_beta)!r}")
    print(f"  median(x) = {median!r}")


if __name__ == "__main__":
    print(f"scipy {__import__('scipy').__version__}, numpy {np.__version__}")
    report("TENSIONS_10", TENSIONS_10)
    report("TENSIONS_7", TENSIONS_7)

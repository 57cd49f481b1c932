"""Rheology conversions checked by the Volterra identity int_0^t E(t - s) dJ(s) = 1.

The identity links a relaxation modulus to its creep compliance without any Laplace
algebra; it is solved here by plain trapezoidal quadrature (Findley, Lai & Onaran 1976,
*Creep and relaxation of nonlinear viscoelastic materials*, sec. 5.2 / eq. 5.22).
"""

from __future__ import annotations

import numpy as np
import pytest

from contact._errors import ContactInputError
from contact._materials import material
from contact.viscoelastic._rheology import (
    CreepSeries,
    PronySeries,
    StandardLinearSolid,
    pair_creep,
)


def _volterra(relax, creep, t_end: float, n: int = 20001) -> float:
    """max over t of |J(0) E(t) + int_0^t E(t - s) J'(s) ds - 1| on a fine grid."""
    t = np.linspace(0.0, t_end, n)
    dj = np.gradient(creep(t), t)
    j0 = creep(np.array([0.0]))[0]
    worst = 0.0
    for k in range(100, n, 1000):
        s = t[: k + 1]
        val = j0 * relax(np.array([t[k]]))[0] + np.trapezoid(relax(t[k] - s) * dj[: k + 1], s)
        worst = max(worst, abs(val - 1.0))
    return worst


def test_sls_stress_relaxation_time_is_tau_c_er_over_eg() -> None:
    sls = StandardLinearSolid(4e9, 1e9, 2.0, nu=0.0)
    assert sls.tau_sigma == pytest.approx(0.5)
    creep = sls.creep()  # nu = 0: (1 - nu^2) J = J
    assert _volterra(sls.relaxation_modulus, creep.compliance, 8.0) < 2e-4
    # the wrong pairing (relaxation time = creep time) breaks the identity
    wrong = StandardLinearSolid(4e9, 1e9, 0.5, nu=0.0).creep()
    assert _volterra(sls.relaxation_modulus, wrong.compliance, 8.0) > 0.05


def test_prony_to_creep_series() -> None:
    pr = PronySeries(1e9, (2e9, 5e8), (0.1, 3.0), nu=0.0)
    creep = pr.creep()
    assert creep.glassy == pytest.approx(1.0 / 3.5e9)
    assert creep.relaxed == pytest.approx(1.0 / 1e9)
    assert _volterra(pr.relaxation_modulus, creep.compliance, 12.0) < 2e-4
    # one-term Prony = SLS: creep time tau_sigma E_g / E_r
    one = PronySeries(1e9, (3e9,), (0.25,), nu=0.0).creep()
    assert one.times[0] == pytest.approx(0.25 * 4.0)


def test_pair_creep_and_limits() -> None:
    steel = material("steel")
    sls = StandardLinearSolid(3e9, 1e9, 1e-3, nu=0.4)
    c = pair_creep(steel, sls)
    f = 1 - 0.4**2
    assert c.glassy == pytest.approx((1 - 0.3**2) / 210e9 + f / 3e9)
    assert c.relaxed == pytest.approx((1 - 0.3**2) / 210e9 + f / 1e9)
    assert c.relaxed_only().amplitudes == ()
    c1, c2 = c.storage_loss(np.array([0.0, 1e3, 1e12]))
    assert c1[0] == pytest.approx(c.relaxed) and c1[-1] == pytest.approx(c.glassy, rel=1e-6)
    assert c2[1] > 0


def test_bad_rheology() -> None:
    with pytest.raises(ContactInputError, match="exceeds the glassy"):
        StandardLinearSolid(1e9, 2e9, 1.0)
    with pytest.raises(ContactInputError, match="tau"):
        PronySeries(1e9, (1e9,), (0.0,))
    with pytest.raises(ContactInputError, match="rigid"):
        pair_creep(None, None)
    with pytest.raises(ContactInputError):
        CreepSeries(1e-9, (1e-9,), (-1.0,))


def test_sls_from_loss_peak() -> None:
    from contact.viscoelastic._loss import loss_data, sls_from_loss

    sls = sls_from_loss(70e9, 0.33, 1e-3, 2e-3)
    w = np.geomspace(1.0, 1e6, 20001)
    tsig = sls.tau_sigma
    e = sls.E_r + (sls.E_g - sls.E_r) * 1j * w * tsig / (1 + 1j * w * tsig)  # E*(omega)
    tan = e.imag / e.real
    k = int(np.argmax(tan))
    assert tan[k] == pytest.approx(1e-3, rel=1e-6)
    assert w[k] == pytest.approx(1 / 2e-3, rel=2e-3)
    assert np.sqrt(sls.E_g * sls.E_r) == pytest.approx(70e9)
    assert loss_data("al").low <= loss_data("al").typical <= loss_data("al").high
    with pytest.raises(ContactInputError, match="no loss data"):
        loss_data("unobtainium")

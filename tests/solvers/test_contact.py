"""Contact laws and HBM option validation."""

from __future__ import annotations

import dataclasses
import re

import numpy as np
import pytest

from seafast.config.modes import ContactLawKind, Formulation, NonlinearSolver
from seafast.fourier import real_dft_matrices
from seafast.solvers.contact import ContactLaw, contact_law
from seafast.solvers.hbm import HBMOptions

K = 1.1e9


@pytest.mark.parametrize("name", list(ContactLawKind))
def test_derivative_matches_finite_difference(name):
    law = contact_law(name, 1000.0)
    d = np.linspace(-0.01, 0.01, 201) + 1.234e-6  # avoid the exact kink
    h = 1e-9
    fd = (law.force(d + h, K) - law.force(d - h, K)) / (2 * h)
    assert np.allclose(law.derivative(d, K), fd, rtol=1e-5, atol=1e-3 * K)


def test_exact_law_values_and_generalised_derivative():
    law = contact_law("exact")
    d = np.array([-1e-3, 0.0, 2e-3])
    assert np.array_equal(law.force(d, K), [0.0, 0.0, K * 2e-3])
    assert np.array_equal(law.derivative(d, K), [0.0, K / 2, K])


def test_tanh_is_the_source_law_and_pulls_slightly():
    law = contact_law("tanh", 1000.0)
    d = np.linspace(-0.02, 0.02, 40001)
    f = law.force(d, K)
    assert np.allclose(f, K * d * (1 + np.tanh(1000 * d)) / 2)
    # largest tension: -0.139 k / kappa at kappa delta ~ -0.64 (about 153 kN for the base saddle)
    assert f.min() == pytest.approx(-0.1392 * K / 1000.0, rel=2e-3)
    assert d[np.argmin(f)] * 1000 == pytest.approx(-0.639, abs=2e-3)
    # accurate to ~0.1 % at 5 mm (docs/theory.md#6-contact-laws): relative error k d (1 - tanh) / 2 vs k d
    assert abs(law.force(5e-3, K) / (K * 5e-3) - 1) < 1e-4


def test_softplus_never_negative_and_stable_for_huge_arguments():
    law = contact_law("softplus", 1000.0)
    d = np.array([-10.0, -1.0, -1e-3, 0.0, 1e-3, 1.0, 10.0])
    with np.errstate(over="raise", invalid="raise", divide="raise"):
        f, fp = law.force_and_derivative(d, K)
    assert np.all(f >= 0) and np.all(np.isfinite(f)) and np.all(np.isfinite(fp))
    assert f[3] == pytest.approx(K * np.log(2) / 1000)
    assert f[-1] == pytest.approx(K * 10.0)


def test_vectorised_broadcast_over_saddles():
    law = contact_law("tanh")
    d = np.random.default_rng(1).normal(0, 3e-3, (16, 3))
    k = np.array([1e9, 2e9, 3e9])
    assert law.force(d, k).shape == (16, 3)
    assert np.allclose(law.force(d, k)[:, 1], law.force(d[:, 1], 2e9))


def test_invalid_law_names_the_accepted_values():
    with pytest.raises(ValueError, match="tanh, softplus, exact"):
        contact_law("coulomb")
    with pytest.raises(ValueError, match="regularisation_per_m"):
        ContactLaw("tanh", -1.0)


@pytest.mark.parametrize(
    "kwargs, field",
    [
        ({"harmonics": -1}, "harmonics"),
        ({"harmonics": 2.5}, "harmonics"),
        ({"harmonics": 5, "time_samples": 11}, "time_samples"),
        ({"contact_law": "hard"}, "contact_law"),
        ({"regularisation_per_m": 0.0}, "regularisation_per_m"),
        ({"formulation": "reduced"}, "formulation"),
        ({"solver": "lm"}, "solver"),
        ({"tolerance": 0.0}, "tolerance"),
        ({"max_iterations": 0}, "max_iterations"),
        ({"continuation": "yes"}, "continuation"),
    ],
)
def test_options_validation_names_field_value_and_allowed(kwargs, field):
    with pytest.raises(ValueError, match="allowed") as err:
        HBMOptions(**kwargs)
    text = str(err.value)
    assert field in text and "allowed" in text and repr(kwargs[field]) in text


def test_options_are_keyword_only_frozen_and_accept_minimal_grid():
    with pytest.raises(TypeError):
        HBMOptions(5)  # type: ignore[misc]
    o = HBMOptions(harmonics=3, time_samples=8)  # N = 2H + 2, not a power of two needed
    assert HBMOptions(harmonics=3, time_samples=9).time_samples == 9
    with pytest.raises(dataclasses.FrozenInstanceError):
        o.harmonics = 4  # type: ignore[misc]
    # the exact law and adaptive harmonics are the defaults; the source's method is one constant away
    assert o.to_dict()["contact_law"] == "exact"
    default = HBMOptions()
    assert default.adaptive and default.harmonics is None and default.time_samples is None
    assert default.with_harmonics(160).time_samples == 400 and default.with_harmonics(5).time_samples == 128
    from seafast.solvers.hbm import SOURCE_OPTIONS

    assert (SOURCE_OPTIONS.contact_law, SOURCE_OPTIONS.regularisation_per_m, SOURCE_OPTIONS.harmonics) == (ContactLawKind.TANH, 1000.0, 5)
    assert (SOURCE_OPTIONS.time_samples, SOURCE_OPTIONS.solver) == (128, NonlinearSolver.HYBR)


def test_modes_given_by_their_values_become_the_enum_members():
    """The case file's strings and the enum members are one: HBMOptions and ContactLaw hold members
    (compared by identity in the solvers), and the options' plain dict holds the values."""
    o = HBMOptions(contact_law="tanh", formulation="full", solver="hybr")
    assert o.contact_law is ContactLawKind.TANH and o.formulation is Formulation.FULL and o.solver is NonlinearSolver.HYBR
    assert o.law.name is ContactLawKind.TANH and ContactLaw("softplus").name is ContactLawKind.SOFTPLUS
    plain = o.to_dict()
    assert (plain["contact_law"], plain["formulation"], plain["solver"]) == ("tanh", "full", "hybr")
    assert all(type(plain[k]) is str for k in ("contact_law", "formulation", "solver"))
    with pytest.raises(ValueError, match=re.escape("HBMOptions.formulation = 'dense'; allowed: condensed | full")):
        HBMOptions(formulation="dense")


@pytest.mark.parametrize("H, N", [(0, 2), (1, 4), (5, 128), (7, 17)])
def test_real_dft_pair_is_exact(H, N):
    inverse, forward = real_dft_matrices(H, N)
    assert np.allclose(forward @ inverse, np.eye(2 * H + 1), atol=1e-13)
    assert real_dft_matrices(H, N)[0] is inverse  # cached

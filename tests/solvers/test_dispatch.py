"""One entry point for the periodic response (solvers/dispatch.py) and the references' options (references/options.py).

``solve_periodic`` gives, for each method, exactly what that method's own function gives; it refuses options
of another method, an unknown method and a start the method does not take, by name; a time-domain reference
started from the harmonic balance solves that first, with its own settings. The options are keyword-only,
validated, and hold the modes as enum members.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from seafast.config.modes import Formulation, SolverMethod, TimeDomainStart
from seafast.solvers import solve_periodic
from seafast.solvers.dispatch import OPTIONS_CLASSES
from seafast.solvers.hbm import HBMOptions, solve_hbm
from seafast.solvers.references import QuasiStaticOptions, TimeDomainOptions, solve_quasi_static, solve_time_domain
from solver_cases import base_model, wave_excitation


@pytest.fixture(scope="module")
def case():
    model = base_model(element_length_m=4.0)
    return model, wave_excitation(model)


def _same(a, b) -> None:
    assert a.method == b.method and a.outcome is b.outcome and a.message == b.message and a.iterations == b.iterations
    np.testing.assert_array_equal(a.saddle_force_time_N, b.saddle_force_time_N)
    np.testing.assert_array_equal(a.cargo_displacement_time_m, b.cargo_displacement_time_m)


def test_each_method_gives_what_its_own_solver_gives(case):
    model, ex = case
    hbm = HBMOptions(harmonics=6, time_samples=32)
    _same(solve_periodic(model, ex, SolverMethod.HBM, options=hbm), solve_hbm(model, ex, hbm))
    _same(solve_periodic(model, ex, "quasi_static"), solve_quasi_static(model, ex))
    td = TimeDomainOptions(time_samples=32, formulation=Formulation.CONDENSED)
    _same(solve_periodic(model, ex, SolverMethod.TIME_DOMAIN, options=td), solve_time_domain(model, ex, td))
    assert set(OPTIONS_CLASSES) == set(SolverMethod)


def test_a_time_domain_reference_from_the_harmonic_balance_solves_it_first(case):
    model, ex = case
    hbm = HBMOptions(harmonics=6, time_samples=32)
    options = TimeDomainOptions(time_samples=32, start=TimeDomainStart.HBM, hbm=hbm)
    r = solve_periodic(model, ex, SolverMethod.TIME_DOMAIN, options=options)
    _same(r, solve_time_domain(model, ex, options, start=solve_hbm(model, ex, hbm)))
    assert r.orbit.start is TimeDomainStart.GIVEN and r.orbit.start_method == "hbm" and r.orbit.same_as_start
    with pytest.raises(ValueError, match=r"options\.start = 'hbm' needs the harmonic balance's solution"):
        solve_time_domain(model, ex, options)


def test_options_of_another_method_an_unknown_method_and_a_start_it_cannot_take_are_refused(case):
    model, ex = case
    with pytest.raises(ValueError, match=r"options: a HBMOptions for method = 'time_domain'; allowed: TimeDomainOptions"):
        solve_periodic(model, ex, SolverMethod.TIME_DOMAIN, options=HBMOptions())
    with pytest.raises(ValueError, match=r"method = 'exact'; allowed: hbm, quasi_static, time_domain"):
        solve_periodic(model, ex, "exact")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=r"initial_compression_m: given for method = 'quasi_static'"):
        solve_periodic(model, ex, SolverMethod.QUASI_STATIC, initial_compression_m=np.zeros((8, 3)))


@pytest.mark.parametrize(
    ("kind", "kwargs", "field"),
    [
        (QuasiStaticOptions, {"time_samples": 1}, "time_samples"),
        (QuasiStaticOptions, {"harmonics_for_indicator": -1}, "harmonics_for_indicator"),
        (TimeDomainOptions, {"formulation": "dense"}, "formulation"),
        (TimeDomainOptions, {"start": "given"}, "start"),
        (TimeDomainOptions, {"time_samples": 32, "steps_per_period": 100}, "steps_per_period"),
        (TimeDomainOptions, {"hht_alpha": 0.1}, "hht_alpha"),
        (TimeDomainOptions, {"max_periods": 1}, "max_periods"),
        (TimeDomainOptions, {"tolerance": 0.0}, "tolerance"),
        (TimeDomainOptions, {"orbit_tolerance": 1.0}, "orbit_tolerance"),
        (TimeDomainOptions, {"hbm": "default"}, "hbm"),
    ],
)
def test_the_references_options_name_the_field_the_value_and_what_is_allowed(kind, kwargs, field):
    with pytest.raises(ValueError, match="allowed") as err:
        kind(**kwargs)
    assert f"{field} = {kwargs[field]!r}" in str(err.value)


def test_the_references_options_are_keyword_only_frozen_and_hold_enum_members():
    with pytest.raises(TypeError):
        TimeDomainOptions(128)  # type: ignore[misc]
    o = TimeDomainOptions(formulation="condensed", start="quasi_static", time_samples=64)
    assert o.formulation is Formulation.CONDENSED and o.start is TimeDomainStart.QUASI_STATIC
    assert o.steps == 16 * 64 and TimeDomainOptions(time_samples=64, steps_per_period=128).steps == 128
    with pytest.raises(dataclasses.FrozenInstanceError):
        o.time_samples = 32  # type: ignore[misc]


def test_a_reference_given_a_number_for_its_options_names_what_it_takes(case):
    """A script written for an older signature (``solve_time_domain(model, ex, 128)``) gets a clear error, not an
    attribute error from deep inside."""
    model, ex = case
    with pytest.raises(TypeError, match=r"options = 128: allowed a TimeDomainOptions"):
        solve_time_domain(model, ex, 128)  # type: ignore[arg-type]
    with pytest.raises(TypeError, match=r"options = 64: allowed a QuasiStaticOptions"):
        solve_quasi_static(model, ex, 64)  # type: ignore[arg-type]

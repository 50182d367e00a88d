"""The cradle's uncoupled blocks from the node-by-node band, and its modes solved once per set of elements."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from scipy.linalg import eigh

from seafast.solvers.cradle_blocks import node_band, pattern_blocks
from seafast.solvers.cradle_dynamics import CradleDynamics, cradle_operators
from seafast.solvers.cradle_shooting import solve_cradle_shooting
from seafast.solvers.cradle_shooting_system import cradle_correction_system, cradle_modes
from test_cradle_dynamics import BEAM_SEA, SADDLES_M, small_dynamics, small_excitation


def element_sets(dynamics: CradleDynamics) -> list[np.ndarray]:
    """Every element, the damping set (pads and lashings) and the pads alone."""
    problem = dynamics.problem
    pads = np.zeros(len(problem.engagements), dtype=bool)
    pads[: 2 * len(problem.pad_pairs)] = True
    return [np.ones(pads.size, dtype=bool), dynamics.damping_set, pads]


def with_and_without_lashings() -> list[CradleDynamics]:
    dynamics = small_dynamics()
    return [dynamics, CradleDynamics(replace(dynamics.problem, lashings=()), 2.0, 2e-3, np.array(SADDLES_M))]


def assert_same_blocks(found, scanned) -> None:
    """The same DOFs and bandwidths per block; bands and dense blocks to round-off of the stiffness (1e-14 of its largest)."""
    assert len(found.banded) == len(scanned.banded)
    for (dofs, q), (dofs_s, q_s), dense, dense_s in zip(found.banded, scanned.banded, found.dense, scanned.dense, strict=True):
        np.testing.assert_array_equal(dofs, dofs_s)
        assert q.bandwidth == q_s.bandwidth
        for x, y in zip(
            (q.banded_stiffness, q.banded_mass, q.banded_damping, *dense),
            (q_s.banded_stiffness, q_s.banded_mass, q_s.banded_damping, *dense_s),
            strict=True,
        ):
            assert x.shape == y.shape
            np.testing.assert_allclose(x, y, rtol=0.0, atol=1e-14 * np.max(np.abs(y)))


@pytest.mark.parametrize("lashed", [True, False])
def test_the_blocks_from_the_node_band_are_the_dense_scans(lashed):
    """Every set of elements, with and without lashings: the blocks found from the entries near the diagonal (the dense
    matrices never scanned) are the connected components of the dense matrices' coupling pattern, banded and dense."""
    dynamics = with_and_without_lashings()[0 if lashed else 1]
    assert dynamics.node_band is not None
    for included in element_sets(dynamics):
        parts = dynamics.linear_parts(included)
        scanned = pattern_blocks(parts.bilateral_stiffness, dynamics.matrices[1], dynamics.matrices[2], dynamics.order)
        assert_same_blocks(parts.block_parts, scanned)
        lashings_in = lashed and bool(np.any(included[-len(dynamics.problem.lashings) or included.size :]))
        assert len(parts.blocks) == (2 if lashings_in else 3)  # the lashings couple the lateral and vertical motions


def test_an_entry_off_the_node_band_is_found_by_the_dense_scan():
    """A beam stiffness coupling the two ends' vertical motions (an entry far from the diagonal in the node order): no
    node band; the linear parts scan the dense matrices, and that entry joins the blocks it couples."""
    dynamics = with_and_without_lashings()[1]
    cargo = dynamics.problem.cargo
    K = cargo.stiffness.copy()
    first, last = cargo.node_dofs(0)[2], cargo.node_dofs(cargo.node_count - 1)[2]
    K[first, last] = K[last, first] = 1e-3 * K[first, first]
    coupled = replace(dynamics, problem=replace(dynamics.problem, cargo=replace(cargo, stiffness=K)))
    assert coupled.node_band is None
    parts = coupled.linear_parts()
    assert_same_blocks(
        parts.block_parts, pattern_blocks(parts.bilateral_stiffness, coupled.matrices[1], coupled.matrices[2], coupled.order)
    )
    vertical = next(q for dofs, q in parts.blocks if first in dofs)
    assert vertical.bandwidth == 2 * (cargo.node_count - 1)  # w_0 to w_last: (w, theta) of every node between
    assert node_band(dynamics.order, (K, cargo.mass), None, (2.0, 2e-3), dynamics.problem.engagement_matrix, 9) is None
    assert node_band(dynamics.order, (cargo.stiffness, cargo.mass), None, (2.0, 2e-3), dynamics.problem.engagement_matrix, 9) is not None


@pytest.mark.parametrize("lashed", [True, False])
def test_the_modes_are_the_dense_eigenpairs_and_their_damping_the_dense_product(lashed):
    """The modes per block are those of the dense ``(K_lin, M)`` (every frequency to 1e-8), mass-normalised; the
    modal damping of the lowest ones is ``Phi^T D Phi`` of the dense D; the damping's coupling to the deck is
    ``-D S`` with ``S = -K_lin^-1 K_co`` solved dense."""
    dynamics = with_and_without_lashings()[0 if lashed else 1]
    included = dynamics.damping_set
    parts = dynamics.linear_parts(included)
    modes = cradle_modes(dynamics, included)
    K, M, D = parts.bilateral_stiffness, dynamics.matrices[1], dynamics.matrices[2]
    dense = np.sqrt(eigh(K, M, eigvals_only=True))
    np.testing.assert_allclose(modes.natural_frequency_rad_s, dense, rtol=1e-8)  # the dense solve: 4e-10 on the lowest
    count = 12
    phi = modes.mode_shape(count)
    np.testing.assert_allclose(phi.T @ M @ phi, np.eye(count), atol=1e-10)
    np.testing.assert_allclose(modes.modal_damping(count), phi.T @ D @ phi, rtol=0.0, atol=1e-12 * np.max(np.abs(phi.T @ D @ phi)))
    K_co, D_co = parts.deck_coupling
    S = -np.linalg.solve(K, K_co)
    np.testing.assert_allclose(D_co, -D @ S, rtol=0.0, atol=1e-9 * np.max(np.abs(D @ S)))


def test_the_modes_are_solved_once_per_set_of_elements():
    """Two solves of the same dynamics and the correction systems of two cutoffs take the one eigensolve of each block
    (the same arrays), kept with the linear parts of that set; another set has its own."""
    dynamics = small_dynamics()
    excitation = small_excitation(dynamics.problem.cargo, BEAM_SEA)
    first = solve_cradle_shooting(dynamics, excitation)
    solved = [key for key, parts in dynamics.parts_cache.items() if "block_modes" in vars(parts)]
    assert solved
    kept = {key: dynamics.parts_cache[key].block_modes for key in solved}
    again = solve_cradle_shooting(dynamics, excitation)
    np.testing.assert_array_equal(again.element_force_N, first.element_force_N)
    for key, eigen in kept.items():
        assert all(a is b for a, b in zip(dynamics.parts_cache[key].block_modes, eigen, strict=True))
    included = np.frombuffer(solved[0], dtype=bool)
    modes = cradle_modes(dynamics, included)
    assert all(v is e[1] for (_, v), e in zip(modes.blocks, kept[solved[0]], strict=True))
    ops = cradle_operators(dynamics, excitation, 1, included)
    low, high = (cradle_correction_system(dynamics, ops, included, modes, w) for w in (50.0, 2000.0))
    assert low.mode_count < high.mode_count
    np.testing.assert_array_equal(high.mode_shape[:, : low.mode_count], low.mode_shape)
    other = element_sets(dynamics)[2]
    assert not np.array_equal(other, included)
    assert dynamics.linear_parts(other).block_modes is not dynamics.parts_cache[solved[0]].block_modes

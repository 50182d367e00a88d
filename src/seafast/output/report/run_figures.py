"""The interactive figures of a run, in report order, with their titles and captions.

The builders: :mod:`~seafast.output.report.vessel_figures` (hull girder, RAOs, deck motion),
:mod:`~seafast.output.report.cargo_figures` (saddles, deflection and moment, contact states) and
:mod:`~seafast.output.report.axial_figures` (stick-slip).
"""

from __future__ import annotations

import xarray as xr

from seafast.output.report.axial_figures import stick_slip_figure
from seafast.output.report.cargo_figures import contact_timeline_figure, deflection_moment_figure, saddle_time_history_figure
from seafast.output.report.common import ReportFigure
from seafast.output.report.vessel_figures import deck_motion_figure, hull_girder_figure, rao_figure

__all__ = ["run_figures"]


def run_figures(ds: xr.Dataset) -> list[ReportFigure]:
    """Every interactive figure of a run dataset, in report order (vessel first)."""
    out: list[ReportFigure] = []
    for fid, title, builder, caption in (
        (
            "fig-hull-girder",
            "Hull girder",
            hull_girder_figure,
            (
                "Still-water deflection and bending moment of the hull, with the wave's hog and sag extremes; the cargo span is shaded. "
                "After a two-way run, dashed: the hull under the coupled cargo."
            ),
        ),
        (
            "fig-raos",
            "Rigid-body RAOs",
            rao_figure,
            (
                "Amplitude and phase of the rigid-body RAOs (surge when the hydrodynamic data hold it, "
                "heave, pitch); the case's wave frequency is the dotted line."
            ),
        ),
        (
            "fig-deck-motion",
            "Deck deflection under the saddles",
            deck_motion_figure,
            "The prescribed deck displacement at each saddle over one period (solid) and in still water (dotted).",
        ),
        (
            "fig-saddle-histories",
            "Saddle force and gap over the period",
            saddle_time_history_figure,
            (
                "Total (static + wave) response. Negative compression is a gap: the nonlinear saddle lifts off and carries no force; "
                "the linear saddle would pull (negative force)."
            ),
        ),
        (
            "fig-deflection-moment",
            "Deflection and bending-moment lines",
            deflection_moment_figure,
            "Thick lines: still water; shaded bands: range over one wave period of the total response.",
        ),
        ("fig-contact-timeline", "Contact-state timeline", contact_timeline_figure, "Green: saddle in contact; orange: detached."),
        (
            "fig-stick-slip",
            "Axial stick-slip",
            stick_slip_figure,
            (
                "Axial displacement of the cargo relative to the deck, and the friction force against the friction available "
                "(sum of mu N over the saddles, from each model's own contact forces); where the friction reaches it, the cargo slides."
            ),
        ),
    ):
        try:
            fig = builder(ds)
        except KeyError:  # a dataset without the variables the figure needs
            fig = None
        if fig is not None:
            out.append(ReportFigure(fid, title, fig, caption))
    return out

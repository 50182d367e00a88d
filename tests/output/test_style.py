"""The shared figure conventions: a PNG laid out tightly and rendered once keeps the pixels of the plain route."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from PIL import Image

from seafast.output.style import legend_outside, save_png


def _figure() -> plt.Figure:
    fig, axes = plt.subplots(2, 2, figsize=(8, 5), sharex=True)
    x = np.linspace(0.0, 1.0, 50)
    for i, ax in enumerate(axes.ravel()):
        ax.plot(x, np.sin((i + 1) * np.pi * x), label=f"mode {i + 1}")
        ax.set_ylabel("u [mm]")
        legend_outside(ax)
    fig.suptitle("probe")
    return fig


def test_save_png_draws_the_same_pixels_as_tight_layout_and_savefig_and_closes_the_figure(tmp_path):
    plain = _figure()
    plain.tight_layout()
    plain.savefig(tmp_path / "plain.png", dpi=120)
    plt.close(plain)
    fig = _figure()
    assert save_png(fig, tmp_path / "fast.png", 120) == tmp_path / "fast.png"
    assert not plt.fignum_exists(fig.number)
    a, b = (np.asarray(Image.open(tmp_path / name)) for name in ("plain.png", "fast.png"))
    assert a.shape == b.shape == (600, 960, 4)
    assert np.array_equal(a, b)


def test_save_png_writes_other_formats_in_their_own(tmp_path):
    path = save_png(_figure(), tmp_path / "figure.pdf", 120)
    assert path.read_bytes().startswith(b"%PDF")

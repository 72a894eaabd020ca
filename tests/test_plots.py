"""The trajectory figure: which panels a symmetric, an asymmetric and a damped scene get, and
properties of the matplotlib objects a reader relies on (no offset notation, symlog energy
error with exact zeros drawn at 0, legends off the data, tick labels that do not overlap, the
energy balance of a damped top)."""
from __future__ import annotations

import io
import tomllib
from pathlib import Path

import numpy as np
import pytest

import derive
from derive.sim import plots
from derive.codegen.render import ROOT

SCENES = Path(__file__).resolve().parent.parent / "scenes"


def _scene(name: str, **simulate) -> dict:
    data = tomllib.loads((SCENES / f"{name}.toml").read_text())
    data["simulate"].update(simulate)
    return data


@pytest.fixture(scope="module")
def symmetric():
    return derive.simulate(_scene("free_symmetric", t_end=0.5, samples=201))


@pytest.fixture(scope="module")
def asymmetric():
    # The first flip of the racket's intermediate axis comes at t ≈ 2.8 s.
    return derive.simulate(_scene("tennis_racket", t_end=4.0, samples=401))


@pytest.fixture(scope="module")
def damped():
    return derive.simulate(_scene("damped_top", t_end=2.0, samples=2001))


_FIGURES: dict[int, object] = {}
_DRAWN: set[int] = set()


def _fig(res, drawn=True):
    """The figure of ``res``, built once per module (the tests only read it); drawn (tick
    labels and layout placed) once a test asks for it drawn."""
    if id(res) not in _FIGURES:
        _FIGURES[id(res)] = plots.figure(res)
    if drawn and id(res) not in _DRAWN:
        _FIGURES[id(res)].canvas.draw()
        _DRAWN.add(id(res))
    return _FIGURES[id(res)]


@pytest.fixture(scope="module", autouse=True)
def _close_figures():
    yield
    import matplotlib.pyplot as plt

    for fig in _FIGURES.values():
        plt.close(fig)
    _FIGURES.clear()
    _DRAWN.clear()


def _axes(fig, name):
    found = [ax for ax in fig.axes if ax.get_label() == name]
    assert len(found) == 1, [ax.get_label() for ax in fig.axes]
    return found[0]


def _close(fig):
    """Figures are shared between tests and closed at the end of the module."""


@pytest.fixture(scope="module")
def heavy():
    """A symmetric heavy top in the reduced formulation: p_α and p_γ are its parameters."""
    return derive.simulate(_scene("looping_top", t_end=0.5, samples=201))


def test_panels_of_each_kind_of_scene(symmetric, asymmetric, damped, heavy):
    # a free body (symmetric or not) is read in its own axes: the polhode, no view from above
    assert plots.panels(symmetric) == ["beta", "omega", "energy", "momenta", "sphere", "polhode"]
    assert plots.panels(asymmetric) == ["beta", "omega", "energy", "momenta", "sphere", "polhode"]
    assert plots.panels(damped) == ["beta", "omega", "energy", "balance", "top", "sphere"]
    assert plots.panels(heavy) == ["beta", "omega", "energy", "momenta", "top", "sphere"]
    for res in (symmetric, asymmetric, damped, heavy):
        fig = _fig(res, drawn=False)
        try:
            names = [ax.get_label() for ax in fig.axes if not ax.get_label().endswith(":twin")]
            assert names == plots.panels(res)
            for name in ("sphere", "polhode"):
                if name in names:
                    assert _axes(fig, name).name == "3d"
        finally:
            _close(fig)


def test_conserved_panel_shows_what_the_body_conserves():
    """p_γ is conserved only with every effect axisymmetric: not for the Kovalevskaya top (centre
    of mass off axis 3), whose panel shows its quartic integral instead."""
    kov = derive.simulate(ROOT / "scenes" / "kovalevskaya_top.toml", t_end=2.0, samples=201)
    names = [name for name, _ in plots._conserved(kov)]
    assert names == ["p_α", "kovalevskaya"]
    lagrange = derive.simulate(ROOT / "scenes" / "looping_top.toml", t_end=0.2, samples=21)
    assert [name for name, _ in plots._conserved(lagrange)] == ["p_α", "p_γ"]


def test_title_names_scene_formulation_method_and_tolerances(symmetric):
    fig = _fig(symmetric)
    try:
        title = fig.get_suptitle()
        s = symmetric.scene.simulate
        for part in (symmetric.scene.title, symmetric.formulation, symmetric.method,
                     f"rtol = {s.rtol:g}", f"atol = {s.atol:g}"):
            assert part in title
    finally:
        _close(fig)


def test_no_offset_text_and_no_overlapping_tick_labels(symmetric, asymmetric, damped):
    for res in (symmetric, asymmetric, damped):
        fig = _fig(res)
        try:
            renderer = fig.canvas.get_renderer()
            for ax in fig.axes:
                if ax.name == "3d":
                    continue
                for axis in (ax.xaxis, ax.yaxis):
                    assert axis.get_offset_text().get_text() == "", (ax.get_label(), axis.get_offset_text())
                    boxes = [lab.get_window_extent(renderer) for lab in axis.get_ticklabels()
                             if lab.get_visible() and lab.get_text()]
                    for i in range(len(boxes)):
                        for j in range(i + 1, len(boxes)):
                            assert not boxes[i].overlaps(boxes[j]), ax.get_label()
        finally:
            _close(fig)


def test_flat_beta_is_shown_as_deviation_not_in_offset_notation(symmetric):
    # β is constant in the free symmetric scene (L along z): its panel plots β − β(0).
    fig = _fig(symmetric)
    try:
        ax = _axes(fig, "beta")
        assert "β − β(0)" in ax.get_ylabel()
        assert f"{symmetric.beta[0]:.12g}" in ax.get_ylabel()
        labels = [t.get_text() for t in ax.get_yticklabels() if t.get_text()]
        assert len(set(labels)) == len(labels) > 2
    finally:
        _close(fig)


def test_energy_error_on_symlog_with_exact_zeros_at_zero(symmetric):
    fig = _fig(symmetric)
    try:
        ax = _axes(fig, "energy")
        assert ax.get_yscale() == "symlog"
        assert ax.get_ylim()[0] == 0.0
        y = np.concatenate([ln.get_ydata() for ln in ax.get_lines()])
        expected = np.abs(symmetric.energy - symmetric.energy[0]) / abs(symmetric.energy[0])
        np.testing.assert_array_equal(y, expected)  # zeros stay 0, nothing clipped to a floor
        assert "E is conserved" in ax.get_title()
    finally:
        _close(fig)


def test_asymmetric_body_shows_omega_and_the_flip(asymmetric):
    w2 = asymmetric.omega[:, 1]
    assert w2[0] > 0 and w2[-1] < 0  # the scene flips within t_end (else the test proves nothing)
    fig = _fig(asymmetric)
    try:
        ax = _axes(fig, "omega")
        lines = {ln.get_label(): ln for ln in ax.get_lines()}
        assert set(lines) == {"ω̃₁", "ω̃₂", "ω̃₃"}
        np.testing.assert_array_equal(lines["ω̃₂"].get_ydata(), w2)
        assert "symmetry" not in _axes(fig, "beta").get_title()
        # The body-frame direction of L starts near +ê₂ and ends near −ê₂.
        pol = _axes(fig, "polhode")
        path = next(ln for ln in pol.get_lines() if ln.get_label() == "L̃/|L̃|")
        ys = np.asarray(path.get_data_3d()[1])
        assert ys[0] > 0.9 and ys[-1] < -0.9
    finally:
        _close(fig)


def test_damped_scene_plots_energy_and_work_done_by_damping(damped):
    fig = _fig(damped)
    try:
        ax = _axes(fig, "energy")
        assert ax.get_yscale() == "linear"
        line = {prefix: next(ln for ln in ax.get_lines() if ln.get_label().startswith(prefix))
                for prefix in ("E(t)", "W(t)", "E + W")}
        E, total = (np.asarray(line[k].get_ydata()) for k in ("E(t)", "E + W"))
        E0 = damped.energy[0]
        assert E[0] - E[-1] > 0.05 * abs(E0)             # damping really takes energy out
        assert np.max(np.abs(total - E0)) < 1e-4 * abs(E0)  # and W accounts for it
        assert "trapezoid" in line["W(t)"].get_label()
        assert "error" not in ax.get_title()
        bal = _axes(fig, "balance")
        assert bal.get_yscale() == "symlog"
    finally:
        _close(fig)


def test_work_against_damping_is_the_trapezoid_rule():
    class R:
        t = np.linspace(0.0, 2.0, 5)
        omega = np.column_stack([t, 0 * t, 0 * t])  # |ω|² = t²

        class scene:
            class damping:
                c = 3.0

    W = plots.work_against_damping(R)
    h = 0.5
    expected = np.concatenate(([0.0], np.cumsum(h / 2 * 3.0 * (R.t[1:] ** 2 + R.t[:-1] ** 2))))
    np.testing.assert_allclose(W, expected, rtol=1e-15)
    assert abs(W[-1] - 3.0 * 8 / 3) < 3.0 * h ** 2 / 6 * 2 + 1e-12  # trapezoid error bound for t²


def test_legends_sit_outside_the_data(symmetric, damped):
    for res in (symmetric, damped):
        fig = _fig(res)
        try:
            renderer = fig.canvas.get_renderer()
            for ax in fig.axes:
                legend = ax.get_legend()
                if legend is None or ax.name == "3d":
                    continue
                panel = _axes(fig, ax.get_label().split(":")[0])
                assert not legend.get_window_extent(renderer).overlaps(panel.get_window_extent(renderer))
        finally:
            _close(fig)


@pytest.mark.parametrize("locs, expected", [
    ([190.0, 192.5, 195.0], ["190.0", "192.5", "195.0"]),
    ([0.0, 0.5, 1.0], ["0", "0.5", "1.0"]),
    ([-2e-13, 0.0, 2e-13, 4e-13], ["-2e-13", "0", "2e-13", "4e-13"]),
    ([0.64350110875, 0.6435011088, 0.64350110885], ["0.64350110875", "0.64350110880", "0.64350110885"]),
])
def test_plain_formatter_prints_every_tick_in_full(locs, expected):
    fmt = plots.plain_formatter()
    fmt.set_locs(locs)
    assert [fmt(v) for v in locs] == expected
    assert fmt.get_offset() == ""


def test_plot_result_writes_a_png(symmetric):
    buf = io.BytesIO()
    plots.plot_result(symmetric, buf)
    assert buf.getvalue().startswith(b"\x89PNG\r\n\x1a\n")


@pytest.mark.parametrize("amplitude", [1e-12, 1e-5])
def test_near_constant_series_print_in_full_without_offset(symmetric, amplitude):
    # β = 0.6435011088 + 1e-12 … printed by default as "1e-12+6.435011088e-1";
    # and a fast, nearly constant spin ω̃₃ = 500 + 1e-9 sin t on its own axis.
    import dataclasses

    t = symmetric.t
    omega = symmetric.omega.copy()
    omega[:, 2] = 500.0 + 1e-9 * np.sin(t)
    res = dataclasses.replace(symmetric, beta=0.6435011088 + amplitude * np.sin(40 * t), omega=omega)
    fig = plots.figure(res)
    try:
        fig.canvas.draw()
        assert {ax.get_label() for ax in fig.axes} >= {"beta", "omega", "omega:twin"}
        for ax in fig.axes:
            if ax.name == "3d":
                continue
            for axis in (ax.xaxis, ax.yaxis):
                assert axis.get_offset_text().get_text() == "", ax.get_label()
                labels = [lab.get_text() for lab in axis.get_ticklabels() if lab.get_text()]
                assert len(set(labels)) == len(labels), (ax.get_label(), labels)
    finally:
        import matplotlib.pyplot as plt

        plt.close(fig)


def test_deviation_from_zero_is_absolute_and_labelled_so():
    x = np.array([0.0, 1e-18, -3e-18, 0.0])
    dev, how, linthresh = plots._deviation(x)
    np.testing.assert_array_equal(dev, [0.0, 1e-18, 3e-18, 0.0])
    assert "absolute" in how and 0 < linthresh <= 3e-18
    dev, how, linthresh = plots._deviation(np.array([-2.0, -2.0, -1.0]))
    np.testing.assert_array_equal(dev, [0.0, 0.0, 0.5])
    assert how == "/ |{0}(0)|" and linthresh == 1e-16


def test_the_grid_has_no_empty_cell(symmetric, asymmetric, damped, heavy):
    for res in (symmetric, asymmetric, damped, heavy):
        fig = _fig(res, drawn=False)
        panels = [ax for ax in fig.axes if not ax.get_label().endswith(":twin")]
        rows, columns = panels[0].get_subplotspec().get_gridspec().get_geometry()
        assert rows * columns == len(panels), plots.panels(res)


def test_exactly_conserved_momenta_are_said_in_words_not_drawn(heavy):
    assert np.all(heavy.p_alpha == heavy.p_alpha[0]) and np.all(heavy.p_gamma == heavy.p_gamma[0])
    ax = _axes(_fig(heavy, drawn=False), "momenta")
    assert not ax.axison and ax.get_lines() == []
    words = " ".join(t.get_text() for t in ax.texts)
    assert "conserved exactly" in words and f"{heavy.t.size} samples" in words
    assert f"p_γ = {heavy.p_gamma[0]:.10g}" in words and f"p_α = {heavy.p_alpha[0]:.10g}" in words


def test_an_exact_quantity_beside_a_drifting_one_is_named_not_drawn(symmetric):
    ax = _axes(_fig(symmetric), "momenta")
    drawn = {ln.get_label() for ln in ax.get_lines()}
    assert ax.axison and drawn and not any("p_α" in label or "p_γ" in label for label in drawn)
    assert "exactly constant (not drawn): p_α = " in ax.get_title()


def test_an_exactly_conserved_energy_is_said_in_words(heavy):
    import dataclasses

    res = dataclasses.replace(heavy, energy=np.full_like(heavy.energy, heavy.energy[0]))
    fig = plots.figure(res)
    try:
        ax = _axes(fig, "energy")
        assert not ax.axison and ax.get_lines() == []
        assert "E is conserved exactly" in " ".join(t.get_text() for t in ax.texts)
    finally:
        import matplotlib.pyplot as plt

        plt.close(fig)


def test_a_free_body_shows_its_polhode_on_the_momentum_sphere(asymmetric):
    ax = _axes(_fig(asymmetric), "polhode")
    L = np.linalg.norm(asymmetric.L, axis=1)
    assert np.ptp(L) < 1e-8 * L[0]  # |L̃| is conserved: the path lies on one sphere
    assert "momentum sphere" in ax.get_title() and f"{np.median(L):.4g} kg m²/s" in ax.get_title()
    path = next(ln for ln in ax.get_lines() if ln.get_label() == "L̃/|L̃|")
    P = np.column_stack(path.get_data_3d())
    np.testing.assert_allclose(np.linalg.norm(P, axis=1), 1.0, rtol=1e-12)
    np.testing.assert_allclose(P * L[:, None], asymmetric.L, rtol=1e-12, atol=1e-15)


def test_the_sphere_sends_no_reader_to_a_view_that_is_not_there(symmetric):
    assert "top view" not in _axes(_fig(symmetric), "sphere").get_title()


def test_a_driven_run_names_its_energy_change_as_work_done():
    res = derive.simulate(str(ROOT / "docs" / "own-body" / "magnetic_top.toml"), t_end=0.5, samples=101)
    fig = plots.figure(res)
    try:
        ax = _axes(fig, "energy")
        assert "work done" in ax.get_title() and "error" not in ax.get_title()
        np.testing.assert_array_equal(ax.get_lines()[0].get_ydata(), res.energy - res.energy[0])
    finally:
        import matplotlib.pyplot as plt

        plt.close(fig)

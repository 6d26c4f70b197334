"""The figures outside the paper's registry (issue 18): docs/confined.png (jkrcyl.plotting.confined) and the cycle
plot (jkrcyl.plotting.cycle) -- checked on the figures' line objects and texts, against the library's own states
(which tests/test_twopatch.py, tests/test_cycle.py verify against independent references)."""
import math

import numpy as np
import pytest

pytest.importorskip("matplotlib")
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import to_rgb  # noqa: E402

import jkrcyl  # noqa: E402
from jkrcyl import cli, plotting  # noqa: E402
from jkrcyl import equilibria as eq  # noqa: E402
from jkrcyl.plotting import confined as pc  # noqa: E402

GB_PIN = 1 / (1 + (3 - 4 * 0.3))     # identical nu = 0.3 bodies: gb = 1/(kappa + 1), kappa = 3 - 4 nu (section 2)


def luminance(color):
    """Greyscale luminance (ITU-R BT.601 weights) of a matplotlib colour."""
    return float(np.dot(to_rgb(color), (0.299, 0.587, 0.114)))


def _texts(fig):
    out = [fig._suptitle.get_text()] if fig._suptitle else []
    out += [t.get_text() for t in fig.texts]
    for leg in fig.legends:
        out += [t.get_text() for t in leg.get_texts()]
    for ax in fig.axes:
        out += [ax.get_title(), ax.get_xlabel(), ax.get_ylabel()] + [t.get_text() for t in ax.texts]
        if ax.get_legend():
            out += [t.get_text() for t in ax.get_legend().get_texts()]
    return "\n".join(t for t in out if t)


# --- docs/confined.png ------------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def confined_08():
    fig = pc.confined_figure(Ms=(0.8,), theta=1.0)
    yield fig
    plt.close(fig)


def test_confined_series_told_apart_in_greyscale():
    """Moved from tests/test_twopatch.py: the families' colours are strictly ordered in luminance, each has its
    own marker; now also the full-contact family (it was a black dash-dot line, a line style of its own)."""
    lum = [luminance(matplotlib.colormaps["viridis"](x)) for _, x, _ in pc.SERIES]
    assert all(b > a + 0.15 for a, b in zip(lum, lum[1:]))
    assert len({m for _, _, m in pc.SERIES}) == len(pc.SERIES)
    assert len({w for _, w in pc.STABILITY}) == len(pc.STABILITY)      # the bands differ in width


def test_confined_line_styles_are_those_of_figs_2_to_12(confined_08):
    """Solid where h >= 0, dashed where h(pi) < 0 (the paper's and Figs. 2-12's convention), on the single patch
    at the bottom: every dashed point is a state of eq.curve with h(pi) < 0, every solid one has h(pi) >= 0
    (the one point where two pieces join excepted); stability is not a line style any more."""
    ax = confined_08.axes[0]
    bottom = to_rgb(matplotlib.colormaps["viridis"](0.0))
    states = {}
    for regime in eq.REGIMES:
        c = eq.curve(0.8, 1.0, regime, n=1500, gb=GB_PIN)
        for d, P, h in zip(c.delta_over_Delta, c.P_star, c.h_pi_over_Delta):
            states[(round(float(d), 9), round(float(P), 9))] = h
    seen = {"-": 0, "--": 0}
    for ln in ax.lines:
        if to_rgb(ln.get_color()) != bottom or ln.get_linewidth() > 2:          # other families, bands
            continue
        ls = ln.get_linestyle()
        assert ls in seen, ls
        hs = [states.get((round(float(d), 9), round(float(P), 9))) for d, P in zip(*ln.get_data())]
        hs = [h for h in hs[1:-1] if h is not None]
        assert hs and all((h >= 0) == (ls == "-") for h in hs)
        seen[ls] += 1
    assert seen["-"] and seen["--"]
    bands = [ln for ln in ax.lines if ln.get_linewidth() in {w for _, w in pc.STABILITY}]
    assert bands and all(ln.get_alpha() < 1 and ln.get_linestyle() == "-" for ln in bands)


def test_confined_figure_states_the_pin_and_explains_zip_full(confined_08):
    """The README pin's gb (identical nu = 0.3 bodies), not the incompressible default; the caption explains
    zip-full (and the other regimes drawn); the legend names the stability bands."""
    text = _texts(confined_08)
    assert f"(1/G_I)/\\beta^* = {GB_PIN:.4g}$ (identical bodies, $\\nu = 0.3$)" in text
    assert "zip-full:" in text and "full contact" in text and "bonded:" in text
    for label, _ in pc.STABILITY:
        assert label in text
    assert "$h(\\pi) \\geq 0$ (feasible)" in text and "$h(\\pi) < 0$ (overclosed)" in text


def test_confined_start_marked_at_M_08(confined_08):
    """M = 0.8 > the largest M with a zero-load contact (8.1) at vartheta = 1: the pin is bonded from first touch
    (ConfinedEvents regime 'bonded'); the start marker sits on full contact at P* = 0."""
    M_max = jkrcyl.zero_load_max_M(1.0)[0]
    assert M_max < 0.8 and not jkrcyl.zero_load_contact(0.8, 1.0)
    ev = eq.confined_events(0.8, 1.0, gb=GB_PIN)
    assert ev.regime == "bonded" and math.isinf(ev.start[0])
    ax = confined_08.axes[0]
    starts = [ln for ln in ax.lines if ln.get_marker() == "o" and to_rgb(ln.get_color()) == (0, 0, 0)]
    assert len(starts) == 1
    (d,), (P,) = starts[0].get_data()
    fc = eq.full_contact(1.0, P_star=0.0, gb=GB_PIN)
    assert P == 0.0 and d == pytest.approx(fc.delta_over_Delta, rel=1e-12)
    assert ax.get_title() == "$M = 0.8$: bonded"


@pytest.mark.parametrize("M, regime", [(0.3, "detachment"), (0.5, "zip-full")])
def test_confined_fold_and_jump_marked(M, regime):
    """The fold (x) is at the P_fold of confined_events and the jump's arrow stays at that load."""
    fig = pc.confined_figure(Ms=(M,), theta=1.0)
    try:
        ev = eq.confined_events(M, 1.0, gb=GB_PIN)
        assert ev.regime == regime
        ax = fig.axes[0]
        (fold,) = [ln for ln in ax.lines if ln.get_marker() == "x"]
        assert fold.get_ydata()[0] == pytest.approx(ev.P_fold, rel=1e-9)
        arrows = [a for a in ax.texts if getattr(a, "arrow_patch", None) is not None]
        assert len(arrows) == 1 and arrows[0].xy[1] == pytest.approx(ev.P_fold, rel=1e-9)
        (start,) = [ln for ln in ax.lines if ln.get_marker() == "o" and to_rgb(ln.get_color()) == (0, 0, 0)]
        assert start.get_ydata()[0] == pytest.approx(0.0, abs=1e-12)
        assert start.get_xdata()[0] == pytest.approx(
            float(eq.curve(M, 1.0, "super-critical" if ev.start[0] > eq.a_crit(1.0, gb=GB_PIN) else
                           "sub-critical", a=[ev.start[0]], gb=GB_PIN).delta_over_Delta[0]), rel=1e-9)
    finally:
        plt.close(fig)


def test_cli_confined_figure(tmp_path, capsys):
    """Moved from tests/test_twopatch.py: jkrcyl two-patch --figure writes the PNG (and says which gb)."""
    f = tmp_path / "confined.png"
    assert cli.main(["two-patch", "--figure", str(f), "--figure-M", "0.8"]) == 0
    assert f.stat().st_size > 10000 and f.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert f"gb={GB_PIN:.10g} (default: identical bodies" in capsys.readouterr().out
    assert cli.main(["two-patch", "--figure", str(f), "--M", "0.3"]) == 2
    assert cli.main(["two-patch", "--figure", str(f), "--figure-M", "x"]) == 2


# --- the cycle plot -----------------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def pin():
    """The README's pin: R = 10 mm, Delta = 1 um, w = 0.05 J/m^2, identical E = 2.6 GPa, nu = 0.3 bodies."""
    m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    return jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)


def test_cycle_plot_states_parameters_and_labels(pin):
    cy = pin.cycle(P_max=2000.0, P_min=-2000.0, control="load", n=400)
    fig = plotting.cycle_figure(cy, pin)
    try:
        ax = fig.axes[0]
        title = ax.get_title()
        for want in ("$E$ = 2.6 GPa", "$\\nu = 0.3$", "$E_I$ = 2.6 GPa", "$R$ = 10 mm", "$\\Delta$ = 1 \u00b5m",
                     "$w$ = 50 mJ/m", "load control", "up to 2 kN/m", "down to -2 kN/m",
                     f"dissipated {cy.dissipated:.4g} J/m"):
            assert want in title, (want, title)
        labels = [t.get_text() for t in ax.get_legend().get_texts()]
        assert {"contact at the bottom", "pin on the top", "direction of travel"} <= set(labels)
        kinds = [t.get_text() for t in ax.texts if t.get_text()]
        assert sorted(kinds) == sorted(j.kind for j in cy.jumps) == ["pull-off", "pull-off", "snap-in"]
        heads = [t for t in ax.texts if getattr(t, "arrow_patch", None) is not None
                 and t.arrow_patch.get_arrowstyle().__class__.__name__ == "CurveFilledB"]
        assert len(heads) >= 4          # up and down the bottom branch, down and up the top one
        for h in heads:                 # each head points along the path: from an earlier point to a later one
            (x0, y0), (x1, y1) = h.xyann, h.xy
            i = [k for k in range(1, len(cy.P)) if np.isclose(cy.delta_work[k] * 1e6, x1) and cy.P[k] == y1]
            assert i and any(np.isclose(cy.delta_work[k - 1] * 1e6, x0) and cy.P[k - 1] == y0 for k in i)
    finally:
        plt.close(fig)


def test_cycle_plot_grip_labels_the_free_pin(pin, tmp_path):
    cy = pin.cycle(delta_max=0.3e-6, delta_min=-2.3e-6, control="grip-work", n=300)
    fig = plotting.cycle_figure(cy, pin)
    try:
        ax = fig.axes[0]
        assert "free pin" in [t.get_text() for t in ax.get_legend().get_texts()]
        assert "$\\delta_{work}$ from 0 up to 300 nm, down to -2.3 \u00b5m" in ax.get_title()
    finally:
        plt.close(fig)
    assert plotting.plot_cycle(cy, tmp_path / "c.png", pin).stat().st_size > 10000


def test_si_prefixes():
    from jkrcyl.plotting.cycle import si
    assert [si(2.6e9, "Pa"), si(0.01, "m"), si(1e-6, "m"), si(-2000.0, "N/m"), si(0.05, "J")] == \
        ["2.6 GPa", "10 mm", "1 \u00b5m", "-2 kN/m", "50 mJ"]

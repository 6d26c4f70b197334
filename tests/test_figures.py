"""Figures 2-12 (jkrcyl.plotting): they build, say what they show, survive greyscale, and show what the
paper's text says they show (edge patches of Fig. 4, negative bounded pressure of Fig. 12a) or the erratum."""
import ast
import itertools
import math
import pathlib
import re

import numpy as np
import pytest

pytest.importorskip("matplotlib")
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import to_rgb  # noqa: E402

import jkrcyl  # noqa: E402
from jkrcyl import Contact, Materials, plotting  # noqa: E402
from jkrcyl import equilibria as eq  # noqa: E402

SMALL_N = {"fig10": 14}     # fig10's n is the number of M values (one adherence search each)
N = 40


@pytest.fixture(scope="module")
def built():
    out = {}
    for name, spec in plotting.FIGURES.items():
        out[name] = spec.build(SMALL_N.get(name, N))
    yield out
    for fig, _ in out.values():
        plt.close(fig)


def _texts(fig):
    """Every string a reader sees: suptitle, titles, axis labels, legend entries, annotations."""
    out = [fig._suptitle.get_text()] if fig._suptitle else []
    for ax in fig.axes:
        out += [ax.get_title(), ax.get_xlabel(), ax.get_ylabel()]
        out += [t.get_text() for t in ax.texts]
        leg = ax.get_legend()
        if leg:
            out += [t.get_text() for t in leg.get_texts()]
    return [t for t in out if t]


def luminance(color):
    """Relative luminance (ITU-R BT.709 weights) of a matplotlib colour: what greyscale printing keeps."""
    r, g, b = to_rgb(color)
    return 0.2126 * r + 0.7152 * g + 0.0722 * b


def test_registry_is_explicit_and_numbered():
    assert list(plotting.FIGURES) == [f"fig{k:02d}" for k in range(2, 13)]
    for name, spec in plotting.FIGURES.items():
        assert spec.name == name and callable(spec.builder) and spec.params


@pytest.mark.parametrize("name", list(plotting.FIGURES))
def test_figure_builds_with_math_labels_and_stated_parameters(built, name):
    fig, rows = built[name]
    assert rows, name
    texts = _texts(fig)
    for ax in fig.axes:
        for lab in (ax.get_xlabel(), ax.get_ylabel()):
            assert "$" in lab, (name, lab)
    joined = "\n".join(texts)
    # raw identifiers must not reach the reader (they are replaced by math text)
    for raw in ("eps_star", "delta/Delta", "vartheta =", "a_crit", "P_star"):
        assert re.search(r"(?<!\\)" + re.escape(raw), joined.replace("\\vartheta", "")) is None, (name, raw)
    spec = plotting.FIGURES[name]
    th = spec.params["theta"]
    for t in (th if isinstance(th, tuple) else (th,)):
        want = "\\vartheta = \\infty" if math.isinf(t) else f"\\vartheta = {t:g}"
        assert want in joined, (name, want)
    if "gb" in spec.params:
        assert f"(1/G_I)/\\beta^* = {spec.params['gb']:.4g}" in joined, name
    assert "\\alpha^*/\\beta^* = 0" in joined, name


EQUILIBRIUM_FIGURES = ["fig02", "fig03", "fig05", "fig06", "fig07", "fig09", "fig11"]


@pytest.mark.parametrize("name", EQUILIBRIUM_FIGURES)
def test_legend_shows_meaning_not_first_segment(built, name):
    """Series entries: marker + colour, no line (so no M looks dashed); then one entry per line style."""
    fig, _ = built[name]
    for ax in fig.axes:
        leg = ax.get_legend()
        if leg is None:
            continue
        handles = leg.legend_handles if hasattr(leg, "legend_handles") else leg.legendHandles
        labels = [t.get_text() for t in leg.get_texts()]
        series = [h for h, lab in zip(handles, labels) if lab.startswith(("$M", "$\\vartheta"))]
        assert series, (name, labels)
        for h in series:
            assert h.get_linestyle() in ("None", "none", "") and h.get_marker() not in (None, "None", "")
        styles = {lab: h.get_linestyle() for h, lab in zip(handles, labels)}
        assert styles["$h(\\pi) \\geq 0$ (feasible)"] == "-"
        assert styles["$h(\\pi) < 0$ (overclosed)"] == "--"


@pytest.mark.parametrize("k", [2, 3, 6, 9])
def test_series_styles_survive_greyscale(k):
    """Neighbouring series differ in marker and in luminance (>= 0.03 of the white-black range)."""
    st = plotting.styles(k)
    assert len({s.marker for s in st}) == k
    lum = [luminance(s.color) for s in st]
    assert all(b - a >= 0.03 for a, b in zip(lum, lum[1:])), lum


def test_pressure_components_differ_in_greyscale():
    styles = plotting.PRESSURE_STYLES
    assert len({s["ls"] for s in styles.values()}) == 3
    for a, b in itertools.combinations(styles, 2):
        assert abs(luminance(styles[a]["color"]) - luminance(styles[b]["color"])) > 0.1 or \
            styles[a]["ls"] != styles[b]["ls"]


def test_fig09_shows_confinement_contrast_and_half_plane_is_told_apart(built):
    fig, rows = built["fig09"]
    cylinders = {r[1] for r in rows if r[1].startswith("cylinder")}
    assert {"cylinder M = 0.4", "cylinder M = 0.6", "cylinder M = 1"} <= cylinders
    ax = fig.axes[0]
    assert {ln.get_linestyle() for ln in ax.lines} >= {"-", ":"}


def _independent_contact(M):
    """Identical nu = 0.3 bodies (vartheta = 1, alpha* = 0), R = 2, Delta = 1, w from the definition of M of
    section 6: M = sqrt(w A R)/(sqrt(2) Delta vartheta), A = beta*/(2 pi)."""
    mat = Materials.from_young(E=2.6, nu=0.3, E_I=2.6, nu_I=0.3)
    A = mat.beta / (2 * math.pi)
    w = 2 * (M * 1.0 * 1.0) ** 2 / (A * 2.0)
    with pytest.warns(jkrcyl.ValidityWarning):          # normalised figures: Delta/R = 1/2 only fixes the units
        return Contact(R=2.0, Delta=1.0, w=w, materials=mat)


def _panel_limits(fig, i):
    return fig.axes[i].get_ylim()


@pytest.mark.parametrize("panel", [0, 1])
def test_fig04_limits_show_the_edge_patches(built, panel):
    """Paper, section 8 (Fig. 4a, b): narrow tensile patches near the contact edges at P* = 4 and 2."""
    fig, _ = built["fig04"]
    M, P_target, _ = plotting.FIG04_CASES[panel]
    c = _independent_contact(M)
    assert math.isclose(c.theta, 1.0) and math.isclose(c.M, M)
    a = max(eq.solve_load(M, 1.0, P_target, "sub-critical", gb=plotting.FIGURE_GB[1.0]))   # P(a): gb-free
    eps = 2 * math.atan(a)
    phi = np.linspace(0.0, 0.999 * eps, 2000)
    nb, nu = c.pressure(a, phi, parts=True)
    total = (nb + nu) * c.R / abs(P_target * c.load_scale)
    tensile = phi[total < 0]
    assert tensile.size and tensile.min() > 0.9 * eps   # one narrow tensile patch next to the edge
    assert (total[phi < 0.9 * eps] > 0).all()
    lo, hi = _panel_limits(fig, panel)
    assert hi >= total.max()                 # compressive centre on the axes
    assert lo <= -0.1 * hi                   # and the patch takes a visible share (old +-8: 0 to 0.6 of 16)
    # the plotted total reaches the patch: its curve goes below zero within the axes
    total_line = [ln for ln in fig.axes[panel].lines if ln.get_label() == "total"][0]
    assert np.min(total_line.get_ydata()) < 0


def test_fig12a_limits_show_the_negative_bounded_part(built):
    """Paper, section 8.3: in Fig. 12a the bounded component violates the pressure inequality (< 0)."""
    fig, _ = built["fig12"]
    M, P_target, _ = plotting.FIG12_CASES[0]
    c = _independent_contact(M)
    a = min(eq.solve_load(M, 1.0, P_target, "super-critical", gb=plotting.FIGURE_GB[1.0]))
    eps = 2 * math.atan(a)
    phi = np.linspace(-0.999 * eps, 0.999 * eps, 801)
    nb, _ = c.pressure(a, phi, parts=True)
    bounded = nb * c.R / abs(P_target * c.load_scale)
    assert bounded.min() < 0
    lo, hi = _panel_limits(fig, 0)
    assert lo <= bounded.min() and hi >= bounded.max()
    assert lo > -8 or hi < 8     # not the old fixed +-8 window


def test_fig10_marks_the_crossing_erratum(built):
    """Crossings from the plotted data vs DERIVATION.md erratum 'Fig. 10' (M = 0.6113 at vartheta = 0.5,
    0.4459 at vartheta = 1, found there with the slope kernels to full precision); grid spacing 0.07 here."""
    fig, _ = built["fig10"]
    text = "\n".join(_texts(fig))
    assert "erratum" in text and "Fig. 10" in text
    found = sorted(float(m) for m in re.findall(r"cross at \$M \\approx ([0-9.]+)\$", text))
    assert len(found) == 2
    assert abs(found[0] - 0.4459) < 0.03 and abs(found[1] - 0.6113) < 0.03


def test_fig11_states_the_stability_erratum_and_marks_stable_states(built):
    fig, rows = built["fig11"]
    assert "erratum" in "\n".join(_texts(fig))
    flags = [r for r in rows if r[0] == "b" and r[1].endswith("flag")]
    assert any(float(r[5]) == 1.0 for r in flags)


def test_fig08_stability_rule_agrees_with_library_release_rate():
    """Fig. 8 marks neat-fit states stable where dQ*/da < 0 (rule of erratum 'Fig. 11b'); the neat fit is the
    Delta -> 0 (M -> inf) limit, where the library's own dG/da|_P > 0 must give the same states."""
    cv = eq.curve(1e3, 1.0, "super-critical", n=400, gb=plotting.FIGURE_GB[1.0])
    slope_rule = np.gradient(cv.P_star, cv.a) < 0
    interior = slice(5, -5)
    assert np.mean(slope_rule[interior] == cv.stable_load[interior]) > 0.98
    from jkrcyl import special
    neat = special.neat_fit_stable(cv.a, 1.0)          # Q* dQ*/da < 0, dQ*/da derived (derive/special.py)
    assert np.mean(neat[interior] == cv.stable_load[interior]) > 0.98
    assert np.mean(neat[interior] == slope_rule[interior]) > 0.98


def test_fig07_says_which_approach_it_draws(built):
    """The note is true of the plotted data: at M_R* = 0 the paper's delta falls while P_R* rises
    (issue 10 item 4: delta/Delta = +0.197 at P_R* = 0.3, -3.2 at P_R* = 8)."""
    fig, rows = built["fig07"]
    text = "\n".join(_texts(fig))
    assert "work conjugate" in text and "(5.8)" in text
    pts = [(float(r[3]), float(r[5])) for r in rows if r[0] == "c" and r[1] == "M = 0"]
    delta, P = np.array(pts).T
    rising = np.diff(P) > 0
    assert np.any(rising & (np.diff(delta) < 0))
    assert np.interp(8.0, P, delta) < -3.0 < 0.19 < np.interp(0.3, P, delta)


@pytest.mark.parametrize("path", sorted(pathlib.Path(plotting.__file__).parent.glob("*.py")), ids=lambda p: p.name)
def test_figures_module_computes_through_the_library(path):
    """No raw kernels: no module of jkrcyl.plotting imports anything from jkrcyl.generated."""
    src = path.read_text()
    for node in ast.walk(ast.parse(src)):
        if isinstance(node, ast.ImportFrom):
            assert "generated" not in (node.module or ""), node.module
            assert all("generated" not in a.name for a in node.names)
        if isinstance(node, ast.Import):
            assert all("generated" not in a.name for a in node.names)


def test_figure_contact_has_the_requested_alpha_and_vartheta():
    for ar in (0.0, 0.1, -0.2):
        c = plotting.figure_contact(0.3, 1.0, ar)
        m = c.materials
        # alpha*/beta* and vartheta from their definitions (section 2, 4), not from Materials' properties
        beta = (m.kappa + 1) / (2 * m.G) + (m.kappa_I + 1) / (2 * m.G_I)
        alpha = (m.kappa - 1) / (2 * m.G) - (m.kappa_I - 1) / (2 * m.G_I)
        assert math.isclose(alpha / beta, ar, abs_tol=1e-14)
        assert math.isclose(m.G * beta / (1 + m.kappa), 1.0, rel_tol=1e-14)
        assert math.isclose(c.M, 0.3, rel_tol=1e-12)


def test_fig02_with_alpha_star_nonzero():
    """alpha_ratio flows into equilibria.curve: stated on the figure, and the curves move."""
    fig, rows = plotting.FIGURES["fig02"].build(12, alpha_ratio=0.1)
    fig0, rows0 = plotting.FIGURES["fig02"].build(12)
    try:
        assert "\\alpha^*/\\beta^* = 0.1" in fig._suptitle.get_text()
        P = np.array([float(r[5]) for r in rows if r[0] == "a" and r[1] == "M = 0.5"])
        P0 = np.array([float(r[5]) for r in rows0 if r[0] == "a" and r[1] == "M = 0.5"])
        assert np.isfinite(P).all() and P.shape == P0.shape
        assert np.max(np.abs(P - P0)) > 1e-3
    finally:
        plt.close(fig)
        plt.close(fig0)


@pytest.mark.parametrize("name", ["fig04", "fig12"])
def test_pressure_legends_tell_components_apart(built, name):
    """bounded / unbounded / total: three line styles in every panel's legend (greyscale-proof)."""
    fig, _ = built[name]
    for ax in fig.axes:
        leg = ax.get_legend()
        handles = leg.legend_handles if hasattr(leg, "legend_handles") else leg.legendHandles
        labels = [t.get_text() for t in leg.get_texts()]
        assert labels == ["bounded", "unbounded", "total"]
        assert len({h.get_linestyle() for h in handles}) == 3


def test_fig07_draws_the_conjugate_approach(built):
    """Fig. 7 (c) also draws delta_work at M_R* = 0: it rises with the load everywhere (positive stiffness),
    and sits at delta + P/(8 pi G_I) = delta/Delta + (gb/2) P_R* from the paper's curve (DERIVATION.md)."""
    fig, rows = built["fig07"]
    work = np.array([(float(r[3]), float(r[5])) for r in rows if r[0] == "c_work"])
    paper = np.array([(float(r[3]), float(r[5])) for r in rows if r[0] == "c" and r[1] == "M = 0"])
    assert len(work) == len(paper) > 10
    assert np.all(np.diff(work[:, 0]) * np.diff(work[:, 1]) > 0)
    gb = plotting.FIGURE_GB[math.inf]
    np.testing.assert_allclose(work[:, 0], paper[:, 0] + gb / 2 * paper[:, 1], rtol=1e-9, atol=1e-12)


# --- Fig. 10: the cylinder's adherence force ends where detachment ends (issue 18) --------------------------------
def _P_star_printed(a, M, th):
    """P* = P beta*/(4 pi Delta vartheta) from the hand-typed (4.4) (reference/), Delta = beta* = 1, zeta* = 4 pi
    vartheta M (section 6), at mpmath precision."""
    import mpmath as mp
    from reference import paper as pp
    return pp.P_44(a, 1, 1, th, 4 * mp.pi * th * M, mp) / (4 * mp.pi * th)


def _detachment_limit_reference(th):
    """Where the lowest fixed-load P* minimum turns super-critical, from the printed (4.4) at 30 digits.

    vartheta = 1/2: the minimum runs into a_crit where the residue of P* at the pole vanishes, i.e. the numerator
    of (4.4) is 0 at a_crit: M = a_c^(3/2)/(a_c^2 - L(a_c) + 2 vartheta).  vartheta = 1: first a super-critical
    minimum is born (dP*/da = d2P*/da2 = 0 on a > a_crit) below the sub-critical one, which still exists there.
    Returns (M, P* of the sub-critical minimum at M, P* of the super-critical one)."""
    import mpmath as mp
    from reference import paper as pp
    with mp.workdps(30):
        ac = mp.findroot(lambda a: pp.a_crit_equation(a, th, mp), 0.9)
        dP = lambda a, M: mp.diff(lambda s: _P_star_printed(s, M, th), a)
        if th == 0.5:
            M = ac ** 1.5 / (ac ** 2 - pp.L(ac, mp) + 2 * th)
            return float(M), None, None
        d2P = lambda a, M: mp.diff(lambda s: _P_star_printed(s, M, th), a, 2)
        a_sn, M = mp.findroot(lambda a, M: (dP(a, M), d2P(a, M)), (1.13, 0.3915), tol=mp.mpf(10) ** -24)
        assert a_sn > ac
        a_sub = mp.findroot(lambda a: dP(a, M), (0.8, 0.88), solver="anderson", tol=mp.mpf(10) ** -24)
        assert a_sub < ac and d2P(a_sub, M) > 0
        return float(M), float(_P_star_printed(a_sub, M, th)), float(_P_star_printed(a_sn, M, th))


@pytest.mark.parametrize("th", [0.5, 1.0])
def test_fig10_ends_detachment_where_the_lowest_minimum_turns_super_critical(built, th):
    """The cylinder curve is a detachment force (thick) up to the limit and 'fold -> full contact' (thin) above
    it; the limit the figure marks equals the printed (4.4)'s, and the crossing with Barquins lies beyond it (the
    DERIVATION.md erratum 'Fig. 10': wherever the cylinder detaches, the half plane under-predicts)."""
    M_ref, P_sub, P_sup = _detachment_limit_reference(th)
    if th == 1.0:
        assert P_sup < P_sub          # the new super-critical minimum is the lower one at once
    fig, rows = built["fig10"]
    (cut,) = [float(r[3]) for r in rows if r[1] == f"detachment limit vartheta = {th:g}"]
    assert cut == pytest.approx(M_ref, abs=2e-6)
    detach = [float(r[3]) for r in rows if r[1] == f"cylinder detachment vartheta = {th:g}"]
    fold = [float(r[3]) for r in rows if r[1] == f"cylinder fold to full contact vartheta = {th:g}"]
    assert detach and fold and max(detach) <= cut <= min(fold)
    text = "\n".join(_texts(fig))
    assert f"detachment ends at $M = {cut:.4f}$" in text and "fold $\\to$ full contact" in text
    (crossing,) = [float(r[3]) for r in rows if r[1] == f"crossing vartheta = {th:g}"]
    assert crossing > cut + 0.03
    derivation = (pathlib.Path(__file__).resolve().parents[1] / "generated" / "DERIVATION.md").read_text()
    assert f"M < {M_ref:.4f} at vartheta = {th:g}" in derivation


def test_fig10_line_widths_tell_detachment_from_fold(built):
    """Thick = detachment, thin = fold into full contact: the legend says which, and the plotted lines use both."""
    fig, _ = built["fig10"]
    ax = fig.axes[0]
    leg = ax.get_legend()
    handles = leg.legend_handles if hasattr(leg, "legend_handles") else leg.legendHandles
    widths = {t.get_text(): h.get_linewidth() for h, t in zip(handles, leg.get_texts())}
    thick = widths["cylinder: detachment (sub-critical minimum)"]
    thin = next(w for k, w in widths.items() if k.startswith("cylinder: fold $\\to$ full contact"))
    assert thick > 1.5 * thin
    drawn = {ln.get_linewidth() for ln in ax.lines}
    assert {thick, thin} <= drawn


def test_fig11_states_the_pair_it_is_drawn_for(built):
    """Fig. 11 used the incompressible default gb = 0.5: now the figures' pair (identical nu = 0.3 bodies,
    gb = 1/(kappa + 1) = 1/2.8, kappa = 3 - 4 nu), said in the title."""
    fig, _ = built["fig11"]
    title = fig._suptitle.get_text()
    assert f"(1/G_I)/\\beta^* = {1 / 2.8:.4g}$ (identical bodies, $\\nu = 0.3$)" in title
    assert plotting.FIGURES["fig11"].params["gb"] == pytest.approx(1 / (1 + (3 - 4 * 0.3)), rel=1e-15)

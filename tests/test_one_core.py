"""One core, checked by behaviour: the routes beside the model core -- the atlas's numba classification, the fit's
superposed track, the figures' flags -- give the core's pull-offs and stability flags on rigid-cradle pairs,
where the shortcuts once diverged (the unit solutions of a compressible rubber roller pass a pole at the receding
contact; the incompressible roller has no a_crit at all, section 7.2).

The core's answer is Contact.pull_off (the walker on the single-patch solver's tables) and Contact.curve (the flags
of jkrcyl.model.stability); each other route must reproduce it, not a number typed here."""
import math

import numpy as np
import pytest

import jkrcyl
from jkrcyl import atlas

R, DELTA = 5e-3, 2e-5


def with_M(materials, M):
    """The contact of the pair at normalised adhesion M (M_R* for a rigid cradle): w from M ~ sqrt(w)."""
    probe = jkrcyl.Contact(R=R, Delta=DELTA, w=1.0, materials=materials)
    return jkrcyl.Contact(R=R, Delta=DELTA, w=(M / probe.M) ** 2, materials=materials)


RUBBER_IN_RIGID = jkrcyl.Materials.from_young(E=math.inf, nu=0.3, E_I=2e6, nu_I=0.5)       # vartheta = inf, alpha* = 0
# compressible (nu_I 0.3): a finite a_crit, the unit solutions pass a pole at the receding contact (alpha* != 0)
ROLLER_IN_RIGID = jkrcyl.Materials.from_young(E=math.inf, nu=0.3, E_I=2e6, nu_I=0.3)
PAIRS = {"incompressible": RUBBER_IN_RIGID, "compressible": ROLLER_IN_RIGID}


@pytest.mark.parametrize("M", [0.1, 0.3, 0.5, 0.7])
def test_atlas_pull_off_is_the_cores_on_a_rigid_cradle(M):
    """The atlas classifies (M_R*, vartheta = inf) with its own numba roots; its adherence force is the core's
    load-control pull-off (a sub-critical fold, detachment: class 'transfer')."""
    c = with_M(RUBBER_IN_RIGID, M)
    res = atlas.classify(np.array([c.M]), np.array([math.inf]))
    po = c.pull_off()
    assert po.P is not None and res["adherence"][0, 0]
    assert res["P_adh"][0, 0] * c.load_scale == pytest.approx(po.P, rel=1e-12)
    assert res["confined"][0, 0] == atlas.CONF_TRANSFER
    curve = c.curve(n=4000)
    # the atlas's sub-critical minimum is where the core's load-control flags turn stable (dP/da > 0 from there)
    a_min = res["sub_a"][0, 0]
    assert np.all(curve.stable_load[curve.a > a_min * 1.001]) and not np.any(curve.stable_load[curve.a < a_min / 1.001])


@pytest.mark.parametrize("pair", PAIRS)
@pytest.mark.parametrize("control", ["load", "grip", "grip-work"])
@pytest.mark.parametrize("M", [0.1, 0.5])
def test_fit_pull_off_is_the_cores_on_a_rigid_cradle(M, control, pair):
    """The fit's pull-off (its superposed track, walked with exact refinement: jkrcyl.fit.branch) is the core's
    Contact.pull_off on the compressible roller whose unit solutions pass a pole."""
    from jkrcyl.fit import branch

    c = with_M(PAIRS[pair], M)
    core = c.pull_off(control)
    fit = branch.pull_off(c, c.materials, control)
    assert (fit.P is None) == (core.P is None)
    # a fold is a stationary point: located to ~sqrt(noise) in a, so its P carries |dP/da| times that -- 1e-8 on
    # the closed forms (alpha* = 0), 1e-6 on the collocation (noise ~1e-11, jkrcyl.model.collocation)
    rel = 1e-8 if c.materials.alpha_ratio == 0 else 1e-6
    if core.P is not None:
        assert fit.P == pytest.approx(core.P, rel=rel)


@pytest.mark.parametrize("pair", PAIRS)
@pytest.mark.parametrize("regime", ["sub-critical", "super-critical"])
def test_figure_flags_are_the_cores_on_a_rigid_cradle(regime, pair):
    """The figures' branches (jkrcyl.equilibria.curve from normalised inputs, as plotting/paper_stability draws
    them) carry the core's stability flags and loads at the core's own contact parameters."""
    from jkrcyl import equilibria

    c = with_M(PAIRS[pair], 0.3)
    pb = c.problem
    try:
        core = c.curve(regime, n=400)
    except ValueError as e:                          # no such branch for this pair: the figures must say the same
        with pytest.raises(ValueError, match=str(e)[:20]):
            equilibria.curve(pb.M, pb.theta, regime, n=400, gb=pb.gb, alpha_ratio=pb.alpha_ratio)
        return
    fig = equilibria.curve(pb.M, pb.theta, regime, gb=pb.gb, alpha_ratio=pb.alpha_ratio, a=core.a)
    np.testing.assert_allclose(fig.P_star, core.P_star, rtol=1e-12, atol=1e-300)
    for flag in ("stable_load", "stable_grip", "stable_grip_work", "feasible"):
        np.testing.assert_array_equal(getattr(fig, flag), getattr(core, flag), err_msg=flag)

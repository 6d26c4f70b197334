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

"""Why a pull stops at an infeasible state (jkrcyl.analysis.reasons.gap_stop): JKR's pin stops where the top
closes (h(pi) = 0, its only gap condition); the cohesive pin can stop where the gap closes beside the contact with
the top wide open -- the message must say which (it once said 'the gap at phi = pi closes first' for both)."""
import math

import numpy as np

import jkrcyl
from cases import cohesive_contact
from jkrcyl.model.single_patch import solver
from jkrcyl.numerics import cohesive as co


def elastic_pin_in_rigid_hole():
    """An elastic pin (nu_I 0.45) in a rigid hole, range h0 = 1.47 Delta, lambda 2.47 (found by hypothesis,
    tests/test_cohesive_map_property.py)."""
    nu = 0.45028557727142104
    return cohesive_contact(math.inf, nu, math.inf, nu, 1.4690327046627536, 2.4731555735280266)


def test_cohesive_gap_stop_names_the_side():
    """Next to a table point where the cohesive pin's gap closes beside the contact (h(pi) > 2 Delta there), the
    stop says so -- not 'the gap at phi = pi closes first'."""
    from jkrcyl.analysis import branches, forward, reasons
    c = elastic_pin_in_rigid_hole()
    pb = c.problem
    t = branches.table(pb, "sub-critical")
    feasible, h = np.asarray(t.feasible), np.asarray(t.h_pi_over_Delta)
    k = next(k for k in range(1, feasible.size) if feasible[k] and not feasible[k - 1])    # the band's edge
    assert h[k - 1] > 2.0
    s, = forward.single_patch_states(pb, c.units, "sub-critical", [t.a[k]], "load")
    assert reasons.gap_stop(pb, s).startswith("no detachment on one patch")
    # independent evidence: the infeasible neighbour, solved alone at its contact, overlaps beside its edge
    law = solver(pb).law
    st = law.state(float(t.eps[k - 1]))
    grid = np.linspace(st.eps * 1.001, math.pi, 2000)
    gap = st.fields.gap(grid)
    assert not co.gap_check(st, 400).feasible and gap.min() < 0 and gap[-1] > 2.0


def test_jkr_gap_stop_names_the_top():
    """JKR's only gap condition is h(pi) >= 0: next to the first infeasible point of a branch's table (h(pi) < 0
    there, a larger contact of identical bodies at M 0.5) the stop is 'confined' (the top closes)."""
    from jkrcyl.analysis import branches, forward, reasons
    from jkrcyl.units import Units
    pb = jkrcyl.equilibria.problem(0.5, 1.0, 1 / 2.8)
    t = branches.table(pb, "sub-critical")
    k = int(np.argmax(~np.asarray(t.feasible)))                        # the first infeasible table point
    assert k > 0 and t.h_pi_over_Delta[k] < 0 <= t.h_pi_over_Delta[k - 1]
    s, = forward.single_patch_states(pb, Units.normalised(pb), "sub-critical", [t.a[k - 1]], "load")
    assert reasons.gap_stop(pb, s).startswith("confined: the gap at phi = pi closes first")


def test_walker_finds_the_fold_before_the_gap():
    """The same pin: the table's first infeasible point lies past the pull-off fold, which is feasible; the walk
    must find that fold inside the cell (it stopped at 'gap' one cell early before) and detach there.  Reference:
    the stand-alone continuation of jkrcyl.numerics.cohesive_pull_off (no table, no walker), its state's
    feasibility checked on 4000 angles of its own gap."""
    from jkrcyl.numerics import cohesive_pull_off as cpo
    c = elastic_pin_in_rigid_hole()
    pb = c.problem
    ref = cpo.pull_off_load(pb.m, pb.edge.s0, pb.theta, pb.gb, pb.alpha_ratio)
    assert ref.kind == "fold" and co.gap_check(ref.state, 4000).feasible
    got = c.pull_off("load")
    assert got.reason.startswith("detachment"), got.reason
    assert abs(c.units.normalise("load", got.P) * pb.scale / ref.p - 1) < 1e-8


def test_cohesive_gap_stop_where_the_top_comes_within_range():
    """The law's top adheres where h(pi) falls below its range h0 (not 0): a grip pull at vartheta 10, gb 0,
    lambda 3.875, M 0.0737 stops next to table points whose only failed gap condition is h(pi) < h0 at the top
    (h0 0.687, h(pi) 0.624 at the neighbour) -- 'confined' naming the range, not 'a second contact beside it, not
    modelled' (as it said before, judging the top by JKR's h(pi) > 0).  Independent evidence: the neighbour solved
    alone has its gap outside the zone smallest at phi = pi and below h0 there."""
    from jkrcyl.analysis import branches, path, reasons
    from jkrcyl.laws.dugdale import edge_of_strength
    from jkrcyl.model.problem import Problem
    from jkrcyl.numerics import cohesive_scales
    from jkrcyl.units import Units
    m_pb = Problem(0.0737, 10.0, 0.0)
    pb = Problem(0.0737, 10.0, 0.0, 0.0, edge_of_strength(cohesive_scales.zone_strength(3.875, m_pb.m)))
    start, event, s, _ = path.pull_path(pb, Units.normalised(pb), "grip")
    assert event == "gap"
    assert reasons.gap_stop(pb, s).startswith("confined: the top of the hole comes within the law's range first")
    t = branches.table(pb, "sub-critical")
    k = int(np.argmin(np.abs(np.asarray(t.a) - s.a))) - 1             # the infeasible neighbour (grip: smaller)
    assert not t.feasible[k]
    law = solver(pb).law
    st = law.state(float(t.eps[k]))
    grid = np.linspace(st.c * 1.001, math.pi, 4000)
    gap = st.fields.gap(grid)
    assert int(np.argmin(gap)) == grid.size - 1 and 0 < gap[-1] < law.h0

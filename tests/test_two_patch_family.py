"""The law -> two-patch family seam (jkrcyl.analysis.two_patch_family): a law names its family by a string the
analyses look up, so a name missing from the registry would only fail at first use.  Every law the library ships
that models two patches names a registered family, and a law of one's own naming an unknown one is told so by a
ValueError naming its parameter, not a KeyError."""
from dataclasses import dataclass

import pytest

import jkrcyl.laws
from jkrcyl.analysis.two_patch_family import REGISTRY, family
from jkrcyl.laws import DugdaleEdge
from jkrcyl.model.edge import Edge
from jkrcyl.model.problem import Problem


def _subclasses(cls):
    for sub in cls.__subclasses__():
        yield sub
        yield from _subclasses(sub)


def test_every_shipped_law_that_models_two_patches_names_a_registered_family():
    shipped = [c for c in _subclasses(Edge) if c.__module__.startswith(("jkrcyl.laws", "jkrcyl.model"))]
    assert {"GriffithEdge", "DugdaleEdge"} <= {c.__name__ for c in shipped}      # the walk reached the laws
    for law in shipped:
        if "two-patch-branches" in law.families:
            assert law.two_patch_family in REGISTRY, law


@dataclass(frozen=True)
class _Misnamed(DugdaleEdge):
    two_patch_family = "NoSuchFamily"


def test_a_law_naming_an_unknown_family_gets_a_value_error_naming_its_parameter():
    pb = Problem(0.3, 1.0, 1 / 2.8, 0.0, _Misnamed(s0=1.0))
    with pytest.raises(ValueError, match=r"^sigma0: .*'NoSuchFamily'.*'CohesiveTwoPatch'"):
        family(pb)
    assert jkrcyl.laws.GRIFFITH_EDGE.two_patch_family in REGISTRY


def test_a_jkr_branch_the_law_cannot_follow_is_said_not_dropped(monkeypatch):
    """A branch of JKR's whose law's states are not found (neither the scaffold's trace nor the law's own seeds
    find one) raises, naming sigma0: the law's two_patch() once returned () silently where JKR has a branch
    (M 0.67, lambda 20, before the end layers).  (Where the own seeds fold in lambda, () is physical:
    tests/test_cohesive_two_own.py.)"""
    from jkrcyl.analysis import cohesive_two_patch
    from jkrcyl.numerics import cohesive_two_branch, cohesive_two_own
    from jkrcyl.numerics.cohesive_scales import zone_strength
    pb = Problem(0.3, 1.0, 1 / 2.8, 0.0, DugdaleEdge(s0=zone_strength(50.0, 0.3)))
    monkeypatch.setattr(cohesive_two_branch, "trace",
                        lambda *a: cohesive_two_branch.Traced((), (), ("unresolved", "unresolved")))

    def no_seed(*a):
        raise cohesive_two_own.NoSeed("none")
    monkeypatch.setattr(cohesive_two_own, "branches", no_seed)
    with pytest.raises(ValueError, match=r"^sigma0: JKR's two-patch branch .* not followed under the law"):
        cohesive_two_patch._branches(family(pb), 12)

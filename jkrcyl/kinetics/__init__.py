"""Rate-dependent adhesion: a pin whose contact edges are cracks with kinetics (jkrcyl.laws.Kinetic), in time.

    c = jkrcyl.Contact(R=..., Delta=..., w=..., materials=m, kinetics=jkrcyl.CrackKinetics(v_star=1e-6, n=0.6))
    c.pull_off(rate=10.0)                          # load ramped down at 10 N/m/s: a RatePullOff
    c.pull_off("grip-work", rate=1e-6)             # a machine pulling the pin at 1 um/s
    c.respond(t, P=P_of_t)                         # any load (or approach) history: a History
    c.cycle(P_max=..., P_min=..., rate=...)        # the loop at a rate: a RateCycle
    jkrcyl.kinetics.rate_sweep(c, rates)           # pull-off against rate, the quasi-static value and asymptote

The single bottom patch is integrated in time (jkrcyl.kinetics.integrate) from an equilibrium at rest on the
fixed-arc states of the single-patch solver (jkrcyl.kinetics.arc) until an event ends it: separation (the contact
vanished) or top contact (the gap at phi = pi closed).  Any material pair (alpha* != 0 and rigid bodies
included: the collocation states, tabulated); the cohesive law with kinetics is not modelled.
"""
from .history import EVENTS, Event, History
from .results import RateCycle, RatePullOff

__all__ = ["EVENTS", "Event", "History", "RateCycle", "RatePullOff", "rate_sweep", "RateSweep",
           "high_rate_pull_off", "frozen_pull_off"]


def __getattr__(name):
    """The sweep (pull-off against rate) is imported on first use."""
    if name in ("rate_sweep", "RateSweep", "high_rate_pull_off", "frozen_pull_off"):
        from . import sweep
        return getattr(sweep, name)
    raise AttributeError(f"module 'jkrcyl.kinetics' has no attribute {name!r}")

"""What a derivation hands to the emitter: named sympy outputs, nothing about code."""
from dataclasses import dataclass, field

import sympy as sp

FORMS = ("into", "parallel")


@dataclass(frozen=True)
class Kernel:
    """A function to emit.

    name: the Python name of the scalar kernel.
    outputs: ``[(output_name, sympy_expr), ...]``; several outputs share common subexpressions and are
        returned as a namedtuple named :attr:`result` (one output: the bare float).
    doc: docstring (units, equation numbers).
    array_args: arguments that the loop forms take as 1-D arrays of equal length.
    forms: loop forms a caller uses: ``"into"`` (``<name>_into(out, ...)`` fills the preallocated
        arrays of ``out``, a :attr:`result` of 1-D arrays) and ``"parallel"`` (the same over
        ``numba.prange``, ``<name>_into_parallel``).  Kernels without forms are scalar only.
    """

    name: str
    outputs: tuple
    doc: str
    array_args: tuple = ("a",)
    extra_args: tuple = field(default=())
    forms: tuple = ()

    def __post_init__(self):
        if set(self.forms) - set(FORMS) or ("parallel" in self.forms and "into" not in self.forms):
            raise ValueError(f"{self.name}: forms {self.forms} (allowed: 'into', 'into' + 'parallel')")

    @property
    def result(self):
        """Name of the namedtuple of the outputs: the kernel name in CamelCase."""
        return "".join(part.capitalize() for part in self.name.split("_"))

    def output_names(self):
        return [name for name, _ in self.outputs]

    def args(self):
        """Argument symbols, sorted by name so that the emitted signature is stable."""
        free = set(self.extra_args)
        for _, expr in self.outputs:
            free |= sp.sympify(expr).free_symbols
        outputs = set(self.output_names())            # a later output may use an earlier one by name
        return sorted((s for s in free if s.name not in outputs), key=lambda sym: sym.name)

"""What a derivation hands to the emitter: named sympy outputs, nothing about code."""
from dataclasses import dataclass, field

import sympy as sp


@dataclass(frozen=True)
class Kernel:
    """A function to emit.

    name: the Python name of the scalar kernel (the array form gets ``_array``).
    outputs: ``[(output_name, sympy_expr), ...]``; several outputs share common subexpressions.
    doc: docstring (units, equation numbers).
    array_args: arguments that the array form takes as 1-D arrays of equal length.
    """

    name: str
    outputs: tuple
    doc: str
    array_args: tuple = ("a",)
    extra_args: tuple = field(default=())

    def args(self):
        """Argument symbols, sorted by name so that the emitted signature is stable."""
        free = set(self.extra_args)
        for _, expr in self.outputs:
            free |= sp.sympify(expr).free_symbols
        return sorted(free, key=lambda sym: sym.name)

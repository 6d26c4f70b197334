"""``python -m derive --out DIR``: run every derivation, write the kernels and DERIVATION.md into DIR."""
import argparse
import pathlib

from . import approach, derivatives, gap, load, pressure
from . import cohesive, confined, green, special, state, zero_load
from .emit import module_source, package_init
from .report import Report

# (module, docstring of the generated file); order = order of the report
MODULES = [
    (pressure, "Pressure solution (section 2): checks only, its kernel is emitted with the load."),
    (load, "Load-contact size (sections 3-4): (4.4), (4.5), (2.6), (3.4), (3.5), (5.4), P* of section 6."),
    (approach, "Approach delta (section 5): (5.3)-(5.8) with the sums (A.13)-(A.15)."),
    (gap, "Gap function h(phi) outside the contact (5.9) and h(pi) (5.10) in closed form."),
    (derivatives, "Slopes dP/da, d delta/da and dG/da at fixed load and fixed grip (sections 6, 8.2, 8.3)."),
    (special, "Special cases of section 7 as limits of the general result: (7.1)-(7.7), neat fit."),
    (zero_load, "Zero-load contact (8.1), its largest M, and the critical contact a_crit (section 4)."),
    (green, "Green's functions of (2.1) and (5.2) from Michell's solution, any alpha*; work-conjugate approach."),
    (confined, "Confined regime: the fold comes before h(pi) = 0; super-critical folds zip into full contact."),
    (state, "Fused equilibrium state: load_state, stress_intensity, approach and gap_pi in one kernel."),
    (cohesive, "Cohesive zone (Maugis-Dugdale, issue 19): zone displacement and load, scales, half-plane limit."),
]


def run(out):
    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    report = Report()
    emitted = []
    for module, doc in MODULES:
        name = module.__name__.rsplit(".", 1)[-1]
        kernels = module.derive(report)
        if kernels:
            (out / f"{name}.py").write_text(module_source(name, doc, kernels))
            emitted.append(name)
        print(f"derived {name}: {len(kernels)} kernels")
    (out / "__init__.py").write_text(package_init(emitted))
    (out / "DERIVATION.md").write_text(report.markdown() + "\n")
    print(f"wrote {out}/DERIVATION.md ({len(report.errata)} errata)")


def main():
    parser = argparse.ArgumentParser(prog="python -m derive", description=__doc__)
    parser.add_argument("--out", default="generated", help="output folder (default: generated)")
    run(parser.parse_args().out)


if __name__ == "__main__":
    main()

"""The explorer's Bokeh document: the input fields (a message beside each, the library's own ValueError), the load
against the work-conjugate approach (branches, first contact, pull-offs, the cycle, the chosen state), the pressure
and the gap around the hole, and a summary in words with units.  A change redraws; bad input leaves the last good
picture as it was.  Each element carries a CSS class (``jkr-<name>``) that tests/test_explore.py finds it by."""
from __future__ import annotations

import html
import logging
from dataclasses import fields

from bokeh.layouts import column, row
from bokeh.models import Checkbox, ColumnDataSource, Div, HoverTool, Range1d, Select, TextInput
from bokeh.plotting import figure

from . import view
from .model import CONTROLS, LAWS, Inputs, compute, field_of

log = logging.getLogger(__name__)
WIDTH = 230
ERROR_STYLE = {"color": "#b00020", "font-size": "12px", "max-width": f"{WIDTH - 10}px"}
TEXT_FIELDS = {"E": "E of the body with the hole [Pa]", "nu": "nu of the body with the hole",
               "E_I": "E_I of the pin [Pa]", "nu_I": "nu_I of the pin", "R": "hole radius R [m]",
               "Delta": "clearance Delta = R - R_D [m]", "w": "work of adhesion w [J/m^2]",
               "law_value": "sigma0 [Pa], lambda or v* [m/s] (the law's)",
               "kinetic_n": "crack kinetics: exponent n",
               "rate": "rate [N/m/s or m/s] (kinetics)",
               "cycle_max": "cycle: upper limit (N/m or m; empty: auto)",
               "cycle_min": "cycle: lower limit (N/m or m; empty: auto)",
               "state_P": "fields at P [N/m] (empty: first contact)"}
CHECKBOXES = {"rigid": "rigid body with the hole", "rigid_I": "rigid pin"}
ORDER = ("E", "rigid", "nu", "E_I", "rigid_I", "nu_I", "R", "Delta", "w", "law", "law_value", "kinetic_n", "rate",
         "control", "cycle_max", "cycle_min", "state_P")


def _widget(name: str, inputs: Inputs):
    """The input widget of one field, with the CSS class jkr-<name> (the tests find it by)."""
    css = [f"jkr-{name}"]
    if name in CHECKBOXES:
        return Checkbox(label=CHECKBOXES[name], active=getattr(inputs, name), css_classes=css)
    if name == "law":
        return Select(title="edge law", value=inputs.law, options=[(k, v[0]) for k, v in LAWS.items()],
                      width=WIDTH - 10, css_classes=css)
    if name == "control":
        return Select(title="control (stability shown, cycle driven, rate pull-off)", value=inputs.control,
                      options=list(CONTROLS), width=WIDTH - 10, css_classes=css)
    return TextInput(title=TEXT_FIELDS[name], value=str(getattr(inputs, name)), width=WIDTH - 10, css_classes=css)


class Explorer:
    """One browser tab: its widgets, sources and the last good picture."""

    def __init__(self, inputs: Inputs = Inputs()):
        self.errors = {}
        self.widgets = {name: _widget(name, inputs) for name in ORDER}
        for name in list(self.widgets) + ["general"]:
            self.errors[name] = Div(text="", styles=ERROR_STYLE, css_classes=[f"jkr-error-{name}"])
        self.sources = {k: ColumnDataSource(v, name=k) for k, v in view.empty().items()}
        self.summary = Div(text="", width=880, css_classes=["jkr-summary"])
        self.status = Div(text="", width=880, css_classes=["jkr-status"], name="status")
        self.redraws = 0
        self.curve_plot, self.pressure_plot, self.gap_plot = self._plots()
        for name, widget in self.widgets.items():
            widget.on_change("active" if isinstance(widget, Checkbox) else "value", self._changed)
        self.redraw()

    def _plots(self):
        curve = figure(width=880, height=430, title="load P against the work-conjugate approach delta_work",
                       y_axis_label="P [N/m]", css_classes=["jkr-curve"], tools="pan,wheel_zoom,box_zoom,reset,save",
                       x_range=Range1d(-1, 1), y_range=Range1d(-1, 1))
        s = self.sources
        curve.multi_line("xs", "ys", source=s["stable"], color="#1f4e9c", line_width=2.2, legend_label="stable")
        curve.multi_line("xs", "ys", source=s["unstable"], color="#1f4e9c", line_width=1.4, line_dash="dashed",
                         legend_label="unstable")
        curve.multi_line("xs", "ys", source=s["infeasible"], color="#9a9a9a", line_width=1.2, line_dash="dotted",
                         legend_label="overclosed (h(pi) < 0)")
        curve.line("x", "y", source=s["cycle"], color="#e08a00", line_width=1.4, alpha=0.8, legend_label="cycle path")
        curve.segment("x0", "y0", "x1", "y1", source=s["jumps"], color="#d62728", line_dash="dashed", line_width=1.5,
                      legend_label="jump")
        dots = curve.scatter("x", "y", source=s["points"], marker="marker", color="color", size=11,
                             legend_field="label")
        curve.add_tools(HoverTool(renderers=[dots], tooltips=[("", "@label"), ("P [N/m]", "@y{0.000}"),
                                                              ("delta_work", "@x @unit")]))
        curve.legend.label_text_font_size = "9pt"
        curve.add_layout(curve.legend[0], "right")
        pressure = figure(width=440, height=260, title="pressure N(phi) (compressive > 0)", x_axis_label="phi [deg]",
                          css_classes=["jkr-pressure"], tools="pan,wheel_zoom,reset,save", y_range=Range1d(-1, 1))
        pressure.line("phi", "y", source=s["pressure"], color="#2b7a3d", line_width=1.8)
        gap = figure(width=440, height=260, title="gap h(phi)", x_axis_label="phi [deg]", css_classes=["jkr-gap"],
                     tools="pan,wheel_zoom,reset,save")
        gap.line("phi", "y", source=s["gap"], color="#6a3d9a", line_width=1.8)
        return curve, pressure, gap

    def layout(self):
        def group(names):
            return column(*[x for name in names for x in (self.widgets[name], self.errors[name])], width=WIDTH)
        intro = Div(text="<b>jkrcyl explore</b>: a pin in a conforming hole (JKR adhesion). Change a field and "
                         "press Enter; SI units, loads per unit length of the cylinder.", width=2 * WIDTH)
        inputs = column(intro, self.errors["general"], row(group(ORDER[:9]), group(ORDER[9:])))
        return row(inputs, column(self.status, self.curve_plot, row(self.pressure_plot, self.gap_plot), self.summary))

    def inputs(self) -> Inputs:
        values = {f.name: (self.widgets[f.name].active if isinstance(self.widgets[f.name], Checkbox)
                           else self.widgets[f.name].value) for f in fields(Inputs)}
        return Inputs(**values)

    def _changed(self, attr, old, new):
        doc = self.status.document
        if doc is None:                   # not served (tests): the changes apply at once
            self.redraw()
            return
        doc.hold("combine")               # one message to the browser for the whole redraw, not one per property
        try:
            self.redraw()
        finally:
            doc.unhold()

    def _show_error(self, exc):
        message = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
        where = field_of(message) if field_of(message) in self.errors else "general"
        self.errors[where].text = f"<span class='jkr-message'>{html.escape(message)}</span>"
        self.status.text = ("<span class='jkr-not-redrawn'>not redrawn: the picture is the last good one "
                            f"(redraw {self.redraws})</span>")

    def redraw(self):
        for div in self.errors.values():
            div.text = ""
        inputs = self.inputs()
        self.widgets["E"].disabled, self.widgets["E_I"].disabled = inputs.rigid, inputs.rigid_I
        self.widgets["law_value"].disabled = LAWS[inputs.law][1] is None
        self.widgets["kinetic_n"].disabled = inputs.law != "kinetic"
        try:
            picture = compute(inputs)
        except (ValueError, ArithmeticError) as exc:
            self._show_error(exc)
            return
        except Exception as exc:          # a library bug: say so in one line, log the traceback on the server
            log.exception("jkrcyl explore: the computation failed")
            self._show_error(RuntimeError(f"internal error ({type(exc).__name__}: {exc}); see the server log"))
            return
        self._draw(picture)

    def _draw(self, picture):
        data = view.picture_data(picture)
        for key, source in self.sources.items():
            source.data = data[key]
        x0, x1, y0, y1 = data["curve_range"]
        self.curve_plot.x_range.update(start=x0, end=x1)
        self.curve_plot.y_range.update(start=y0, end=y1)
        x_unit, p_unit, g_unit = data["units"]
        self.curve_plot.xaxis.axis_label = f"delta_work [{x_unit}]"
        self.pressure_plot.yaxis.axis_label = f"N [{p_unit}]"
        self.gap_plot.yaxis.axis_label = f"h [{g_unit}]"
        lo, hi = view.pressure_range(data["pressure"]["y"])
        self.pressure_plot.y_range.update(start=lo, end=hi)
        self.redraws += 1
        self.summary.text = view.summary_html(picture)
        self.status.text = (f"redraw <span class='jkr-redraws'>{self.redraws}</span> in "
                            f"{picture.timings['total']:.3g} s")


def make_document(doc):
    """The Bokeh application: one :class:`Explorer` per browser tab."""
    explorer = Explorer()
    doc.title = "jkrcyl explore"
    doc.add_root(explorer.layout())

"""The Taylor method's C (``<prefix>_taylor.{h,c}``), rendered from a model's jet as data.

:func:`derive.codegen.jet.decompose` gives the right-hand side as elementary steps (rule,
operands, output node); ``templates/c/taylor.c.j2`` renders the scalar jet from them and
the same template the lanes jet (several trajectories at once), each step
by the macros of its rule's file ``templates/c/taylor_rules/<rule>.j2``: ``step`` (the scalar
statement computing coefficient n), ``lanes_step`` (the lanes' call of a sum's vector helper; an
elementwise rule's ``step`` printed per lane instead), ``scalar`` and ``lanes`` (the helpers
``tc_<rule>``, ``tcl_<rule>``) and, for a sum the lanes run beside others, ``fused_*``. A
:class:`CView` says how a statement names a coefficient and prints a constant: the scalar jet's
``u[k][n]``, or the lanes' ``u[k][n][lane_]`` with every parameter and named constant indexed
by the lane. Adding a function adds its rule's file and its row of
:data:`derive.codegen.jet.RULE_TABLE` (and, beyond one series operand, its decomposition in
:data:`derive.codegen.jet.RULES`).
"""
from __future__ import annotations

import sympy as sp

from derive.codegen import jet
from derive.codegen.jet import Const, Decomposition, controlled_states, decompose, rule_of
from derive.codegen.kernelspec import Block, CPrinter, KernelSpec, c_expr
from derive.codegen.render import TAYLOR_INCS, environment, render
from derive.methods.taylor import METHODS, TaylorMethod

#: The index of the lane loops in the lanes jet's C (templates/c/taylor.c.j2): a name
#: no model symbol takes (they never end in an underscore).
LANE = "lane_"
FUSED_MAX = 4  # the sums of one fused loop (each a vector accumulator, its operands' loads)


class _LanePrinter(CPrinter):
    """:class:`CPrinter` with the symbols named in ``laned`` indexed by the lane."""

    def __init__(self, laned):
        super().__init__()
        self.laned = frozenset(laned)

    def _print_Symbol(self, expr):
        name = str(expr)
        return f"{name}[{LANE}]" if name in self.laned else name


class CView:
    """How a jet statement names coefficient ``n`` of node ``k`` and prints a constant: the
    scalar jet's ``u[k][n]`` and :func:`c_expr`, or (``laned``: the names a lane has its own
    value of) the lanes jet's ``u[k][n][lane_]`` and those names indexed by the lane."""

    def __init__(self, laned=None):
        self.lane = laned is not None
        self._print = _LanePrinter(laned).doprint if self.lane else c_expr

    def u(self, k: int, n: str = "n") -> str:
        return f"u[{k}][{n}][{LANE}]" if self.lane else f"u[{k}][{n}]"

    def expr(self, e) -> str:
        return self._print(e)

    def const(self, c: Const) -> str:
        text = self._print(c.expr)
        return text if c.named else f"({text})"

    def coef(self, op, n: str = "n") -> str:
        """Coefficient n of an operand: a series' entry, a constant's value at n = 0 only."""
        return self.u(op, n) if isinstance(op, int) else f"({n} == 0 ? {self.const(op)} : 0.0)"


SCALAR = CView()


def coef(op, n: str = "n") -> str:
    """Coefficient n of an operand in the scalar jet's C (:class:`CView`)."""
    return SCALAR.coef(op, n)


def rule_templates() -> dict:
    """{rule: its file's macros} (``templates/c/taylor_rules/<rule>.j2``), one per row of
    :data:`derive.codegen.jet.RULE_TABLE`."""
    env = environment()
    return {r.name: env.get_template(f"c/taylor_rules/{r.name}.j2").module for r in jet.RULE_TABLE}


def render_taylor(model, spec: KernelSpec | None = None) -> dict[str, str]:
    """``<name>_taylor.h`` and ``<name>_taylor.c`` for ``model`` (``spec``: its kernel spec, if
    the caller has it): the coefficient recurrences and the Taylor solvers
    (:mod:`derive.methods.taylor`). The C includes ``<name>_solvers.h`` (``derive_stats``, the
    ``DERIVE_*`` codes, the model header). Raises :class:`NoTaylorRule` for a function without
    a rule."""
    spec = spec if spec is not None else KernelSpec.of(model)
    d = decompose(spec, outputs=True)
    methods_ctx = [_method_context(m) for m in METHODS.values()]
    rhs_steps = [s for s in d.steps if not s.obs]
    obs_steps = [s for s in d.steps if s.obs]
    jet_scope = _scope(rhs_steps, d.guards + [op.expr for op in d.outputs if isinstance(op, Const)], d)
    obs_scope = _scope(obs_steps + d.last, [], d)
    ny = d.ny
    ctx = {
        "prefix": model.name, "ny": ny, "d": d, "v": SCALAR, "rules": rule_templates(),
        "methods": methods_ctx, "max_order": max(m["max_order"] for m in methods_ctx),
        "controlled": controlled_states(model), "states": model.state_names,
        "rhs_nodes": rhs_steps, "obs_nodes": obs_steps,
        "guards": [f"({c_expr(g)})" for g in d.guards],
        "jet_scope": _printed(jet_scope), "obs_scope": _printed(obs_scope),
        # the columns of the coefficient table w past the states: (column, operand)
        "columns": [(ny + c, op) for c, op in enumerate(d.columns)],
        # the states whose sin and cos the samples compute (each pair at 2 c, 2 c + 1 past them)
        "trig": d.trig,
        "nobs": len(d.pointwise),
        "has_angles": spec.observable_names[:3] == ("alpha", "beta", "gamma"),
        "pointwise": _pointwise(model, d),
    }
    ctx["lanes"] = _lanes(d, rhs_steps, jet_scope) if ctx["pointwise"] else None
    # the nodes the dense output reads of the jet's (the states, and what the outputs' series are
    # made of, less the nodes made for them): what the lanes' full-grid driver copies out of a
    # lane before it (DERIVE_T_EACH_DENSE, templates/c/taylor.inc.j2)
    read = set(range(ny)) | {op for op in d.columns if isinstance(op, int)}
    for s in obs_steps + d.last:
        read |= s.reads | set(s.outs)
    ctx["dense_nodes"] = sorted(read - {k for s in obs_steps for k in s.outs})
    # the doubles a lane keeps of its steps (at least one step's at the highest order)
    ctx["LBUF"] = max(2048, 6 + len(ctx["dense_nodes"]) * (ctx["max_order"] + 1))
    return {f"{model.name}_taylor.h": render("c/taylor.h.j2", **ctx),
            f"{model.name}_taylor.c": render("c/taylor.c.j2", **ctx), **taylor_shared()}


def taylor_shared() -> dict[str, str]:
    """``derive_taylor_base.inc`` (the sizes and vector types a model's jet and output map are
    written against) and ``derive_taylor.inc`` (the Taylor methods' drivers: step-size control,
    dense output, the output blocks, the solve, simulate, final-only and lanes drivers), one text
    each for every model; a model's ``<model>_taylor.c`` defines its sizes as macros, includes
    the first, defines its jet, and includes the second."""
    base, drivers = TAYLOR_INCS
    return {base: render("c/taylor_base.inc.j2", rules=rule_templates(),
                         names=[r.name for r in jet.RULE_TABLE], lane=LANE),
            drivers: render("c/taylor.inc.j2", methods=[_method_context(m) for m in METHODS.values()])}


def _scope(steps: list, exprs: list, d: Decomposition) -> tuple[list, list]:
    """The parameters and named constants that ``steps`` and the SymPy ``exprs`` read
    (constants through the constants they are made of): ([(index, name)], [(name, SymPy)]),
    in order."""
    names = set()
    for e in list(exprs) + [x for s in steps for x in s.exprs]:
        names |= {str(s) for s in sp.sympify(e).free_symbols}
    consts = []
    for name, e in reversed(d.constants):
        if str(name) in names:
            consts.append((str(name), e))
            names |= {str(s) for s in e.free_symbols}
    return [(i, nm) for i, nm in d.params if nm in names], consts[::-1]


def _printed(scope: tuple, view: CView = SCALAR) -> tuple[list, list]:
    """A :func:`_scope` with its constants printed as C through ``view``."""
    return scope[0], [(nm, view.expr(e)) for nm, e in scope[1]]


def _lanes(d: Decomposition, rhs_steps: list, scope: tuple) -> dict | None:
    """The jet of the lanes driver (several trajectories at once, :mod:`derive.sim.batch`), from
    the same steps as the scalar jet: ``nodes``, per step ("loop", step) for an elementwise rule
    (its scalar statement, every series entry and every parameter and constant indexed by the
    lane, in a loop over the lanes), ("call", step) for a sum (its rule's vector helper
    ``tcl_<rule>``), or ("fused", [step]) (:func:`_fused`); ``view``: the lanes'
    :class:`CView`. None when a helper's argument would need a lane (a parameter in a power's
    exponent): such a model has no lanes driver."""
    for s in rhs_steps:
        if not rule_of(s.rule).elementwise and any(
                isinstance(a, Const) and sp.sympify(a.expr).free_symbols for a in s.args):
            return None
    laned = {nm for _, nm in scope[0]} | {nm for nm, _ in scope[1]} | {str(s) for s in d.order0}
    view = CView(laned)
    return {"nodes": _fused(d, rhs_steps), "params": scope[0], "view": view,
            "consts": _printed(scope, view)[1],
            "guards": [f"({view.expr(g)})" for g in d.guards],
            "outputs": [view.coef(out) for out in d.outputs], "index": LANE}


def _fused(d: Decomposition, rhs_steps: list) -> list:
    """The lanes' jet items, one per rhs step, in an order that puts the Cauchy sums that do
    not depend on one another side by side: each step's stage is the number of sums
    (non-elementwise rules) on its longest path of operands within a pass; a stage's
    elementwise loops come first, then its sums, those of the :attr:`Rule.fusable` rules of one
    stage as one loop over j with an accumulator each, ("fused", [step]) (up to FUSED_MAX). A
    sum alone waits on its own chain of additions (latency-bound over the lanes' vector); two or
    three in one loop fill the units. Each sum keeps its own order of terms: the same numbers."""
    writer = d.writer
    made = {s.index for s in rhs_steps}
    stage, sums = {}, {}
    for s in rhs_steps:
        deps = ({writer[k].index for k in s.reads if k in writer} & made) - {s.index}
        stage[s.index] = max((stage[k] + sums[k] for k in deps), default=0)
        sums[s.index] = not rule_of(s.rule).elementwise
    out = []
    for st in sorted(set(stage.values())):
        here = [s for s in rhs_steps if stage[s.index] == st]
        out += [("loop", s) for s in here if rule_of(s.rule).elementwise]
        calls = [s for s in here if not rule_of(s.rule).elementwise]
        out += [("call", s) for s in calls if not rule_of(s.rule).fusable]
        group = [s for s in calls if rule_of(s.rule).fusable]
        for k in range(0, len(group), FUSED_MAX):
            chunk = group[k:k + FUSED_MAX]
            out.append(("call", chunk[0]) if len(chunk) == 1 else ("fused", chunk))
    return out


class _BlockPrinter(CPrinter):
    """C for the output map over a block of samples (``<prefix>outputs_block``), a loop that gcc
    can vectorise: the same text as :class:`CPrinter` prints, but

    * a Piecewise term is a select on the bits of named values, ``derive_select(pc, pv, pd)``
      (``derive_libm.h``), each
      branch's value a statement of its own, computed unconditionally, and each condition a
      mask (all ones where it holds): gcc does not if-convert ``cond ? 0 : x*y`` under the
      default ``-ftrapping-math`` (it will not speculate a product or a quotient, and sinks a
      value computed ahead into the branch that uses it), but and/or on the bits of two
      computed values is straight-line code. The chosen value is the branch's own expression,
      so the bits are those of the conditional; where the branch not taken is singular (0/0 at
      a guarded pole) its NaN is computed and dropped;
    * a statement made of ``fixed`` symbols alone (the parameters and temporaries of theirs:
      the guards' conditions) goes to ``once``, computed before the loop, the others to
      ``each``, in the loop: (type, name, C text), in the order printed (a statement's operands
      before it);
    * ``acos`` is ``derive_acos_poly`` (``derive_libm.h``: arithmetic alone, fdlibm's; libm's
      does not vectorise).

    The names end in an underscore, which no model symbol does."""

    def __init__(self, fixed):
        super().__init__()
        self.fixed = set(fixed)
        self.uses_acos = False
        self.once: list = []
        self.each: list = []
        self.count = 0

    def statement(self, kind: str, e, text: str) -> str:
        name = f"pw{self.count}_"
        self.count += 1
        (self.once if e.free_symbols <= self.fixed else self.each).append((kind, name, text))
        return name

    def _print_Piecewise(self, expr):
        *pairs, (default, _) = expr.args
        out = self.statement("double", default, self._print(default))
        for value, cond in reversed(pairs):
            c = self.statement("uint64_t", cond, f"0 - (uint64_t)({self._print(cond)})")
            v = self.statement("double", value, self._print(value))
            out = f"derive_select({c}, {v}, {out})"
        return out

    def _print_acos(self, expr):
        self.uses_acos = True
        return f"derive_acos_poly({self._print(expr.args[0])})"


def _pointwise(model, d: Decomposition) -> dict | None:
    """The outputs at a sample from the states and the columns there, printed as a C function
    body: their own CSE, the states, columns and parameters they read; ``block``: the same map
    over a block of samples (:class:`_BlockPrinter`)."""
    if not d.pointwise:
        return None
    block = Block.of([e for _, e in d.pointwise], "x")
    uses_t = block.uses_time()
    pr = _BlockPrinter(block.fixed(model.params))
    for name, e in block.temps:
        text = pr.doprint(e)
        (pr.once if name in pr.fixed else pr.each).append(("double", str(name), text))
    outs = [(j, pr.doprint(e)) for (j, _), e in zip(d.pointwise, block.outputs)]
    series_columns = [(len(model.states) + c, s) for c, s in block.uses(d.column_symbols)]
    return {"states": block.uses(model.states), "params": block.uses(model.params),
            "columns": series_columns
            + [(len(model.states) + len(d.columns) + c, s) for c, s in block.uses(d.trig_symbols)],
            # the map computing the trig pairs itself (<prefix>outputs_block_trig): the columns
            # from the series, then per pair (state index, sin name, cos name)
            "series_columns": series_columns,
            "trig_pairs": [(k, str(d.trig_symbols[2 * c]), str(d.trig_symbols[2 * c + 1]))
                           for c, k in enumerate(d.trig)],
            "uses_t": uses_t, "once": pr.once, "each": pr.each, "outputs": outs,
            "acos": pr.uses_acos}


def _method_context(m: TaylorMethod) -> dict:
    return {"name": m.name, "summary": m.summary, "min_order": m.min_order,
            "max_order": m.max_order, "safety": m.safety,
            "decl": ", ".join(f"{ty} {nm}" for ty, nm in m.params),
            "args": ", ".join(nm for _, nm in m.params)}

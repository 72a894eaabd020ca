"""Taylor recurrences from a model's expression graph, rendered into C (``<prefix>_taylor.{h,c}``).

The right-hand side after CSE (the kernel spec's ``rhs`` block: the domain guards, then f) is
decomposed once into elementary operations u_k = φ(u_i, u_j, constants), as heyoka decomposes a
system. Each node is either a *constant* (numbers, parameters and whatever is made of them
alone: printed as a C expression, evaluated once per expansion) or a *series*, an array of
Taylor coefficients u_k,0 … u_k,p. For a series node the n-th coefficient follows from the
operands' coefficients 0…n (and its own earlier ones) by the rule of its elementary function;
the states close the loop, y_{i,n+1} = f_i,n / (n + 1). ``templates/c/taylor.c.j2`` runs
n = 0 … p−1 over the nodes in order.

Rules (:data:`RULES`, one entry per elementary function: adding a function adds an entry and,
where it needs one, a C helper ``tc_<name>`` in the template; nothing else changes), with
a, b the operands' coefficients and u the node's:

===========  ==========================================================================
Add          u_n = Σ c_i a_i,n  (+ the constant terms at n = 0)
Mul          u_n = Σ_{j=0}^{n} a_j b_{n−j}  (Cauchy product; a square sums half the terms)
division     u_n = (a_n − Σ_{j=1}^{n} b_j u_{n−j}) / b_0
pow x^α      u_n = Σ_{j=0}^{n−1} (α(n−j) − j) a_{n−j} u_j / (n a_0)   (constant α)
sqrt         u_n = (a_n − Σ_{j=1}^{n−1} u_j u_{n−j}) / (2 u_0)
exp          u_n = Σ_{j=1}^{n} j a_j u_{n−j} / n
log          u_n = (n a_n − Σ_{j=1}^{n−1} j u_j a_{n−j}) / (n a_0)
sin, cos     s_n = Σ_{j=1}^{n} j a_j c_{n−j} / n,   c_n = −Σ_{j=1}^{n} j a_j s_{n−j} / n  (one pair)
atan2(y, x)  r = x² + y², w = x y' − y x' (atan(a): x = 1):  θ_{n+1} = (w_n − Σ_{j=1}^{n} r_j (n+1−j) θ_{n+1−j}) / ((n+1) r_0)
Piecewise    u_n = the coefficient of the branch whose condition holds at order 0
===========  ==========================================================================

Integer powers 2…4 are products (exact, as the other kernels print them), negative integer
powers a division, ½ a sqrt. Order 0 of every rule is the function itself.
"""
from __future__ import annotations

import functools
import re
from dataclasses import dataclass, field

import sympy as sp

from derive.codegen.kernelspec import Block, CPrinter, KernelSpec, _flatten_observables, c_expr
from derive.codegen.render import TAYLOR_INC, render
from derive.methods.taylor import METHODS, TaylorMethod


class NoTaylorRule(ValueError):
    """The expression uses a function without a rule in :data:`RULES`."""


@dataclass
class Node:
    """One series node: ``code`` is the C statement computing its coefficient ``n`` (a C
    variable of the generated loop), given every operand's coefficients up to n; empty for the
    second node of a pair computed by the first (cos beside sin)."""

    index: int
    rule: str
    code: str
    obs: bool = False  # made for an output (computed only when the outputs are wanted)

    @property
    def deps(self) -> set[int]:
        """The nodes this one reads (for a pair's second node, the first one, which computes
        both)."""
        if not self.code:
            return {self.index - 1}
        return {int(k) for k in re.findall(r"u\[(\d+)\]", self.code)} - {self.index}


@dataclass
class Decomposition:
    """The right-hand side as elementary operations: the states are series nodes 0…NY−1 (and
    ``t``, when it appears, the next one), then one node per operation in evaluation order."""

    ny: int
    constants: list = field(default_factory=list)  # [(C name, C expression)] in order
    nodes: list = field(default_factory=list)      # [Node]
    outputs: list = field(default_factory=list)    # per rhs component: ("u", k) or ("c", text)
    guards: list = field(default_factory=list)     # per domain guard: C text at order 0
    params: list = field(default_factory=list)     # [(index, name)] of the parameters used
    time_node: int | None = None
    n_nodes: int = 0
    # The outputs (with ``decompose(spec, outputs=True)``): the series of their sin, cos and
    # exp calls (("u", k), the columns), and every output (index, SymPy expression) in the
    # states and the columns' symbols.
    columns: list = field(default_factory=list)
    column_symbols: list = field(default_factory=list)
    pointwise: list = field(default_factory=list)
    last: list = field(default_factory=list)       # [Node] the columns need at order p
    # The sin and cos of the states that stay pointwise (the cyclic angles): [state index], the
    # pair of each computed together at every sample (``<prefix>trig_block``), their symbols
    # ``tvs<k>``, ``tvc<k>`` (k: the pair's place in ``trig``) in ``pointwise``.
    trig: list = field(default_factory=list)
    trig_symbols: list = field(default_factory=list)

    @property
    def rules(self) -> list[str]:
        """The rules the nodes use, in the order of :data:`RULES` (the C helpers to emit)."""
        used = {n.rule for n in self.nodes}
        return [r for r in RULE_NAMES if r in used]


# ---------------------------------------------------------------------------------------------
# operands: ("u", k) a series node, ("c", text) a constant C expression


def _u(k: int, n: str = "n") -> str:
    return f"u[{k}][{n}]"


def coef(op, n: str = "n") -> str:
    """Coefficient n of an operand as C: a series' entry, a constant's value at n = 0 only."""
    kind, v = op
    return _u(v, n) if kind == "u" else f"({n} == 0 ? {v} : 0.0)"


def _is_time(s) -> bool:
    """Whether ``s`` is the time: the symbol named ``t``, whatever its assumptions (a user
    term's ``t`` is real, the built-in models' plain; the C printers name both ``t``, and
    :meth:`derive.codegen.kernelspec.Block.uses_time` asks by the name too)."""
    return isinstance(s, sp.Symbol) and s.name == "t"


def _times(exprs) -> set:
    """The time symbols (:func:`_is_time`) of ``exprs``."""
    return {s for e in exprs for s in sp.sympify(e).free_symbols if _is_time(s)}


class _Builder:
    def __init__(self, spec: KernelSpec):
        m = spec.model
        self.d = Decomposition(ny=len(m.states))
        self.ops: dict = {s: ("u", i) for i, s in enumerate(m.states)}  # memo: expr -> operand
        self.params = set(m.params)
        self.next = self.d.ny
        self.const_series: dict = {}
        self.obs_phase = False

    # -- nodes ----------------------------------------------------------------------------
    def node(self, rule: str, code: str) -> tuple:
        """A new node; in ``code``, ``@`` is its coefficient n and ``#`` its array."""
        k = self.next
        self.next += 1
        self.d.nodes.append(Node(k, rule, code.replace("@", _u(k)).replace("#", f"u[{k}]"),
                                 self.obs_phase))
        return ("u", k)

    def series(self, op) -> int:
        """The node index of an operand, a constant made a series (c, 0, 0, …) where a rule
        needs arrays."""
        if op[0] == "u":
            return op[1]
        if op[1] not in self.const_series:
            self.const_series[op[1]] = self.node("const", f"@ = {coef(op)};")[1]
        return self.const_series[op[1]]

    def is_const(self, e) -> bool:
        for s in e.free_symbols:
            op = self.ops.get(s)
            if _is_time(s) or (op is not None and op[0] == "u"):
                return False
        return True

    # -- expressions ----------------------------------------------------------------------
    def of(self, e) -> tuple:
        e = sp.sympify(e)
        found = self.ops.get(e)
        if found is not None:
            return found
        if _is_time(e):  # one node, whichever symbol of the time
            if self.d.time_node is None:
                self.d.time_node = self.next
                self.next += 1
            out = ("u", self.d.time_node)
        elif self.is_const(e):
            out = ("c", f"({c_expr(e)})")
        else:
            rule = RULES.get(e.func)
            if rule is None:
                raise NoTaylorRule(f"no Taylor rule for {e.func.__name__} (in {e})")
            out = rule(self, e)
        self.ops[e] = out
        return out

    def temp(self, name, e):
        """A CSE temporary: a constant becomes a named C constant, a series a node."""
        if self.is_const(e):
            self.d.constants.append((str(name), c_expr(e)))
            self.ops[name] = ("c", str(name))
        else:
            self.ops[name] = self.of(e)

    def order0(self, e) -> str:
        """C text of ``e`` at order 0 (a condition's or a guard's value at the expansion
        point): series symbols become their coefficient 0."""
        subs = {s: sp.Symbol(_u(op[1], "0")) for s in e.free_symbols
                for op in [self.ops.get(s)] if op is not None and op[0] == "u"}
        return c_expr(e.xreplace(subs))


# ---------------------------------------------------------------------------------------------
# the rules: one per elementary function


def _add(b: _Builder, e) -> tuple:
    consts, parts = [], []
    for arg in e.args:
        if b.is_const(arg):
            consts.append(arg)
            continue
        coeff, rest = arg.as_coeff_Mul()  # c * (series), c a number: folded into the sum
        k = b.series(b.of(rest))
        sign = "-" if coeff < 0 else "+"
        mag = abs(coeff)
        parts.append(f"{sign} {_u(k)}" if mag == 1 else f"{sign} {c_expr(mag)} * {_u(k)}")
    code = " ".join(parts)
    code = code[2:] if code.startswith("+ ") else "-" + code[2:]
    if consts:
        code += f" + (n == 0 ? {c_expr(sp.Add(*consts))} : 0.0)"
    return b.node("add", f"@ = {code};")


def _product(b: _Builder, ks: list) -> int:
    """The product of series nodes, left to right (Cauchy-product nodes)."""
    acc = ks[0]
    for k in ks[1:]:
        if k == acc:
            acc = b.node("sqr", f"@ = tc_sqr(n, u[{k}]);")[1]
        else:
            acc = b.node("mul", f"@ = tc_mul(n, u[{acc}], u[{k}]);")[1]
    return acc


def _power(b: _Builder, base, k: int) -> int:
    """The node of base**k, k ≥ 1: squares and products (x⁴ = (x²)²), each kept for reuse."""
    if k == 1:
        return b.series(b.of(base))
    key = sp.Pow(base, k)
    if key in b.ops:
        return b.series(b.ops[key])
    if k % 2 == 0:
        half = _power(b, base, k // 2)
        out = b.node("sqr", f"@ = tc_sqr(n, u[{half}]);")[1]
    else:
        out = _product(b, [_power(b, base, k - 1), _power(b, base, 1)])
    b.ops[key] = ("u", out)
    return out


def _quotient(b: _Builder, num: int, den: int) -> int:
    return b.node("div", f"tc_div(n, u[{num}], u[{den}], #);")[1]


def _scaled(b: _Builder, c, k: int) -> tuple:
    return ("u", k) if c == 1 else b.node("scale", f"@ = {c_expr(c)} * u[{k}][n];")


def _mul(b: _Builder, e) -> tuple:
    const, num, den = [], [], []
    for f in e.args:
        if b.is_const(f):
            const.append(f)
            continue
        base, ex = f.as_base_exp()
        if ex.is_Integer and ex < 0:
            den.append(_power(b, base, int(-ex)))
        elif ex.is_Integer and ex > 1:
            num.append(_power(b, base, int(ex)))
        else:
            num.append(b.series(b.of(f)))
    c = sp.Mul(*const)
    if not den:
        return _scaled(b, c, _product(b, num))
    d = _product(b, den)
    n = _product(b, num) if num else b.series(("c", "1.0"))
    return _scaled(b, c, _quotient(b, n, d))


def _pow(b: _Builder, e) -> tuple:
    base, ex = e.as_base_exp()
    if not b.is_const(ex):  # a series exponent: base**x = exp(x log base)
        return b.of(sp.exp(ex * sp.log(base)))
    if ex.is_Integer:
        k = int(ex)
        if k > 0:
            return ("u", _power(b, base, k))
        return ("u", _quotient(b, b.series(("c", "1.0")), _power(b, base, -k)))
    a = b.series(b.of(base))
    if ex == sp.Rational(1, 2):
        return b.node("sqrt", f"tc_sqrt(n, u[{a}], #);")
    return b.node("pow", f"tc_pow(n, u[{a}], {c_expr(ex)}, #);")


def _sincos(b: _Builder, e) -> tuple:
    x = e.args[0]
    a = b.series(b.of(x))
    s = b.node("sincos", "")[1]
    c = b.node("sincos", "")[1]
    b.d.nodes[-2].code = f"tc_sincos(n, u[{a}], u[{s}], u[{c}]);"
    b.ops[sp.sin(x)], b.ops[sp.cos(x)] = ("u", s), ("u", c)
    return b.ops[e]


def _exp(b: _Builder, e) -> tuple:
    a = b.series(b.of(e.args[0]))
    return b.node("exp", f"tc_exp(n, u[{a}], #);")


def _log(b: _Builder, e) -> tuple:
    a = b.series(b.of(e.args[0]))
    return b.node("log", f"tc_log(n, u[{a}], #);")


def _atan2(b: _Builder, e) -> tuple:
    y, x = e.args
    r = b.series(b.of(x ** 2 + y ** 2))
    yk, xk = b.series(b.of(y)), b.series(b.of(x))
    return b.node("atan2", f"tc_atan2(n, u[{yk}], u[{xk}], u[{r}], #);")


def _atan(b: _Builder, e) -> tuple:
    """atan(a) = atan2(a, 1): the atan2 rule with x the constant 1, r = 1 + a²."""
    a = e.args[0]
    r = b.series(b.of(1 + a ** 2))
    ak, one = b.series(b.of(a)), b.series(("c", "1.0"))
    return b.node("atan2", f"tc_atan2(n, u[{ak}], u[{one}], u[{r}], #);")


def _piecewise(b: _Builder, e) -> tuple:
    ops = [(b.of(value), cond) for value, cond in e.args]
    *pairs, (default, _) = ops
    out = coef(default)
    for value, cond in reversed(pairs):
        out = f"(({b.order0(cond)}) ? {coef(value)} : {out})"
    return b.node("piecewise", f"@ = {out};")


#: One rule per elementary function (SymPy function → rule). A rule decomposes its expression
#: into nodes whose C computes coefficient n; the C helpers tc_<rule> are in
#: templates/c/taylor.c.j2 (emitted only when a node uses them).
RULES = {
    sp.Add: _add,
    sp.Mul: _mul,
    sp.Pow: _pow,
    sp.sin: _sincos,
    sp.cos: _sincos,
    sp.exp: _exp,
    sp.log: _log,
    sp.atan2: _atan2,
    sp.atan: _atan,
    sp.Piecewise: _piecewise,
}

#: The node kinds, in the order their C helpers are emitted.
RULE_NAMES = ("const", "add", "scale", "mul", "sqr", "div", "sqrt", "pow", "exp", "log",
              "sincos", "atan2", "piecewise")


def decompose(spec: KernelSpec, outputs: bool = False) -> Decomposition:
    """The kernel spec's right-hand side (with its domain guards) as elementary operations;
    with ``outputs``, the model's outputs too (:attr:`Decomposition.columns`,
    :attr:`Decomposition.pointwise`): their sin, cos and exp calls become series nodes
    (sharing the right-hand side's), the outputs expressions in those."""
    b = _Builder(spec)
    block = spec.rhs
    for name, e in block.temps:
        b.temp(name, e)
    nd = len(spec.model.domain)
    b.d.guards = [f"({b.order0(g)})" for g in block.outputs[:nd]]
    b.d.outputs = [b.of(e) for e in block.outputs[nd:]]
    b.d.params = block.uses(spec.model.params)
    if outputs:
        _add_outputs(b, spec)
    b.d.n_nodes = b.next
    return b.d


def _add_outputs(b: _Builder, spec: KernelSpec) -> None:
    """The outputs' transcendental calls (sin, cos, exp of the controlled states, where
    :func:`series_safe`) as series nodes — the columns — and every output as an expression of
    the states and those columns (named ``tv<c>``), evaluated per sample with those calls
    read from the columns."""
    m = spec.model
    _, exprs = _flatten_observables(m.outputs)
    exprs = [sp.sympify(e) for e in exprs]
    states = set(m.states) | _times(exprs)
    # A call of a state that feeds nothing back (cos γ of the spin) stays a libm call: the step
    # control holds such a state to its rate's size only, and over a step a fast angle turns by
    # radians, more than a series of the step's order resolves (measured: such columns failed
    # outputs_converged on 85–96 steps of 86–114 of the reference top).
    cyclic = {s for s, c in zip(m.states, controlled_states(m)) if not c}
    calls: list = []
    for e in exprs:
        for sub in sp.preorder_traversal(e):
            if (isinstance(sub, _ENTIRE) and sub.free_symbols & states
                    and not sub.free_symbols & cyclic and sub not in calls
                    and series_safe(m, sub)):
                calls.append(sub)
    b.obs_phase = True
    b.d.columns = [b.of(c) for c in calls]
    b.obs_phase = False
    names = [sp.Symbol(f"tv{c}") for c in range(len(calls))]
    b.d.column_symbols = names
    subs = dict(zip(calls, names))
    # sin and cos of a state left out above (a cyclic angle): one reduction and two kernels per
    # sample for the pair, over a block of samples at once (templates/c/taylor.c.j2,
    # <prefix>trig_block), where glibc's sincos, called per sample, was a quarter of a solve's
    # time.
    trig_calls = set().union(*(e.atoms(sp.sin, sp.cos) for e in exprs))
    for k, s in enumerate(m.states):
        if any(f(s) in trig_calls and f(s) not in subs for f in (sp.sin, sp.cos)):
            pair = (sp.Symbol(f"tvs{len(b.d.trig)}"), sp.Symbol(f"tvc{len(b.d.trig)}"))
            b.d.trig.append(k)
            b.d.trig_symbols.extend(pair)
            subs[sp.sin(s)], subs[sp.cos(s)] = pair
    b.d.pointwise = [(j, e.xreplace(subs)) for j, e in enumerate(exprs)]
    # The nodes the columns read at order p (the passes 0..p-1 give the states through p and
    # every node through p-1), in evaluation order.
    by_index = {n.index: n for n in b.d.nodes}
    need, todo = set(), [op[1] for op in b.d.columns]
    while todo:
        k = todo.pop()
        if k in need or k not in by_index:  # a state or the time: already through order p
            continue
        need.add(k)
        todo.extend(by_index[k].deps)
    b.d.last = [n for n in b.d.nodes if n.index in need and n.code]


# Functions analytic everywhere: their series converge wherever their operands' do.
_ENTIRE = (sp.sin, sp.cos, sp.exp)


def _singular_keys(e, states) -> set | None:
    """The operands at which ``e`` is singular (the base of a negative or fractional power,
    the argument of a log, the pair of an atan2), or None when ``e`` holds something else
    this check does not follow (a piecewise term whose condition depends on the state, an
    unknown function)."""
    if not (e.free_symbols & states) or e.is_Symbol or e.is_Number:
        return set()
    if e.is_Pow:
        inner = _singular_keys(e.base, states)
        if inner is None:
            return None
        if e.exp.is_Integer and e.exp >= 0:
            return inner
        return inner | {("pow", e.base)}
    if e.func in (sp.log, sp.atan2) or isinstance(e, _ENTIRE) or e.is_Add or e.is_Mul:
        keys = set()
        for a in e.args:
            k = _singular_keys(a, states)
            if k is None:
                return None
            keys |= k
        if e.func in (sp.log, sp.atan2):
            keys.add((e.func.__name__, e.args))
        return keys
    if isinstance(e, sp.Piecewise):
        keys = set()
        for value, cond in e.args:
            k = _singular_keys(value, states)
            if k is None or (cond.free_symbols & states):
                return None
            keys |= k
        return keys
    return None


def series_safe(model, e) -> bool:
    """May output ``e`` be evaluated from its own Taylor series over a step?

    The step is chosen from the states' coefficients, so within it the states' series converge
    (to the tolerance); an output's series converges as well where the output is an entire
    function of the states (sums, products, non-negative powers, sin, cos, exp) — or singular
    only where the right-hand side itself is (the same base of a negative or fractional power,
    log or atan2 argument: there the states' own series see the singularity). Anything else
    (an atan2 of the outputs alone, a square root the dynamics do not take, a piecewise term
    switching on the state) is evaluated pointwise from the evaluated state instead."""
    states = set(model.states) | _times([e, *model.rhs, *model.domain])
    keys = _singular_keys(sp.sympify(e), states)
    if keys is None:
        return False
    if not keys:
        return True
    allowed: set = set()
    for f in list(model.rhs) + list(model.domain):
        k = _singular_keys(sp.sympify(f), states)
        if k:
            allowed |= k
    return keys <= allowed


#: Multiply-adds per term of a node's Cauchy-type sum at order n (a product's n + 1 terms, a
#: square's half, sin/cos's two sums, …): a jet of order p costs about Σ w_rule · p²/2 (the
#: cost model of ``method = "auto"``, :mod:`derive.methods.costs`). Linear nodes (sums,
#: scalings, constants, a piecewise choice) cost O(p) and count a tenth.
JET_WEIGHTS = {"mul": 1.0, "sqr": 0.5, "div": 1.0, "sqrt": 0.5, "pow": 2.0, "exp": 1.0, "log": 1.0,
               "sincos": 2.0, "atan2": 3.0}


def jet_weight(spec: KernelSpec) -> float:
    """Σ over the right-hand side's series nodes of :data:`JET_WEIGHTS` (0.1 for a linear node):
    the ``w`` of :mod:`derive.methods.costs`, a jet of order p costing about w p²/2
    multiply-adds. 0 when a function of the right-hand side has no Taylor rule."""
    try:
        d = decompose(spec)
    except NoTaylorRule:
        return 0.0
    return round(sum(JET_WEIGHTS.get(n.rule, 0.1) for n in d.nodes if n.code), 3)


def controlled_states(model) -> tuple[bool, ...]:
    """Per state: True when it feeds something back (appears in a right-hand side or a domain
    guard). A state that appears in none, a cyclic angle such as α or γ, is integrated from the
    others; the step control holds it to the size of its rate, not of its value (its growth, γ ~
    6 t on the reference top, would loosen the relative tolerance of every other state), and
    the outputs take no series of its functions (:func:`_add_outputs`)."""
    free = set()
    for e in list(model.rhs) + list(model.domain):
        free |= sp.sympify(e).free_symbols
    flags = tuple(s in free for s in model.states)
    return flags if any(flags) else tuple(True for _ in flags)


def applicable(model) -> str | None:
    """None if every function in the model's right-hand side has a Taylor rule, else why not."""
    try:
        decompose(KernelSpec.of(model))
    except NoTaylorRule as err:
        return str(err)
    return None


def render_taylor(model, methods: list[str] | None = None, spec: KernelSpec | None = None
                  ) -> dict[str, str]:
    """``<name>_taylor.h`` and ``<name>_taylor.c`` for ``model`` (``spec``: its kernel spec, if
    the caller has it): the coefficient recurrences and the Taylor solvers
    (:mod:`derive.methods.taylor`). The C includes ``<name>_solvers.h`` (``derive_stats``, the
    ``DERIVE_*`` codes, the model header). Raises :class:`NoTaylorRule` for a function without
    a rule."""
    names = list(METHODS) if methods is None else list(methods)
    for n in names:
        if n not in METHODS:
            raise ValueError(f"unknown Taylor method {n!r}; known: {', '.join(METHODS)}")
    spec = spec if spec is not None else KernelSpec.of(model)
    d = decompose(spec, outputs=True)
    methods_ctx = [_method_context(METHODS[n]) for n in names]
    rhs_nodes = [n for n in d.nodes if n.code and not n.obs]
    obs_nodes = [n for n in d.nodes if n.code and n.obs]
    jet_text = [n.code for n in rhs_nodes] + d.guards + [op[1] for op in d.outputs if op[0] == "c"]
    obs_text = [n.code for n in obs_nodes + d.last]
    ny = len(model.states)
    ctx = {
        "prefix": model.name, "ny": ny, "d": d, "coef": coef,
        "methods": methods_ctx, "max_order": max(m["max_order"] for m in methods_ctx),
        "controlled": controlled_states(model), "states": model.state_names,
        "rhs_nodes": rhs_nodes, "obs_nodes": obs_nodes,
        "jet_scope": _scope(jet_text, d), "obs_scope": _scope(obs_text, d),
        # the columns of the coefficient table w past the states: (column, operand)
        "columns": [(ny + c, op) for c, op in enumerate(d.columns)],
        # the states whose sin and cos the samples compute (each pair at 2 c, 2 c + 1 past them)
        "trig": d.trig,
        "nobs": len(d.pointwise),
        "has_angles": spec.observable_names[:3] == ("alpha", "beta", "gamma"),
        "pointwise": _pointwise(model, d),
    }
    ctx["lanes"] = _lanes(d, rhs_nodes, ctx["jet_scope"]) if ctx["pointwise"] else None
    # the nodes the dense output reads of the jet's (the states, and what the outputs' series are
    # made of, less the nodes made for them): what the lanes' full-grid driver copies out of a
    # lane before it (templates/c/taylor_lanes_driver.c.j2)
    read = set(range(ny)) | {int(k) for k in _NODE.findall(" ".join(obs_text + [coef(op) for op in d.columns]))}
    ctx["dense_nodes"] = sorted(read - {n.index for n in d.nodes if n.obs})
    # the doubles a lane keeps of its steps (at least one step's at the highest order)
    ctx["LBUF"] = max(2048, 6 + len(ctx["dense_nodes"]) * (ctx["max_order"] + 1))
    return {f"{model.name}_taylor.h": render("c/taylor.h.j2", **ctx),
            f"{model.name}_taylor.c": render("c/taylor.c.j2", **ctx),
            TAYLOR_INC: taylor_drivers()}


@functools.lru_cache(maxsize=1)
def taylor_drivers() -> str:
    """``derive_taylor.inc``: the Taylor methods' drivers (step-size control, dense output, the
    solve and simulate drivers), one text for every model; a model's ``<model>_taylor.c``
    defines its jet and sizes as macros and includes it."""
    return render("c/taylor.inc.j2", methods=[_method_context(m) for m in METHODS.values()])


#: The index of the lane loops in the lanes driver's C (templates/c/taylor_lanes.c.j2): a name
#: no model symbol takes (they never end in an underscore).
LANE = "lane_"

_SERIES = re.compile(r"u\[(\d+)\]\[([^\]]+)\]")
_NODE = re.compile(r"\bu\[(\d+)\]")
_PRODUCT = re.compile(r"^u\[(\d+)\]\[n\] = tc_(mul|sqr)\(n, (.*)\);$")


def _lanes(d: Decomposition, rhs_nodes: list, jet_scope: tuple) -> dict | None:
    """The jet of the lanes driver (several trajectories at once, :mod:`derive.sim.batch`): the
    statements of :func:`decompose`'s C with every series entry and every parameter and
    constant indexed by the lane (``u[k][n]`` -> ``u[k][n][lane_]``, ``x0`` -> ``x0[lane_]``), an
    elementwise node as a loop over the lanes, a rule's helper ``tc_<rule>`` as its lanes helper
    ``tcl_<rule>`` (the product and the square writing into their node's entry). None when a
    helper's argument would need a lane (a parameter in a power's exponent): such a model
    has no lanes driver."""
    names = [nm for _, nm in jet_scope[0]] + [nm for nm, _ in jet_scope[1]]
    word = re.compile(r"\b(" + "|".join(map(re.escape, names)) + r")\b") if names else None

    def lane(text: str) -> str:
        text = _SERIES.sub(lambda m: f"u[{m.group(1)}][{m.group(2)}][{LANE}]", text)
        return word.sub(lambda m: f"{m.group(1)}[{LANE}]", text) if word else text

    nodes = []
    for node in rhs_nodes:
        code = node.code
        if "tc_" not in code:
            nodes.append(("loop", lane(code)))
            continue
        m = _PRODUCT.match(code)
        if m:
            code = f"tc_{m.group(2)}(n, {m.group(3)}, u[{m.group(1)}][n]);"
        if word and word.search(_SERIES.sub("", code)):
            return None
        nodes.append(("call", code.replace("tc_", "tcl_")))
    return {"nodes": _fused(d, rhs_nodes, nodes), "params": jet_scope[0],
            "consts": [(nm, lane(e)) for nm, e in jet_scope[1]],
            "guards": [lane(g) for g in d.guards],
            "outputs": [lane(coef(out)) for out in d.outputs], "index": LANE}


_FUSABLE = re.compile(r"^tcl_(mul|div)\(n, u\[(\d+)\], u\[(\d+)\], u\[(\d+)\](?:\[n\])?\);$")
FUSED_MAX = 4  # the sums of one fused loop (each a vector accumulator, its operands' loads)


def _fused(d: Decomposition, rhs_nodes: list, nodes: list) -> list:
    """The lanes' jet statements ``nodes`` (one per rhs node) in an order that puts the Cauchy
    sums that do not depend on one another side by side: each node's stage is the number of
    sums (rule calls) on its longest path of operands within a pass; a stage's elementwise
    loops come first, then its sums, the products' and quotients' of one stage as one loop
    over j with an accumulator each, ("fused", [(rule, node, a, b)]) (up to FUSED_MAX). A sum
    alone waits on its own chain of additions (latency-bound over the lanes' vector); two or
    three in one loop fill the units (the bench's 1000 tops, final-only lanes: 5.7 -> 5.2-5.4
    ms). Each sum keeps its own order of terms: the same numbers."""
    writer = {}
    for node in d.nodes:  # (a pair's second node is computed by its first)
        writer[node.index] = node.index if node.code else writer[node.index - 1]
    made = {node.index for node in rhs_nodes}
    stage, sums = {}, {}
    for node, (kind, _) in zip(rhs_nodes, nodes):
        deps = ({writer[k] for k in node.deps if k in writer} & made) - {node.index}  # (a pair's own)
        stage[node.index] = max((stage[k] + sums[k] for k in deps), default=0)
        sums[node.index] = kind == "call"
    out = []
    for s in sorted(set(stage.values())):
        here = [(node, kn) for node, kn in zip(rhs_nodes, nodes) if stage[node.index] == s]
        out += [kn for _, kn in here if kn[0] == "loop"]
        calls = [kn for _, kn in here if kn[0] == "call"]
        fusable = [(kn, _FUSABLE.match(kn[1])) for kn in calls]
        out += [kn for kn, m in fusable if not m]
        group = [(kn, m) for kn, m in fusable if m]
        for k in range(0, len(group), FUSED_MAX):
            chunk = group[k:k + FUSED_MAX]
            if len(chunk) == 1:
                out.append(chunk[0][0])
            else:  # (rule, the node it makes, its operands a and b: a b, or a / b)
                out.append(("fused", [(m.group(1), int(m.group(4)), int(m.group(2)), int(m.group(3)))
                                      for _, m in chunk]))
    return out


def _scope(texts: list[str], d: Decomposition) -> tuple[list, list]:
    """The parameters and named constants that C ``texts`` read (constants through the
    constants they are made of): ([(index, name)], [(name, C expression)]), in order."""
    text = " ".join(texts)
    consts = []
    for name, e in reversed(d.constants):
        if re.search(rf"\b{re.escape(name)}\b", text):
            consts.append((name, e))
            text += " " + e
    params = [(i, nm) for i, nm in d.params if re.search(rf"\b{re.escape(nm)}\b", text)]
    return params, consts[::-1]


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
    pr = _BlockPrinter(model.params)
    temps = []
    for name, e in block.temps:
        text = pr.doprint(e)
        if e.free_symbols <= pr.fixed:
            pr.fixed.add(name)
            pr.once.append(("double", str(name), text))
        else:
            pr.each.append(("double", str(name), text))
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

"""A model's Taylor jet as data: the right-hand side decomposed into elementary steps.

The right-hand side after CSE (the kernel spec's ``rhs`` block: the domain guards, then f) is
decomposed once into elementary operations u_k = φ(u_i, u_j, constants), as heyoka decomposes a
system. Each operand is either a *constant* (:class:`Const`: numbers, parameters and whatever is
made of them alone, a SymPy expression printed as C and evaluated once per expansion) or a
*series* node k, an array of Taylor coefficients u_k,0 … u_k,p. A :class:`Step` names its rule,
its operands and the node(s) it writes; the n-th coefficient of its output follows from the
operands' coefficients 0…n (and its own earlier ones) by the rule's recurrence; the states close
the loop, y_{i,n+1} = f_i,n / (n + 1).

Nothing here is C text: the scalar jet and the lanes jet (several trajectories at once) are both
rendered from the same steps by :mod:`derive.codegen.taylor`, each step by the macros of its
rule's file ``templates/c/taylor_rules/<rule>.j2``, which holds the rule's recurrence and its
scalar and lanes C. :data:`RULE_TABLE` has one row per rule, a and b the operands' coefficients
and u the step's:

===========  ==========================================================================
const        u_n = c at n = 0, else 0 (a constant where a rule needs a series)
add          u_n = Σ c_i a_i,n  (+ the constant terms at n = 0)
scale        u_n = c a_n
mul, sqr     u_n = Σ_{j=0}^{n} a_j b_{n−j}  (Cauchy product; a square sums half the terms)
div          u_n = (a_n − Σ_{j=1}^{n} b_j u_{n−j}) / b_0
pow x^α      u_n = Σ_{j=0}^{n−1} (α(n−j) − j) a_{n−j} u_j / (n a_0)   (constant α)
sqrt         u_n = (a_n − Σ_{j=1}^{n−1} u_j u_{n−j}) / (2 u_0)
exp          u_n = Σ_{j=1}^{n} j a_j u_{n−j} / n
log          u_n = (n a_n − Σ_{j=1}^{n−1} j u_j a_{n−j}) / (n a_0)
sincos       s_n = Σ_{j=1}^{n} j a_j c_{n−j} / n,   c_n = −Σ_{j=1}^{n} j a_j s_{n−j} / n  (one pair)
atan2(y, x)  r = x² + y², w = x y' − y x' (atan(a): x = 1):  θ_{n+1} = (w_n − Σ_{j=1}^{n} r_j (n+1−j) θ_{n+1−j}) / ((n+1) r_0)
piecewise    u_n = the coefficient of the branch whose condition holds at order 0
===========  ==========================================================================

Integer powers 2…4 are products (exact, as the other kernels print them), negative integer
powers a division, ½ a sqrt. Order 0 of every rule is the function itself.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from derive.codegen.kernelspec import KernelSpec, _flatten_observables


class NoTaylorRule(ValueError):
    """The expression uses a function without a rule (:data:`RULES`, :data:`RULE_TABLE`)."""


@dataclass(frozen=True)
class Rule:
    """One elementary function of the jet; its C is ``templates/c/taylor_rules/<name>.j2``.

    ``weight``: multiply-adds per term of its sum at order n (a product's n + 1 terms, a
    square's half, sin/cos's two sums), the cost model of ``method = "auto"``
    (:mod:`derive.methods.costs`); ``elementwise``: O(p) work, no sum (the lanes repeat its
    scalar statement per lane; its weight counts a tenth); ``fusable``: a sum the lanes may run
    in one loop beside other such sums (its file's ``fused_*`` macros); ``unary``: the SymPy
    functions decomposed as this rule of one series operand (``u = f(a)``)."""

    name: str
    weight: float = 0.1
    elementwise: bool = False
    fusable: bool = False
    unary: tuple = ()


#: One row per rule, in the order their C helpers are emitted. Adding a rule adds its row here
#: and its file ``templates/c/taylor_rules/<name>.j2``; a function of more than one operand (or
#: made of several steps) also its decomposition in :data:`RULES`.
RULE_TABLE = (
    Rule("const", elementwise=True),
    Rule("add", elementwise=True),
    Rule("scale", elementwise=True),
    Rule("mul", 1.0, fusable=True),
    Rule("sqr", 0.5),
    Rule("div", 1.0, fusable=True),
    Rule("sqrt", 0.5),
    Rule("pow", 2.0),
    Rule("exp", 1.0, unary=(sp.exp,)),
    Rule("log", 1.0, unary=(sp.log,)),
    Rule("sincos", 2.0),
    Rule("atan2", 3.0),
    Rule("piecewise", elementwise=True),
)


def rule_of(name: str) -> Rule:
    """The row of :data:`RULE_TABLE` named ``name``."""
    for r in RULE_TABLE:
        if r.name == name:
            return r
    raise KeyError(name)


@dataclass(frozen=True)
class Const:
    """A constant operand: ``expr`` made of numbers, parameters and named constants; printed
    bare when ``named`` (a named constant, a literal), else in parentheses."""

    expr: object
    named: bool = False


@dataclass
class Step:
    """One elementary operation: rule ``rule`` (a row of :data:`RULE_TABLE`) of the operands
    ``args`` (node indices, or :class:`Const`) writing the node(s) ``outs`` (two for the sin and
    cos pair). ``const``: the constant part of a sum, the factor of a scaling; ``branches``: a
    piecewise term's (condition at order 0, operand) pairs, the default last with condition
    None; ``reads0``: the nodes those conditions read at order 0. ``obs``: made for an output
    (computed only when the outputs are wanted)."""

    rule: str
    outs: tuple
    args: tuple = ()
    const: object = None
    terms: tuple = ()        # add: (sign, factor or None, node) per series term
    branches: tuple = ()
    reads0: frozenset = frozenset()
    obs: bool = False

    @property
    def index(self) -> int:
        return self.outs[0]

    @property
    def reads(self) -> set[int]:
        """The nodes this step reads (its operands' series, its conditions' order 0)."""
        ops = list(self.args) + [k for _, _, k in self.terms] + [v for _, v in self.branches]
        return {op for op in ops if isinstance(op, int)} | set(self.reads0)

    @property
    def exprs(self) -> list:
        """The constant SymPy expressions the step's C prints (what decides its scope)."""
        out = [op.expr for op in list(self.args) + [v for _, v in self.branches]
               if isinstance(op, Const)]
        out += [c for c, _ in self.branches if c is not None]
        return out + ([self.const] if self.const is not None else [])


@dataclass
class Decomposition:
    """The right-hand side as elementary steps: the states are series nodes 0…NY−1 (and ``t``,
    when it appears, the next one), then the steps' nodes in evaluation order."""

    ny: int
    constants: list = field(default_factory=list)  # [(name Symbol, SymPy expression)] in order
    steps: list = field(default_factory=list)      # [Step]
    outputs: list = field(default_factory=list)    # per rhs component: its operand
    guards: list = field(default_factory=list)     # per domain guard: SymPy at order 0
    params: list = field(default_factory=list)     # [(index, name)] of the parameters used
    time_node: int | None = None
    n_nodes: int = 0
    # The outputs (with ``decompose(spec, outputs=True)``): the series of their sin, cos and
    # exp calls (operands, the columns), and every output (index, SymPy expression) in the
    # states and the columns' symbols.
    columns: list = field(default_factory=list)
    column_symbols: list = field(default_factory=list)
    pointwise: list = field(default_factory=list)
    last: list = field(default_factory=list)       # [Step] the columns need at order p
    # The sin and cos of the states that stay pointwise (the cyclic angles): [state index], the
    # pair of each computed together at every sample (``<prefix>trig_block``), their symbols
    # ``tvs<k>``, ``tvc<k>`` (k: the pair's place in ``trig``) in ``pointwise``.
    trig: list = field(default_factory=list)
    trig_symbols: list = field(default_factory=list)
    # The symbols standing for a series' coefficient 0 in the guards and conditions.
    order0: dict = field(default_factory=dict)     # {Symbol: node}

    @property
    def rules(self) -> list[str]:
        """The rules the steps use, in the order of :data:`RULE_TABLE` (the C helpers to emit)."""
        used = {s.rule for s in self.steps}
        return [r.name for r in RULE_TABLE if r.name in used]

    @property
    def n_op_nodes(self) -> int:
        """The nodes the steps write (past the states and the time)."""
        return sum(len(s.outs) for s in self.steps)

    @property
    def writer(self) -> dict:
        """{node: the step writing it} (a pair's two nodes: its one step)."""
        return {k: s for s in self.steps for k in s.outs}


def _is_time(s) -> bool:
    """Whether ``s`` is the time: the symbol named ``t``, whatever its assumptions (a user
    term's ``t`` is real, the built-in models' plain; the C printers name both ``t``, and
    :meth:`derive.codegen.kernelspec.Block.uses_time` asks by the name too)."""
    return isinstance(s, sp.Symbol) and s.name == "t"


def _times(exprs) -> set:
    """The time symbols (:func:`_is_time`) of ``exprs``."""
    return {s for e in exprs for s in sp.sympify(e).free_symbols if _is_time(s)}


ONE = Const(sp.Float(1.0), named=True)


class _Builder:
    def __init__(self, spec: KernelSpec):
        m = spec.model
        self.d = Decomposition(ny=len(m.states))
        self.ops: dict = {s: i for i, s in enumerate(m.states)}  # memo: expr -> operand
        self.next = self.d.ny
        self.const_series: dict = {}
        self.obs_phase = False

    # -- steps ----------------------------------------------------------------------------
    def step(self, rule: str, *args, n_out: int = 1, **kw) -> int:
        """A new step of ``rule`` writing ``n_out`` new nodes; the first one's index."""
        outs = tuple(range(self.next, self.next + n_out))
        self.next += n_out
        self.d.steps.append(Step(rule, outs, tuple(args), obs=self.obs_phase, **kw))
        return outs[0]

    def series(self, op) -> int:
        """The node index of an operand, a constant made a series (c, 0, 0, …) where a rule
        needs arrays."""
        if isinstance(op, int):
            return op
        if op not in self.const_series:
            self.const_series[op] = self.step("const", op)
        return self.const_series[op]

    def is_const(self, e) -> bool:
        for s in e.free_symbols:
            if _is_time(s) or isinstance(self.ops.get(s), int):
                return False
        return True

    # -- expressions ----------------------------------------------------------------------
    def of(self, e):
        e = sp.sympify(e)
        found = self.ops.get(e)
        if found is not None:
            return found
        if _is_time(e):  # one node, whichever symbol of the time
            if self.d.time_node is None:
                self.d.time_node = self.next
                self.next += 1
            out = self.d.time_node
        elif self.is_const(e):
            out = Const(e)
        else:
            rule = _decomposition(e.func)
            if rule is None:
                raise NoTaylorRule(f"no Taylor rule for {e.func.__name__} (in {e})")
            out = rule(self, e)
        self.ops[e] = out
        return out

    def temp(self, name, e):
        """A CSE temporary: a constant becomes a named C constant, a series a node."""
        if self.is_const(e):
            self.d.constants.append((name, e))
            self.ops[name] = Const(name, named=True)
        else:
            self.ops[name] = self.of(e)

    def order0(self, e) -> tuple:
        """``e`` at order 0 (a condition's or a guard's value at the expansion point): series
        symbols become symbols ``u[k][0]`` of their coefficient 0; and the nodes read."""
        subs = {}
        for s in e.free_symbols:
            op = self.ops.get(s)
            if isinstance(op, int):
                subs[s] = sp.Symbol(f"u[{op}][0]")
                self.d.order0[subs[s]] = op
        return e.xreplace(subs), frozenset(self.d.order0[s] for s in subs.values())


# ---------------------------------------------------------------------------------------------
# the decompositions: SymPy function -> steps


def _add(b: _Builder, e) -> int:
    consts, terms = [], []
    for arg in e.args:
        if b.is_const(arg):
            consts.append(arg)
            continue
        coeff, rest = arg.as_coeff_Mul()  # c * (series), c a number: folded into the sum
        k = b.series(b.of(rest))
        terms.append(("-" if coeff < 0 else "+", None if abs(coeff) == 1 else abs(coeff), k))
    return b.step("add", terms=tuple(terms), const=sp.Add(*consts) if consts else None)


def _product(b: _Builder, ks: list) -> int:
    """The product of series nodes, left to right (Cauchy-product steps)."""
    acc = ks[0]
    for k in ks[1:]:
        acc = b.step("sqr", k) if k == acc else b.step("mul", acc, k)
    return acc


def _power(b: _Builder, base, k: int) -> int:
    """The node of base**k, k ≥ 1: squares and products (x⁴ = (x²)²), each kept for reuse."""
    if k == 1:
        return b.series(b.of(base))
    key = sp.Pow(base, k)
    if key in b.ops:
        return b.series(b.ops[key])
    if k % 2 == 0:
        out = b.step("sqr", _power(b, base, k // 2))
    else:
        out = _product(b, [_power(b, base, k - 1), _power(b, base, 1)])
    b.ops[key] = out
    return out


def _scaled(b: _Builder, c, k: int) -> int:
    return k if c == 1 else b.step("scale", k, const=c)


def _mul(b: _Builder, e) -> int:
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
    n = _product(b, num) if num else b.series(ONE)
    return _scaled(b, c, b.step("div", n, d))


def _pow(b: _Builder, e):
    base, ex = e.as_base_exp()
    if not b.is_const(ex):  # a series exponent: base**x = exp(x log base)
        return b.of(sp.exp(ex * sp.log(base)))
    if ex.is_Integer:
        k = int(ex)
        if k > 0:
            return _power(b, base, k)
        return b.step("div", b.series(ONE), _power(b, base, -k))
    a = b.series(b.of(base))
    if ex == sp.Rational(1, 2):
        return b.step("sqrt", a)
    return b.step("pow", a, Const(ex, named=True))


def _sincos(b: _Builder, e) -> int:
    x = e.args[0]
    s = b.step("sincos", b.series(b.of(x)), n_out=2)
    b.ops[sp.sin(x)], b.ops[sp.cos(x)] = s, s + 1
    return b.ops[e]


def _unary(rule: str):
    """The decomposition of a function of one series operand as step ``rule``."""
    return lambda b, e: b.step(rule, b.series(b.of(e.args[0])))


def _atan2(b: _Builder, e) -> int:
    y, x = e.args
    r = b.series(b.of(x ** 2 + y ** 2))
    return b.step("atan2", b.series(b.of(y)), b.series(b.of(x)), r)


def _atan(b: _Builder, e) -> int:
    """atan(a) = atan2(a, 1): the atan2 rule with x the constant 1, r = 1 + a²."""
    a = e.args[0]
    r = b.series(b.of(1 + a ** 2))
    return b.step("atan2", b.series(b.of(a)), b.series(ONE), r)


def _piecewise(b: _Builder, e) -> int:
    ops = [(b.of(value), cond) for value, cond in e.args]
    *pairs, (default, _) = ops
    branches, reads = [], set()
    for value, cond in pairs:
        c0, r = b.order0(cond)
        branches.append((c0, value))
        reads |= r
    branches.append((None, default))
    return b.step("piecewise", branches=tuple(branches), reads0=frozenset(reads))


#: SymPy function → its decomposition into steps, for the functions that are more than one rule
#: of one series operand (those come from :attr:`Rule.unary` of their rows).
RULES = {
    sp.Add: _add,
    sp.Mul: _mul,
    sp.Pow: _pow,
    sp.sin: _sincos,
    sp.cos: _sincos,
    sp.atan2: _atan2,
    sp.atan: _atan,
    sp.Piecewise: _piecewise,
}


def _decomposition(func):
    """The decomposition of SymPy function ``func`` (:data:`RULES`, or the rule of
    :data:`RULE_TABLE` that takes it as a unary function), or None."""
    if func in RULES:
        return RULES[func]
    for r in RULE_TABLE:
        if func in r.unary:
            return _unary(r.name)
    return None


def decompose(spec: KernelSpec, outputs: bool = False) -> Decomposition:
    """The kernel spec's right-hand side (with its domain guards) as elementary steps; with
    ``outputs``, the model's outputs too (:attr:`Decomposition.columns`,
    :attr:`Decomposition.pointwise`): their sin, cos and exp calls become series nodes
    (sharing the right-hand side's), the outputs expressions in those."""
    b = _Builder(spec)
    block = spec.rhs
    for name, e in block.temps:
        b.temp(name, e)
    nd = len(spec.model.domain)
    b.d.guards = [b.order0(g)[0] for g in block.outputs[:nd]]
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
    writer = b.d.writer
    need, todo = set(), list(b.d.columns)
    while todo:
        k = todo.pop()
        s = writer.get(k)
        if s is None or s.index in need:  # a state or the time: already through order p
            continue
        need.add(s.index)
        todo.extend(s.reads)
    b.d.last = [s for s in b.d.steps if s.index in need]


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
    if isinstance(e, sp.Piecewise):
        if any(cond.free_symbols & states for _, cond in e.args):
            return None
        operands = [value for value, _ in e.args]
    elif e.func in (sp.log, sp.atan2) or isinstance(e, _ENTIRE) or e.is_Add or e.is_Mul:
        operands = e.args
    else:
        return None
    keys = set()
    for a in operands:
        k = _singular_keys(a, states)
        if k is None:
            return None
        keys |= k
    if e.func in (sp.log, sp.atan2):
        keys.add((e.func.__name__, e.args))
    return keys


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


def jet_weight(spec: KernelSpec) -> float:
    """Σ over the right-hand side's steps of their rules' weights (:class:`Rule`):
    the ``w`` of :mod:`derive.methods.costs`, a jet of order p costing about w p²/2
    multiply-adds. 0 when a function of the right-hand side has no Taylor rule."""
    try:
        d = decompose(spec)
    except NoTaylorRule:
        return 0.0
    return round(sum(rule_of(s.rule).weight for s in d.steps), 3)


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

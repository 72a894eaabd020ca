"""Kernel spec: a model laid out for code generation.

Ordered state and parameter names, and for each function (rhs, Jacobian, observables) a list of
common-subexpression temporaries followed by the outputs, printed as C99 and as NumPy. Everything
here is deterministic: canonical CSE order, numbered temporaries, no dict/set iteration over
symbols, so the generated text is byte-identical whatever PYTHONHASHSEED is.
"""
from __future__ import annotations

from collections import Counter
from dataclasses import dataclass

import sympy as sp
from sympy.printing.c import C99CodePrinter
from sympy.printing.numpy import NumPyPrinter

from derive.symbolic.models import INPUTS, Model


def _small_power(printer, expr) -> str | None:
    """x**n for 2 ≤ |n| ≤ 4 as a parenthesised product (x*x, not pow(x, 2): exact and faster);
    None for any other power. Parenthesised because a Mul prints its denominator through here,
    right after a "/"."""
    base, exp = expr.as_base_exp()
    if not (exp.is_Integer and 2 <= abs(int(exp)) <= 4):
        return None
    b = printer.parenthesize(base, sp.printing.precedence.PRECEDENCE["Mul"] + 1)
    prod = "(" + "*".join([b] * abs(int(exp))) + ")"
    return prod if exp > 0 else f"1.0/{prod}"


class CPrinter(C99CodePrinter):
    """C99 with small integer powers as products and Piecewise as nested conditionals."""

    def _print_Pow(self, expr):
        small = _small_power(self, expr)
        if small is not None:
            return small
        base, exp = expr.as_base_exp()
        if exp == sp.Rational(1, 2):
            return f"sqrt({self._print(base)})"
        if exp == -1:
            return f"1.0/{self.parenthesize(base, sp.printing.precedence.PRECEDENCE['Mul'] + 1)}"
        return super()._print_Pow(expr)

    def _print_Symbol(self, expr):
        return str(expr)

    def _print_Piecewise(self, expr):
        *pairs, (default, _) = expr.args
        out = self._print(default)
        for value, cond in reversed(pairs):
            out = f"(({self._print(cond)}) ? ({self._print(value)}) : ({out}))"
        return out


class NPrinter(NumPyPrinter):
    """NumPy code; small integer powers as products, Piecewise as numpy.where (vectorised)."""

    def _print_Pow(self, expr, rational=False):
        small = _small_power(self, expr)
        return small if small is not None else super()._print_Pow(expr, rational=rational)

    def _print_Piecewise(self, expr):
        # numpy.where over (cond, value) pairs, innermost last; the last pair must be the default.
        *pairs, (default, cond_true) = expr.args
        out = self._print(default)
        for value, cond in reversed(pairs):
            out = f"numpy.where({self._print(cond)}, {self._print(value)}, {out})"
        return out


_C = CPrinter()
# order "none": the argument order array_ops_first chose (see there) is the order printed.
_NP = NPrinter({"fully_qualified_modules": True, "order": "none"})


def c_expr(e) -> str:
    return _C.doprint(e)


def np_expr(e, scalars: frozenset = frozenset()) -> str:
    return _NP.doprint(array_ops_first(e, scalars))


# ---------------------------------------------------------------------------------------------
# NumPy: fewer passes over the batch


def _is_scalar(e, scalars) -> bool:
    return e.free_symbols <= scalars


def _array_factors(term, scalars) -> list:
    return [f for f in sp.Mul.make_args(term) if not _is_scalar(f, scalars)]


def array_ops_first(e, scalars: frozenset):
    """``e`` rearranged (the same value up to rounding) for NumPy on a batch, where each
    operation with an array operand is a pass over N numbers and ``scalars`` (the parameters,
    and temporaries made of them alone) cost nothing: in a product the scalar factors are
    multiplied together before they meet an array, and an array factor common to several
    terms of a sum is taken out of them once (greedily, the most common first: a·x + b·x →
    (a + b)·x). Negative terms come last, so that a sum starts without a negation. The
    result is unevaluated, for printing in this order."""
    if e.is_Atom or not e.args:
        return e
    if e.is_Mul:
        args = [array_ops_first(a, scalars) for a in e.args]
        sc = [a for a in args if _is_scalar(a, scalars)]
        ar = [a for a in args if not _is_scalar(a, scalars)]
        head = [sp.Mul(*sc)] if len(sc) > 1 and ar else sc
        return sp.Mul(*head, *ar, evaluate=False)
    if e.is_Add:
        return _sum(list(e.args), scalars)
    return e.func(*[array_ops_first(a, scalars) for a in e.args])


def _sum(terms, scalars):
    counts = Counter(f for t in terms for f in set(_array_factors(t, scalars)))
    common = [(-k, sp.default_sort_key(f), f) for f, k in counts.items() if k > 1]
    if common:
        f = min(common, key=lambda c: c[:2])[2]
        inner = []
        for t in terms:
            args = list(sp.Mul.make_args(t))
            if f in args:
                args.remove(f)
                inner.append(sp.Mul(*args))
        rest = [array_ops_first(t, scalars) for t in terms if f not in sp.Mul.make_args(t)]
        out = rest + [sp.Mul(array_ops_first(f, scalars), _sum(inner, scalars), evaluate=False)]
    else:
        out = [array_ops_first(t, scalars) for t in terms]
    out.sort(key=lambda t: t.could_extract_minus_sign())  # stable: positive terms first
    return sp.Add(*out, evaluate=False)


@dataclass(frozen=True)
class Block:
    """CSE temporaries and outputs for one generated function."""

    temps: tuple  # ((name, expr), ...)
    outputs: tuple  # (expr, ...)

    @classmethod
    def of(cls, exprs, prefix: str) -> Block:
        exprs = [sp.sympify(e) for e in exprs]
        temps, reduced = sp.cse(exprs, symbols=sp.numbered_symbols(prefix), order="canonical")
        return cls(tuple(temps), tuple(reduced))

    def uses(self, symbols) -> list[tuple[int, str]]:
        """(index, name) of the given symbols that this block's expressions mention, in order."""
        free = set()
        for _, e in self.temps:
            free |= e.free_symbols
        for e in self.outputs:
            free |= e.free_symbols
        return [(i, str(s)) for i, s in enumerate(symbols) if s in free]

    def c(self):
        return [(str(n), c_expr(e)) for n, e in self.temps], [c_expr(e) for e in self.outputs]

    def fixed(self, params) -> set:
        """``params`` and the temporaries made of them alone (or of earlier such temporaries)."""
        fixed = set(params)
        for n, e in self.temps:
            if e.free_symbols <= fixed:
                fixed.add(n)
        return fixed

    def c_hoisted(self, params) -> tuple[list, list]:
        """The temporaries printed for C in two lists: those made of ``params`` alone
        (:meth:`fixed`), then the others, each list in the CSE's order. A loop over samples
        computes the first list once: the same expressions, the same bits."""
        fixed = self.fixed(params)
        return ([(str(n), c_expr(e)) for n, e in self.temps if n in fixed],
                [(str(n), c_expr(e)) for n, e in self.temps if n not in fixed])

    def uses_time(self) -> bool:
        """Whether an expression of the block mentions the time ``t``."""
        return any(str(s) == "t" for _, e in self.temps for s in e.free_symbols) or any(
            str(s) == "t" for e in self.outputs for s in e.free_symbols)

    def numpy(self, params=()):
        """Printed for NumPy, the parameters (and temporaries made of them alone) scalars."""
        scalars = frozenset(self.fixed(params))
        return ([(str(n), np_expr(e, scalars)) for n, e in self.temps],
                [np_expr(e, scalars) for e in self.outputs])


def _flatten_observables(obs: dict):
    names, exprs = [], []
    for key, val in obs.items():
        if isinstance(val, (tuple, list)):
            suffix = ("x", "y", "z") if key == "axis" else ("1", "2", "3")
            for s, v in zip(suffix, val):
                names.append(f"{key}_{s}" if key == "axis" else f"{key}{s}")
                exprs.append(v)
        else:
            names.append(key)
            exprs.append(val)
    return names, exprs


#: Weights of the operation kinds in a right-hand side's cost (roughly cycles on a current
#: x86-64 core: a libm call costs about ten additions). Only the ranking of formulations by it
#: matters (``auto`` tries the cheapest applicable one first).
OP_WEIGHTS = {"SIN": 12, "COS": 12, "TAN": 15, "ATAN2": 20, "ATAN": 15, "ACOS": 12, "EXP": 12,
              "LOG": 12, "SQRT": 6, "POW": 10, "DIV": 4}


#: What one right-hand side evaluation costs the stepper per state component (DOP853 combines
#: about a dozen stage vectors per stage, a multiply and an add each, and its error estimate
#: and dense output a few more), in the same units as OP_WEIGHTS.
STEP_COST_PER_STATE = 20


def operation_cost(block: "Block") -> int:
    """Σ weight × count over the operations of a block's temporaries and outputs (additions,
    multiplications and negations weigh 1; piecewise branches are counted once each)."""
    total = 0
    for e in [e for _, e in block.temps] + list(block.outputs):
        for op, n in _op_counts(e).items():
            total += OP_WEIGHTS.get(op, 1) * n
    return total


def _op_counts(expr) -> dict:
    counts = sp.count_ops(expr, visual=True)
    out: dict = {}
    for term in sp.Add.make_args(counts):
        coeff, sym = term.as_coeff_Mul()
        if sym.is_Symbol:
            out[str(sym)] = out.get(str(sym), 0) + int(coeff)
    return out


def sequential(init_params, params) -> list:
    """The derived parameters' expressions with earlier derived parameters substituted, so each
    depends on the inputs and the given parameters alone."""
    done: dict = {}
    out = []
    for index, expr in init_params:
        e = sp.sympify(expr).subs(done)
        done[params[index]] = e
        out.append((index, e))
    return out


@dataclass(frozen=True)
class KernelSpec:
    model: Model
    rhs: Block
    jac: Block
    obs: Block
    observable_names: tuple
    init: Block
    init_param_index: tuple
    checks: Block | None = None
    check_names: tuple = ()
    # output 1 (β) alone, where the outputs start with the z-y-z angles: what a search for β's
    # extrema evaluates many times a turning point (the sweeps' measures), without the rest
    beta: Block | None = None

    @classmethod
    def of(cls, model: Model) -> KernelSpec:
        names, exprs = _flatten_observables(model.outputs)
        # The domain expressions share the CSE of rhs and Jacobian (they reuse sin β, |q|², ...).
        dom = list(model.domain)
        derived = sequential(model.init_params, model.params)
        init = Block.of(list(model.init) + [e for _, e in derived], "x")
        checks = Block.of(list(model.checks.values()), "x") if model.checks else None
        beta = Block.of([exprs[1]], "x") if tuple(names[:3]) == ("alpha", "beta", "gamma") else None
        return cls(model, Block.of(dom + list(model.rhs), "x"), Block.of(dom + list(model.jacobian), "x"),
                   Block.of(exprs, "x"), tuple(names), init, tuple(i for i, _ in derived),
                   checks, tuple(model.checks), beta)

    @property
    def cost(self) -> int:
        """Weighted operation count of one right-hand side (domain checks included)."""
        return operation_cost(self.rhs)

    def context(self, language: str) -> dict:
        """The template context: everything a template needs, already printed."""
        m = self.model
        pr = (lambda b: b.c()) if language == "c" else (lambda b: b.numpy(m.params))
        nd = len(m.domain)
        rt, ro = pr(self.rhs)
        jt, jo = pr(self.jac)
        rg, ro, jg, jo = ro[:nd], ro[nd:], jo[:nd], jo[nd:]
        ot, oo = pr(self.obs)
        obs_once, obs_each = self.obs.c_hoisted(m.params) if language == "c" else ([], [])
        it, io = pr(self.init)
        ny = len(m.states)
        ct, co = pr(self.checks) if self.checks is not None else ([], [])
        used = {k: (b.uses(m.states), b.uses(m.params)) for k, b in
                (("rhs", self.rhs), ("jac", self.jac), ("obs", self.obs))}
        if self.checks is not None:
            used["checks"] = (self.checks.uses(m.states), self.checks.uses(m.params))
        bt, bo = pr(self.beta) if self.beta is not None else ([], [])
        if self.beta is not None:
            used["beta"] = (self.beta.uses(m.states), self.beta.uses(m.params))
        init_used = (self.init.uses(INPUTS), self.init.uses(m.params))
        return dict(
            used=used,
            name=m.name, prefix=m.name, NAME=m.name.upper(), formulation=m.formulation,
            description=m.description, effects=m.effects, symmetric=m.symmetric,
            states=m.state_names, params=m.param_names, state_symbols=[str(s) for s in m.states],
            param_symbols=[str(s) for s in m.params], ny=len(m.states), np=len(m.params),
            rhs_temps=rt, rhs_out=ro, jac_temps=jt, jac_out=jo, obs_temps=ot, obs_out=oo,
            obs_once=obs_once, obs_each=obs_each, obs_time=self.obs.uses_time(),
            observables=self.observable_names, nobs=len(self.observable_names),
            rhs_guard=rg, jac_guard=jg,
            init_used=init_used, init_temps=it, init_y=io[:ny],
            init_p=list(zip(self.init_param_index, io[ny:])),
            nin=len(INPUTS), inputs=[str(s) for s in INPUTS],
            has_angles=self.observable_names[:3] == ("alpha", "beta", "gamma"),
            check_temps=ct, check_out=co, check_names=self.check_names,
            beta_temps=bt, beta_out=bo,
            nchecks=len(self.check_names),
        )

"""Terms written by the user in a scene: ``[[potential]]`` and ``[[torque]]``, each an effect.

A term is a potential V (J) or a torque τ (N m, three components in the body or the inertial
frame) written as text (:mod:`derive.symbolic.expressions`), with named parameters::

    [[potential]]
    name = "magnet"
    V = "-mu*B*R13"
    params = { mu = 0.2, B = 1.5 }

Names an expression may use: ``R11`` … ``R33`` (R maps body to inertial components, v⁰ = R ṽ,
so ``R31 R32 R33`` is the inertial vertical in body axes), ``alpha beta gamma`` (z-y-z), the
term's params and ``pi``; a torque also ``omega1 omega2 omega3`` (body) and ``t`` (s).

Each term becomes a registry effect (:func:`effect_of`, registered by :func:`register`) keyed by
its *content*: the kind, the expressions, the frame and the parameters' names determine the
model (two scenes with the same V share it, whatever they call the term); the parameters'
values are the model's parameters. The effect's name is ``<kind>_<hash>`` and its parameters
``<effect name>_<param>``, so several terms (and the built-in M, g, l, c) never clash. The
effects contract (:mod:`derive.symbolic.effects`) is followed as for a built-in effect:

* potential(R, sym): V with R's entries, the angles of R (the symbols α, β, γ when R is the
  z-y-z matrix of the Euler-angle formulation, else atan2 forms of R's entries), the params;
* torque(ω̃, R, sym): τ̃ in body axes (an inertial torque is rotated, τ̃ = Rᵀ τ⁰);
* axisymmetric: V a rational function of R33 alone (no calls, integer powers), which is what
  the reduced formulation and the Routh bound of β need; a torque never is;
* the invariances the analysis reports (p_α, p_γ, the energy) are checked symbolically by
  :func:`derive.symbolic.symmetries.symmetries`, not read from this flag.

Nothing here imports SymPy at module level: scenes are validated on the warm path.
"""
from __future__ import annotations

import ast
import hashlib
import re
from dataclasses import dataclass

from derive.symbolic import effects as fx
from derive.symbolic import expressions as ex

#: The scene's arrays of tables for user terms, in the order they are validated.
KINDS = ("potential", "torque")
FRAMES = ("body", "inertial")

MATRIX_NAMES = tuple(f"R{i}{j}" for i in (1, 2, 3) for j in (1, 2, 3))
ANGLE_NAMES = ("alpha", "beta", "gamma")
OMEGA_NAMES = ("omega1", "omega2", "omega3")
TIME_NAME = "t"
#: What every expression of a kind may use besides its params.
BASE_NAMES = {
    "potential": MATRIX_NAMES + ANGLE_NAMES,
    "torque": MATRIX_NAMES + ANGLE_NAMES + OMEGA_NAMES + (TIME_NAME,),
}
#: Names a parameter may not take (they mean something already).
RESERVED = frozenset(BASE_NAMES["torque"]) | frozenset(ex.FUNCTIONS) | frozenset(ex.CONSTANTS)
NAME_PATTERN = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,31}")
#: Most terms of each kind in one scene, and params per term.
MAX_TERMS = 32
MAX_PARAMS = 32


@dataclass(frozen=True)
class Term:
    """A validated user term.

    Attributes
    ----------
    kind : str
        "potential" or "torque".
    name : str
        The scene's name for it (unique among the scene's terms of its kind).
    exprs : tuple of str
        (V,) or (τ₁, τ₂, τ₃), as written.
    frame : str
        "body" or "inertial" for a torque ("" for a potential).
    params : tuple of (str, float)
        The parameters, as given.
    occurrence : int
        How many terms of the scene before this one have the same content (0 for the first):
        two identical terms are two effects.
    """

    kind: str
    name: str
    exprs: tuple
    frame: str
    params: tuple
    occurrence: int = 0

    @property
    def content(self) -> tuple:
        """What determines the model: kind, expressions, frame, parameter names (sorted)."""
        return (self.kind, self.exprs, self.frame, tuple(sorted(p for p, _ in self.params)),
                self.occurrence)

    @property
    def effect(self) -> str:
        """The registry name of its effect, ``<kind>_<first 10 hex digits of the content>``."""
        digest = hashlib.sha256(repr(self.content).encode("utf-8")).hexdigest()
        return f"{self.kind}_{digest[:10]}"

    @property
    def values(self) -> dict:
        return dict(self.params)

    def model_param(self, param: str) -> str:
        """The model's name of a param (``<effect>_<param>``)."""
        return f"{self.effect}_{param}"

    def given(self) -> dict:
        """The term as a scene file gives it."""
        out = {"name": self.name}
        if self.kind == "potential":
            out["V"] = self.exprs[0]
        else:
            out["frame"] = self.frame
            out["tau"] = list(self.exprs)
        out["params"] = dict(self.params)
        return out


def names_for(kind: str, params) -> tuple:
    """The names an expression of ``kind`` with these params may use."""
    return BASE_NAMES[kind] + tuple(params)


def parse_all(term: Term) -> tuple:
    """The checked expressions of a term (ExpressionError as :func:`expressions.parse`)."""
    names = names_for(term.kind, (p for p, _ in term.params))
    return tuple(ex.parse(text, names) for text in term.exprs)


# ---------------------------------------------------------------------------------------------
# the effect of a term


_EFFECTS: dict = {}  # content -> Effect, for the terms registered in this process


def register(term: Term) -> str:
    """Register the term's effect (once per content per process) and return its name."""
    name = term.effect
    if name not in fx.REGISTRY:
        effect = _EFFECTS.get(term.content) or effect_of(term)
        _EFFECTS[term.content] = effect
        fx.register(effect)
    return name


def _rational_in_R33(parsed: ex.Parsed, params) -> bool:
    """V depends on R33 (= cos β) alone, as a rational function: no calls, integer powers."""
    if not parsed.names <= {"R33", "pi", *params}:
        return False
    for node in ast.walk(parsed.tree):
        if isinstance(node, ast.Call):
            return False
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Pow):
            e = node.right
            if isinstance(e, ast.UnaryOp) and isinstance(e.op, (ast.USub, ast.UAdd)):
                e = e.operand
            if not (isinstance(e, ast.Constant) and type(e.value) is int):
                return False
    return True


def _angles(R):
    """(α, β, γ) of R: the symbols themselves when R is the z-y-z matrix of the Euler-angle
    formulation, else the atan2 forms (:func:`derive.symbolic.rotations.zyz_angles`)."""
    from derive.symbolic.rotations import ANGLES, ZYZ, zyz_angles

    return ANGLES if R == ZYZ.matrix() else zyz_angles(R)


def _env(parsed_list, term: Term, R, sym, omega=None) -> dict:
    """Values of the names the expressions use."""
    used = set().union(*(p.names for p in parsed_list))
    env = {f"R{i + 1}{j + 1}": R[i, j] for i in range(3) for j in range(3)}
    if used & set(ANGLE_NAMES):
        env.update(zip(ANGLE_NAMES, _angles(R)))
    if omega is not None:
        env.update(zip(OMEGA_NAMES, list(omega)))
        env[TIME_NAME] = time_symbol()
    env.update({p: sym(term.model_param(p)) for p, _ in term.params})
    return env


def time_symbol():
    """The time symbol t (real): the rhs's first argument in the generated code."""
    import sympy as sp

    return sp.Symbol(TIME_NAME, real=True)


def effect_of(term: Term) -> fx.Effect:
    """The registry effect of a term (see the module docstring)."""
    parsed = parse_all(term)
    pnames = tuple(sorted(p for p, _ in term.params))
    model_params = tuple(fx.Param(term.model_param(p), (("real", True),)) for p in pnames)
    name = term.effect

    def values(v) -> dict:
        v = dict(v)
        return {term.model_param(p): float(v[p]) for p in pnames}

    if term.kind == "potential":
        def potential(R, sym):
            return ex.to_sympy(parsed[0], _env(parsed, term, R, sym))

        return fx.Effect(name, "potential", f"potential V = {term.exprs[0]}",
                         params=model_params, values=values, potential=potential,
                         axisymmetric=_rational_in_R33(parsed[0], pnames))

    def torque(omega, R, sym):
        import sympy as sp

        env = _env(parsed, term, R, sym, omega)
        tau = sp.Matrix([ex.to_sympy(p, env) for p in parsed])
        return R.T * tau if term.frame == "inertial" else tau

    return fx.Effect(name, "torque", f"{term.frame} torque tau = ({', '.join(term.exprs)})",
                     params=model_params, values=values, torque=torque)

"""A SciPy reference run: ``solve_ivp`` on the generated NumPy right-hand side (not the fast path),
with the compiled init and output maps and the scene's step budget.

Takes: a model description and the scene's numbers. Gives: the outputs, states and nfev.
"""
from __future__ import annotations

import functools
import importlib.util
from pathlib import Path

from derive.errors import IntegrationError, raise_if_signalled
from derive.methods.registry import DEFAULT_METHOD
from derive.methods.status import Status
from derive.methods.status import message as status_message
from derive.runtime.integrate import ModelKernel


def _budgeted(method: str, max_steps: int, where: list):
    """SciPy's solver class ``method`` ("RK45", "DOP853", "Radau", "LSODA", ...) with the scene's
    step budget, as the compiled drivers apply it: the step after ``max_steps`` steps fails the
    solve instead of being taken, its time is appended to ``where``. SciPy's steps cost about a
    thousand times the compiled ones (Python per step), so without it a fast top ran for minutes.
    A step is one call of the solver's ``_step_impl`` (rejected tries inside it included)."""
    from scipy import integrate

    class Budgeted(getattr(integrate, method)):
        steps = 0

        def _step_impl(self):
            raise_if_signalled()
            if self.steps >= max_steps:
                where.append(self.t)
                return False, _BUDGET_SPENT
            self.steps += 1
            return super()._step_impl()

    Budgeted.__name__ = Budgeted.__qualname__ = f"Budgeted{method}"
    return Budgeted


_BUDGET_SPENT = "step budget spent"


def _solve_scipy(desc, method, inputs, p, t, sc):
    """SciPy's solve_ivp on the generated NumPy right-hand side (a reference, not the fast
    path): the compiled init map gives y0, the compiled output map the outputs. The step budget
    ``max_steps`` holds as for the compiled methods (exit 3 when spent)."""
    from scipy.integrate import solve_ivp

    kernel = ModelKernel.load(desc, DEFAULT_METHOD)  # for its init and output maps
    y0, p, rc = kernel.init(inputs, p)  # p: a copy with the derived parameters written
    if rc:
        raise IntegrationError(f"t = {t[0]:.6g}: the initial state is not finite")
    mod = _numpy_module(desc.folder, desc.name)
    s = sc.simulate
    spent: list = []
    sol = solve_ivp(mod.rhs, (t[0], t[-1]), y0, method=_budgeted(method, s.max_steps, spent),
                    t_eval=t, rtol=s.rtol, atol=s.atol, args=(p,),
                    **({"jac": mod.jac} if method in ("Radau", "BDF", "LSODA") else {}))
    if spent:
        raise IntegrationError(status_message({"status": int(Status.MAX_STEPS), "t_fail": spent[0]},
                                              max_steps=s.max_steps))
    if not sol.success:
        raise IntegrationError(f"t = {sol.t[-1] if sol.t.size else t[0]:.6g}: scipy {method}: {sol.message}")
    y = sol.y.T.copy()
    return kernel.outputs_at(t, y, p), y, p, sol.nfev


@functools.lru_cache(maxsize=None)
def _numpy_module(folder: str, name: str):
    """The generated NumPy module of the model ``name`` in ``folder`` (imported from its file)."""
    spec = importlib.util.spec_from_file_location(f"derive_generated_{name}",
                                                  Path(folder) / "numpy" / f"{name}.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod

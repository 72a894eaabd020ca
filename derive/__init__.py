"""derive: rigid-body rotation, derived symbolically, checked against a lecture, compiled to C.

Conventions throughout: z-y-z Euler angles in the quantum-mechanics convention of the notes
(α about the inertial z axis, β about the intermediate y′ axis, γ about the body 3 axis); the
rotation matrix R = Rz(α) Ry(β) Rz(γ) maps body components to inertial components
(v_inertial = R v_body); ω̃ are body-frame components; SI units.

The public API is this module: :func:`simulate`, :func:`prepare`, :func:`simulate_batch`,
:func:`sweep`, :func:`analyze` and the errors :class:`SceneError`, :class:`IntegrationError`,
:class:`CompilerError`. The stages behind it are subpackages (``derive.symbolic``,
``derive.methods``, ``derive.codegen``, ``derive.runtime``, ``derive.sim``, ``derive.sweeps``,
``derive.lecture``), each saying in its docstring what it takes, gives and may import.

Each entry point here imports its stage when first called, not at ``import derive``: a stage
brings NumPy, compiled libraries or SymPy, which ``derive --help`` and a program that only
imports the package do not pay for. The functions here are the documented face (signatures,
docstrings, examples); the stages' own functions take the normalised arguments.
"""
from derive.errors import CompilerError, IntegrationError, SceneError
from derive.sim.saveat import SaveAt, choose as _choose

#: The one place the version is written (pyproject.toml reads it; `derive --version` prints it).
__version__ = "0.1.0"
DISTRIBUTION = "derive-rigid-body"
"""The name on the package index (``pip install derive-rigid-body``): a plain ``derive`` there is an
unrelated project. The import and the command stay ``derive``."""

__all__ = ["SceneError", "IntegrationError", "CompilerError", "SaveAt", "simulate", "simulate_batch",
           "sweep", "analyze", "prepare"]


def simulate(scene, *, saveat=None, **overrides):
    """Simulate one scene: derive (or load) its model, integrate it in one C call, return the arrays.

    Parameters
    ----------
    scene : str, os.PathLike, dict or Scene
        A scene file (TOML), the name of a shipped example (``"looping_top"``; ``derive
        examples`` lists them), or a dict shaped like the TOML (tables ``body``, optional
        ``gravity`` and ``damping``, ``initial``, optional ``simulate``).
    saveat : SaveAt, optional
        What to keep: ``SaveAt(t="final")`` every array at t_end alone (length 1 along time),
        ``SaveAt(outputs=("beta", …))`` only those outputs (the others None). Default: every
        output at every sample.
    **overrides
        Keys of the ``[simulate]`` table that replace the scene's: ``method``, ``rtol``,
        ``atol``, ``formulation``, ``h``, ``max_steps``, ``t_end``, ``samples``. ``None`` means
        "not given".

    Returns
    -------
    derive.sim.result.Result
        The arrays of the output file as attributes: ``t`` (n,), the z-y-z angles ``alpha``,
        ``beta`` (in [0, π]), ``gamma`` (α, γ continuous, not wrapped), ``omega`` (n, 3, body
        frame ω̃), ``axis`` (n, 3, inertial components of body axis ê₃), ``energy`` (T + V),
        ``p_alpha`` and ``p_gamma`` (conserved only without damping), ``n`` (the upward vertical
        in body axes) and ``L`` (angular momentum about the pivot, body axes); ``integrals``
        ({name: (n,) array}, the extra integral of an integrable case, also as
        ``integral_<name>``); ``method``, ``formulation`` and ``nfev`` (what ran). The
        integrals carry the names ``derive analyze`` gives them: ``L_squared`` (``|L|²``, free
        body), ``L_1``/``L_2``/``L_3`` (the component of L along the symmetry axis of a Lagrange
        top), ``L_dot_rc`` (spherical body), ``kovalevskaya``, ``goryachev_chaplygin`` (only
        for a state on L·n = 0).

    Raises
    ------
    SceneError
        Bad input (a ``ValueError``), with the command line's one-line message
        ``<file>: <key>: <what is wrong>``.
    IntegrationError
        Numerical failure (step size underflow, non-finite state, step budget spent), saying
        where (time, quantity).
    CompilerError
        No working C compiler for a model that must be compiled first.

    Examples
    --------
    >>> import derive
    >>> res = derive.simulate("looping_top", t_end=0.5, samples=6)
    >>> res.t.shape, res.omega.shape
    ((6,), (6, 3))
    >>> bool(abs(res.energy[-1] - res.energy[0]) < 1e-9 * abs(res.energy[0]))
    True

    A second call with the same model reuses the compiled kernel (no derivation, no compile).
    """
    from derive.sim.simulation import simulate as _simulate

    return _simulate(scene, _choose(saveat), **overrides)


def prepare(scene, **overrides):
    """Validate, plan and compile a scene once, to run it many times cheaply.

    Parameters
    ----------
    scene : str, os.PathLike, dict or Scene
        As for :func:`simulate`.
    **overrides
        ``[simulate]`` keys, as for :func:`simulate`.

    Returns
    -------
    derive.sim.prepared.Prepared
        ``run()`` gives the :class:`~derive.sim.result.Result` :func:`simulate` would, with
        no validation, look-up or derivation per call; ``run(initial={...}, params={...})``
        reruns with new initial values or parameters of the same shape.

    Raises
    ------
    SceneError
        Bad input.
    CompilerError
        No working C compiler for a model that must be compiled first.

    Examples
    --------
    >>> import derive
    >>> top = derive.prepare("looping_top", t_end=0.5, samples=6)
    >>> a, b = top.run(), top.run(initial={"beta": 0.6})
    >>> round(float(a.beta[0]), 3), round(float(b.beta[0]), 3)
    (0.5, 0.6)
    """
    from derive.sim.prepared import prepare as _prepare

    return _prepare(scene, **overrides)


def simulate_batch(scenes, outputs=None, *, saveat=None, **overrides):
    """Simulate many scenes that differ only in numbers, with one call into C for all of them.

    Parameters
    ----------
    scenes : sequence of str, dict or Scene
        Scenes as :func:`simulate` takes them. They must name the same effects, body symmetry,
        output times, method and tolerances; the moments, effect parameters and initial states
        may differ.
    saveat : SaveAt, optional
        What to keep. The default (every output at every sample): one Result per scene.
        ``SaveAt(t="final")``: every output (and ``state``) at the last sample only;
        ``SaveAt(outputs=("beta", "axis", …, "state"))``: those at every sample (with
        ``t="final"``, at the last). Any selection gives one
        :class:`~derive.sim.batch.BatchResult` with arrays stacked along a first axis of
        length N, bit for bit the numbers of the full batch, and only those arrays allocated
        (the compiled loop runs in chunks whose work arrays are reused): 1000 trajectories of
        1001 samples keep 1000 final states instead of mapping ~200 MB. With ``"final"``, a
        formulation whose α and γ are states and an adaptive method, each trajectory is
        integrated straight to the end (the same steps; no interior sample is made; ``nfev``
        then counts no dense-output evaluations), and a Taylor method runs several
        trajectories at once in SIMD lanes (``BatchResult.driver`` says which driver ran).
        The integrals of the integrable cases are not computed (they are functions of ``L``
        and ``n``).
    outputs : None, "final" or sequence of str, optional
        The short spelling of ``saveat`` (:meth:`SaveAt.of`): ``"final"`` is
        ``SaveAt(t="final")``, names are ``SaveAt(outputs=names)``; give one of the two.
    **overrides
        ``[simulate]`` keys applied to every scene, as in :func:`simulate`.

    Returns
    -------
    list of derive.sim.result.Result, or derive.sim.batch.BatchResult
        Without ``outputs``: one result per scene, in order, each as :func:`simulate` would
        give it. With ``outputs``: one BatchResult (None for no scenes). With
        ``formulation = "auto"`` the scenes share one formulation.

    Raises
    ------
    SceneError
        Bad input, or scenes that do not share a model.
    IntegrationError
        A trajectory failed (the message names which).

    Examples
    --------
    >>> import derive
    >>> base = {"body": {"I1": 1.0, "I3": 0.5}, "gravity": {"M": 1.0, "g": 1.0, "l": 1.0},
    ...         "simulate": {"t_end": 1.0, "samples": 3}}
    >>> def start(beta):
    ...     return {"alpha": 0.0, "beta": beta, "gamma": 0.0,
    ...             "alpha_dot": 0.0, "beta_dot": 0.0, "gamma_dot": 6.0}
    >>> runs = derive.simulate_batch([{**base, "initial": start(b)} for b in (0.3, 0.6)])
    >>> [round(float(r.beta[0]), 3) for r in runs]
    [0.3, 0.6]
    >>> ends = derive.simulate_batch([{**base, "initial": start(b)} for b in (0.3, 0.6)], outputs="final")
    >>> ends.beta.shape, ends.omega.shape, bool(ends.beta[1] == runs[1].beta[-1])
    ((2,), (2, 3), True)
    """
    from derive.sim.batch import simulate_batch as _batch

    return _batch(scenes, _choose(saveat, outputs), **overrides)


def sweep(spec, *, workers=None, scheduler=None, progress=None, saveat=None, **kwargs):
    """Run a parameter sweep: many points of one scene, each measured while it is integrated.

    Parameters
    ----------
    spec : str, os.PathLike or dict
        A sweep file (TOML), the name of a shipped example sweep (``"sleeping_threshold"``), or
        a dict shaped like one: ``scene`` (a path relative to the sweep file, or an inline
        scene table), ``vary`` (dotted scene keys → ``{from, to, num}`` or ``{values}``, the
        Cartesian product, first key slowest) or ``random`` (``n``, ``seed``, ``{low, high}``
        per key), and ``measures`` (``beta_max``, ``beta_min``, ``energy_drift``, ``nfev``,
        ``flips``, …).
    workers : int, optional
        Start a Dask ``LocalCluster`` with that many worker processes.
    scheduler : str, optional
        The address of a running Dask scheduler (``tcp://host:port``).
    progress : bool, optional
        A progress bar on stderr (default: when stderr is a terminal).
    saveat : SaveAt, optional
        A sweep keeps t_end only: ``SaveAt(t="final")`` (with ``outputs`` among ``alpha``,
        ``beta``, ``gamma``, ``omega``) adds the ``final_state`` measure's columns.
    **kwargs
        ``processes`` (the local engine's process count, default one per core) and
        ``add_measure`` (a measure added to the spec's list).

    Returns
    -------
    derive.sweeps.result.SweepResult
        ``params`` and ``measures`` ({name: (N,) array}, one entry per point), ``status``
        ((N,) str: "ok" or why the point failed) and ``to_pandas()``. The numbers are the same
        whichever engine ran them.

    Raises
    ------
    SceneError
        A bad sweep or scene (one line naming the key).
    IntegrationError
        The engine failed as a whole (a single point's failure is recorded in ``status``).

    Examples
    --------
    >>> import derive
    >>> spec = {"scene": {"body": {"I1": 1.0, "I3": 0.5}, "gravity": {"M": 1.0, "g": 1.0, "l": 1.0},
    ...                   "initial": {"alpha": 0.0, "beta": 0.5, "gamma": 0.0, "alpha_dot": 0.0,
    ...                               "beta_dot": 0.0, "gamma_dot": 6.0},
    ...                   "simulate": {"t_end": 1.0}},
    ...         "vary": {"initial": {"beta": {"from": 0.3, "to": 0.6, "num": 4}}},
    ...         "measures": ["beta_max", "nfev"]}
    >>> res = derive.sweep(spec, processes=1)
    >>> res.measures["beta_max"].shape
    (4,)
    """
    from derive.sweeps.engine import sweep as _sweep

    return _sweep(spec, workers=workers, scheduler=scheduler, progress=progress,
                  saveat=None if saveat is None else _choose(saveat), **kwargs)


def analyze(scene):
    """The lecture's analysis for a scene's own body, evaluated at the scene's numbers.

    Derives T, V, the equations of motion, the cyclic coordinates and conserved momenta, the
    integrable case (Euler, Lagrange, Kovalevskaya, Goryachev–Chaplygin or general) with its
    integrals, and the relative equilibria (sleeping, hanging, steady precession, permanent
    rotations) with their linearisation and a stability verdict.

    Parameters
    ----------
    scene : str, os.PathLike, dict or Scene
        As for :func:`simulate`.

    Returns
    -------
    derive.lecture.analysis.Analysis
        ``to_json()`` gives ``{"case", "integrals", "equilibria", …}`` (docs/analyze.md);
        ``to_markdown()`` the report ``derive analyze`` prints.

    Raises
    ------
    SceneError
        Bad input.
    IntegrationError
        A verdict that cannot be evaluated in double precision (numbers out of range).

    Examples
    --------
    >>> import derive
    >>> derive.analyze("sleeping_top").to_json()["case"]
    'lagrange'
    """
    from derive.lecture.analysis import analyze as _analyze

    return _analyze(scene)

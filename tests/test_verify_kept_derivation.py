"""A convention's derived quantities are kept in the compile cache between `derive verify`
commands: a later command reads them instead of deriving them, its verdicts are those of a
command that derived everything, and a damaged, foreign or stale entry is ignored and written
again. The kept values are rebuilt by a whitelist of SymPy classes, equal argument for argument
to the derived ones."""
import json
import subprocess
import sys

import pytest
import sympy as sp

from derive.lecture import derivation as dv
from derive.lecture import derivation_kept as kept
from derive.lecture import notes_check as nc
from derive.runtime import cache as cache_folder

#: A short text in z-x-z: a Lagrangian in the angles, a momentum, Euler's equation, the energy.
TEXT = r"""---
convention: z-x-z
angles: [\phi, \theta, \psi]
---
# The heavy symmetric top

$$L = \frac{1}{2} I_1 (\dot\theta^2 + \dot\phi^2 \sin^2\theta) + \frac{1}{2} I_3 (\dot\psi + \dot\phi\cos\theta)^2 - M g l \cos\theta$$

$$p_\psi = I_3 (\dot\psi + \dot\phi \cos\theta)$$

$$p_\phi = I_1 \dot\phi \sin^2\theta + I_3 (\dot\psi + \dot\phi\cos\theta) \cos\theta$$

$$I_1 \dot{\omega}_1 = (I_2 - I_3) \omega_2 \omega_3$$

$$I_1 \ddot\theta = I_1 \dot\phi^2 \sin\theta\cos\theta - I_3 (\dot\psi + \dot\phi\cos\theta) \dot\phi \sin\theta + M g l \sin\theta$$
"""


@pytest.fixture
def fresh(tmp_path, monkeypatch):
    """An empty cache in ``tmp_path``, and ``command()``: check TEXT as a fresh process would
    (no derivation in memory), counting the heavy tops derived."""
    monkeypatch.setenv("DERIVE_CACHE", str(tmp_path))
    derived = []
    real = dv.heavy_symmetric_top

    def counting(conv):
        derived.append(conv.name)
        return real(conv)

    monkeypatch.setattr(dv, "heavy_symmetric_top", counting)

    def command():
        dv.derivation.cache_clear()
        dv._loaded.clear()
        return [c.as_dict() for c in nc.check_text(TEXT)]

    yield command, derived, tmp_path / cache_folder.MODELS
    dv.derivation.cache_clear()
    dv._loaded.clear()


def _folder(models):
    (folder,) = [f for f in models.iterdir() if f.name.startswith(kept.PREFIX)]
    return folder


def test_a_second_command_reads_the_kept_derivation_and_gives_the_same_verdicts(fresh):
    command, derived, models = fresh
    first = command()
    assert derived == ["zxz"] and any(c["verdict"] == "holds" for c in first)
    folder = _folder(models)
    assert folder.name == f"{kept.PREFIX}zxz-{kept.source_key()[:24]}" and cache_folder.is_marked(folder)
    assert command() == first and derived == ["zxz"]  # the top was read, not derived


def test_a_damaged_kept_derivation_is_derived_again_and_healed(fresh, capsys):
    command, derived, models = fresh
    first = command()
    data = _folder(models) / kept.FILE
    data.write_text(data.read_text().replace("beta", "betb"))  # no longer matches its manifest
    assert command() == first and len(derived) == 2
    assert capsys.readouterr().err == (f"note: kept derivation {data.parent} has a damaged {kept.FILE} "
                                       "(it does not match its checksum); deriving it again\n")
    assert command() == first and len(derived) == 2  # healed: written again and read back
    assert capsys.readouterr().err == ""


@pytest.mark.parametrize("change", [
    lambda d: d.update(convention="zyz"),
    lambda d: d.update(key="0" * 64),
    lambda d: d["values"].update({"top.lagrangian": ["__import__", [["symbol", "os", {}]]]}),
    lambda d: d["values"].update({"top.lagrangian": ["rational", 1, "2"]}),
])
def test_a_kept_derivation_of_another_convention_key_or_form_is_not_read(tmp_path, monkeypatch, capsys, change):
    monkeypatch.setenv("DERIVE_CACHE", str(tmp_path))
    d = dv.Derivation("z-x-z")
    kept.write("zxz", {"top.lagrangian": d.top.lagrangian})
    assert kept.read("zxz") == ({"top.lagrangian": d.top.lagrangian}, {"top.lagrangian"})
    folder = _folder(tmp_path / cache_folder.MODELS)
    data = json.loads((folder / kept.FILE).read_text())
    change(data)
    cache_folder.write_folder(folder, {kept.FILE: json.dumps(data)}, kept.FILE, replace=True)
    assert kept.read("zxz") == ({}, set())
    assert capsys.readouterr().err.startswith(f"note: kept derivation {folder} ")


def test_every_derived_quantity_is_kept_as_derived():
    d = dv.Derivation("z-x-z")
    computed = (d.omega, d.frames, d.top.energy, d.top.accelerations, d.reduction.rates_from_momenta,
                d.reduction.effective_potential, d.reduction.beta_acceleration, d.sleeping.condition,
                d.kinetic, d.spin_frequencies)
    assert d.along.ok
    assert "along.rates" not in d.derived()          # the rates are derived on a relation with rates
    d.along.rates
    values = d.derived()
    assert all(any(v is c for v in values.values()) for c in computed)
    assert values["along.trig"] == d.along.trig and values["along.rates"] == d.along.rates
    assert {"d.omega", "top.lagrangian", "reduction.beta_acceleration", "sleeping.condition",
            "along.trig", "along.rates"} <= set(values)
    for path, value in values.items():
        back = kept.decode(json.loads(json.dumps(kept.encode(value))))
        assert type(back) is type(value) and back == value and sp.srepr(back) == sp.srepr(value), path
    again = dv.Derivation("z-x-z")
    again.seed({path: kept.decode(kept.encode(v)) for path, v in values.items()})
    assert again.derived().keys() == values.keys()
    assert again.top.accelerations == d.top.accelerations and again.sleeping.condition == d.sleeping.condition
    assert again.along.ok and again.along.trig == d.along.trig and again.along.rates == d.along.rates
    without_rates = dv.Derivation("z-x-z")
    without_rates.seed({"along.trig": kept.decode(kept.encode(d.along.trig))})
    assert "rates" not in vars(without_rates.along) and without_rates.along.rates == d.along.rates
    assert not dv.Derivation("z-y-x").along.ok  # a Tait–Bryan sequence: kept as not applying
    tait_bryan = dv.Derivation("z-y-x")
    tait_bryan.seed({"along.trig": kept.decode(kept.encode(None))})
    assert "along" in vars(tait_bryan) and not tait_bryan.along.ok


def test_the_momenta_the_fast_tops_precession_and_lagranges_residuals_are_kept_as_derived():
    from derive.lecture.fast_top import slow_precession_lead

    d = dv.Derivation("z-x-z")
    assert d.momenta == {q: d.top.momentum(q) for q in dv.rot.ANGLES}
    assert d.fast_precession is not None
    assert d.fast_precession == slow_precession_lead(d.steady_force, dv.rot.alpha_d, dv.rot.gamma_d)
    assert d.residuals(d.top.lagrangian) == dv.lagrange_residuals(d.top.lagrangian) == d.top_residuals
    assert d.residuals(d.kinetic) is d.kinetic_residuals
    other = d.kinetic.xreplace({dv.I2: dv.I1})                      # any other Lagrangian: derived
    assert d.residuals(other) == dv.lagrange_residuals(other) != d.kinetic_residuals
    values = d.derived()
    assert {"d.momenta", "d.fast_precession", "d.top_residuals", "d.kinetic_residuals"} <= set(values)
    again = dv.Derivation("z-x-z")
    again.seed({path: kept.decode(json.loads(json.dumps(kept.encode(v)))) for path, v in values.items()})
    for name in ("momenta", "fast_precession", "top_residuals", "kinetic_residuals"):
        assert name in vars(again) and sp.srepr(getattr(again, name)) == sp.srepr(getattr(d, name)), name
    assert again.residuals(again.top.lagrangian) is again.top_residuals


def test_a_value_outside_the_whitelist_is_left_out(tmp_path, monkeypatch):
    monkeypatch.setenv("DERIVE_CACHE", str(tmp_path))
    t = sp.Symbol("t")
    with pytest.raises(kept.NotKept):
        kept.encode(sp.Function("f")(t))
    kept.write("zyz", {"d.omega": sp.Matrix([t, 1, sp.Rational(1, 2)]), "d.kinetic": sp.Function("f")(t)})
    # Known as left out: a later command does not write it again.
    assert kept.read("zyz") == ({"d.omega": sp.Matrix([t, 1, sp.Rational(1, 2)])}, {"d.omega", "d.kinetic"})


def test_the_kept_derivation_grows_and_the_cache_clears_it(tmp_path, monkeypatch):
    monkeypatch.setenv("DERIVE_CACHE", str(tmp_path))
    x = sp.Symbol("x", positive=True)
    kept.write("zxz", {"d.omega": sp.Matrix([x])})
    kept.write("zxz", {"d.omega": sp.Matrix([x]), "d.kinetic": x**2 / 2})
    assert kept.read("zxz")[0] == {"d.omega": sp.Matrix([x]), "d.kinetic": x**2 / 2}
    assert kept.decode(kept.encode(x)) is x
    cache_folder.clear_cache(tmp_path)
    assert not tmp_path.exists() or not list(tmp_path.rglob(kept.FILE))


def test_derive_verify_starts_without_the_registries_only_other_commands_list():
    code = ("import sys, contextlib, io\nfrom derive import cli\n"
            "with contextlib.redirect_stdout(io.StringIO()) as out:\n    cli.main(['verify', '--help'])\n"
            "assert '--convention' in out.getvalue()\n"
            "print(sorted({'derive.sim.scene', 'derive.sweeps.measures', 'derive.methods.registry'} & set(sys.modules)))\n"
            "with contextlib.redirect_stdout(io.StringIO()) as out:\n    cli.main(['simulate', '--help'])\n"
            "print('rk4' in out.getvalue())\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert done.stdout.splitlines() == ["[]", "True"]

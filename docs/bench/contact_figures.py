"""The figures of docs/contact.md: run from the checkout root with `python docs/bench/contact_figures.py`
(the independent references are the ones tests/test_contact.py defines)."""
import sys

sys.path.insert(0, "tests")
import numpy as np
from test_contact import read_example, run_scene, _scene, TIPPE, _frictionless_reference, _newton_euler_inertial
from scipy.interpolate import CubicSpline
rel = lambda v: float(np.max(np.abs(v - v[0])) / abs(v[0]))
T = _frictionless_reference()[1]
for n, rt, at in ((100, 1e-13, 1e-15), (1000, 2.2e-14, 1e-17), (10000, 2.2e-14, 1e-17)):
    r = run_scene(read_example("frictionless_top"), t_end=n * T, samples=2001, rtol=rt, atol=at, max_steps=10**8)
    print(f"frictionless {n} nutations rtol {rt}: E {rel(r.energy):.1e} p_alpha {rel(r.p_alpha):.1e} p_gamma {rel(r.p_gamma):.1e}")
r = run_scene(read_example("rolling_sphere"))
print("rolling sphere 5 s: E %.1e J %.1e Routh %.1e" % (rel(r.energy), rel(r.integrals["jellett"]), rel(r.integrals["routh"])))
exp = 180 * (0.2 - np.cos(0.1)) / 1.2
for name, c, t_end in (("viscous", {"friction": "viscous"}, 4.0), ("regularised 1e-2", {"regularization": 1e-2}, 13.0)):
    r = run_scene(_scene(TIPPE, contact=c, simulate={"t_end": t_end, "samples": 4001}))
    i = np.where(r.beta > np.pi - 0.02)[0][0]
    print(f"tippe {name}: within 0.02 of pi at t={r.t[i]:.3f}, w3={r.omega[i,2]:.4f}, rel {abs(r.omega[i,2]-exp)/abs(exp):.1e}; J {rel(r.integrals['jellett']):.1e}")
r = run_scene(_scene(TIPPE, contact={"regularization": 1e-2}, simulate={"t_end": 1.2, "samples": 24001, "rtol": 1e-12, "atol": 1e-14}))
i = int(np.argmax(r.beta > np.pi / 2)); sl = slice(i - 4, i + 4)
t90 = float(CubicSpline(r.t[sl], np.cos(r.beta[sl])).solve(0.0, extrapolate=False)[0]); ref = _newton_euler_inertial(1e-2, 1.2)
print(f"t90 ours {t90:.12f} independent {ref:.12f} rel {abs(t90-ref)/ref:.1e}")
a, b = (run_scene(_scene(TIPPE, simulate={"t_end": 10.0, "samples": 1001, "rtol": rt, "atol": rt * 1e-2})) for rt in (1e-9, 1e-10))
print("exact coulomb: switches", [(round(s.t, 6), s.event) for s in b.switches], "J %.1e" % rel(b.integrals["jellett"]),
      "stick dt rel %.1e beta_end rel %.1e" % (abs(a.switches[0].t-b.switches[0].t)/b.switches[0].t, abs(a.beta[-1]-b.beta[-1])/b.beta[-1]), "beta end", b.beta[-1])

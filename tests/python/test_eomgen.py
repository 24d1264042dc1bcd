"""The Python module against the command line, closed forms and the symbolic equations (docs/python.md).

Run by ctest (python:pytest) with PYTHONPATH naming the built package, EOMGEN the eomgen executable and
XDG_CACHE_HOME a cache of its own."""

import csv
import io
import math
import os
import subprocess
import threading

import numpy as np
import pytest

import eomgen

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MODELS = os.path.join(ROOT, "models")
EOMGEN = os.environ.get("EOMGEN")


def model_path(name):
    return os.path.join(MODELS, name + ".toml")


@pytest.fixture(scope="module")
def door():
    return eomgen.load(model_path("door"))


@pytest.fixture(scope="module")
def pendulum():
    return eomgen.load(model_path("pendulum"))


def eomgen_run_csv(tmp_path, model, *options):
    """`eomgen run MODEL --csv FILE OPTIONS` read back: the header and an (N, columns) array of every value."""
    if not EOMGEN:
        pytest.skip("EOMGEN names no eomgen executable")
    out = tmp_path / "run.csv"
    subprocess.run([EOMGEN, "run", model, "--quiet", "--csv", str(out), *options], check=True,
                   stdout=subprocess.DEVNULL)
    with open(out) as f:
        rows = list(csv.reader(f))
    return rows[0], np.array([[float(v) for v in r] for r in rows[1:]])


def test_load_reads_the_model_file(door):
    assert door.name == "door"
    assert door.title == "Closing tilted door"
    assert door.coordinates == ["psi"]
    assert door.parameters == {"m": 30.0, "w": 0.9, "h": 2.0, "g": 9.8, "theta": 0.0234}
    assert door.outputs == ["z_c", "v_edge"]
    assert door.units["psi"] == "rad" and door.units["g"] == "m/s^2"
    np.testing.assert_array_equal(door.initial_state, [0.0, 0.0])
    assert "door" in repr(door)


def test_simulate_equals_eomgen_run_to_the_last_bit(door, tmp_path):
    sol = door.simulate(1.0, samples=50, set={"theta": 0.1})
    header, run = eomgen_run_csv(tmp_path, model_path("door"), "--t-end", "1", "--samples", "50", "--set",
                                 "theta=0.1")
    names = [h.split(" [")[0] for h in header]
    assert names == sol.names
    assert [n + (" [" + sol.units[n] + "]" if sol.units[n] else "") for n in names] == header
    assert run.shape == (51, len(names))
    np.testing.assert_array_equal(sol.to_array(), run)  # every bit: the same compiled code, driver and options


def test_the_door_closes_when_the_closed_form_says(door):
    theta, w, g = 0.0234, 0.9, 9.8
    sol = door.simulate(10.0, until="psi=-pi/2")
    assert sol.stopped_by is not None and "psi" in sol.stopped_by
    closed = math.sqrt(w / (3 * g * math.sin(theta))) * math.gamma(0.25) * math.sqrt(math.pi) / (2 * math.gamma(0.75))
    assert sol.t_final == pytest.approx(closed, rel=1e-9)
    assert sol.t[-1] <= sol.t_final
    # The energy is conserved along the way, and the outputs are the model file's expressions.
    assert np.max(np.abs(sol.energy - sol.energy[0])) < 1e-9 * abs(sol.energy[0])
    np.testing.assert_allclose(sol.outputs["v_edge"], w * sol["psi_dot"], rtol=1e-15)
    np.testing.assert_allclose(sol["z_c"], (w * math.sin(theta) * np.sin(sol["psi"]) + 2.0 * math.cos(theta)) / 2,
                               rtol=1e-14)


def test_sensitivities_equal_eomgen_run_and_the_closed_form(door, tmp_path):
    sol = door.simulate(100.0, until="psi=-pi/2", sensitivities=["theta", "w", "x0:psi"])
    assert sol.sensitivity_names == ["theta", "w", "psi(0)"] and sol.S.shape == (len(sol), 2, 3)
    # The closing time T = c sqrt(w / (g sin theta)): dT/dtheta = -T cot(theta)/2, dT/dw = T/(2w).
    T, theta, w = sol.t_final, 0.0234, 0.9
    dt = sol.event_dt["psi=-pi/2"]
    assert dt[0] == pytest.approx(-T / (2 * math.tan(theta)), rel=1e-9)
    assert dt[1] == pytest.approx(T / (2 * w), rel=1e-9)
    header, run = eomgen_run_csv(tmp_path, model_path("door"), "--t-end", "100", "--until", "psi=-pi/2",
                                 "--sensitivities", "theta,w,x0:psi")
    columns = {h.split(" [")[0]: run[:, k] for k, h in enumerate(header)}
    np.testing.assert_array_equal(sol.t, columns["t"])
    for c in sol.sensitivity_names:
        for state in ("psi", "psi_dot"):
            np.testing.assert_array_equal(sol.sensitivity(state, c), columns[f"d{state}/d{c}"])
        for out in door.outputs:
            np.testing.assert_array_equal(sol.sensitivity(out, c), columns[f"d{out}/d{c}"])
    with pytest.raises(eomgen.UsageError, match="did you mean 'theta'"):
        door.simulate(1.0, sensitivities=["thetta"])
    # rk4 and the variational integrator: S is the derivative of the method's own motion with the same steps.
    h = 1e-6
    for method in ("rk4", "symplectic"):
        fixed = door.simulate(1.0, method=method, dt=0.01, sensitivities=["theta"])
        up = door.simulate(1.0, method=method, dt=0.01, set={"theta": theta + h})["psi"][-1]
        down = door.simulate(1.0, method=method, dt=0.01, set={"theta": theta - h})["psi"][-1]
        assert fixed.S[-1, 0, 0] == pytest.approx((up - down) / (2 * h), rel=1e-6), method
    # The state alone in the error control: still the closed form, to the looser steps' accuracy.
    alone = door.simulate(100.0, until="psi=-pi/2", sensitivities=["theta"], state_error_only=True, rtol=1e-8,
                          atol=1e-10)
    assert alone.event_dt["psi=-pi/2"][0] == pytest.approx(-alone.t_final / (2 * math.tan(theta)), rel=1e-7)


def test_values_in_declared_units_or_their_own(door):
    a = door.simulate(0.5, samples=10, set={"theta": "3 deg"})
    b = door.simulate(0.5, samples=10, set={"theta": math.radians(3)})
    np.testing.assert_array_equal(a.x, b.x)
    assert a.parameters["theta"] == pytest.approx(math.radians(3), rel=1e-15)
    c = door.simulate(0.5, samples=10, init={"psi": -0.2, "psi_dot": 0.1})
    assert c.x[0, 0] == -0.2 and c.x[0, 1] == 0.1


def test_every_method_integrates_the_pendulum(pendulum):
    ref = pendulum.simulate(2.0, samples=20)
    for method, options in [("dop853", {}), ("adams", {}), ("radau5", {}), ("rk4", {"dt": 1e-4}),
                            ("symplectic", {"dt": 1e-4})]:
        sol = pendulum.simulate(2.0, samples=20, method=method, **options)
        np.testing.assert_allclose(sol.q, ref.q, atol=1e-6, err_msg=method)


def test_a_constrained_model_gives_its_multipliers_and_residuals(tmp_path):
    m = eomgen.load(model_path("pendulum_cartesian"))
    sol = m.simulate(2.0, samples=40)
    assert m.constraints == list(sol.multipliers)
    (c,) = m.constraints
    assert np.max(sol.residuals[c]) < 1e-9
    header, run = eomgen_run_csv(tmp_path, model_path("pendulum_cartesian"), "--t-end", "2", "--samples", "40")
    assert [h.split(" [")[0] for h in header] == sol.names
    np.testing.assert_array_equal(sol.to_array(), run)


def door_closing_time(theta, w=0.9, g=9.8):
    return np.sqrt(w / (3 * g * np.sin(theta))) * math.gamma(0.25) * math.sqrt(math.pi) / (2 * math.gamma(0.75))


def test_a_sweep_equals_eomgen_run_sweep_and_the_closed_form(door, tmp_path):
    thetas = [0.05, 0.1, 0.2, 0.4, 0.8]
    e = door.sweep({"theta": thetas}, t_end=100.0, until="psi=-pi/2")
    assert len(e) == 5 and e.ok.all() and e.stopped_by == ["psi=-pi/2"] * 5
    np.testing.assert_allclose(e.t, door_closing_time(np.array(thetas)), rtol=1e-9)
    np.testing.assert_allclose(e.q[:, 0], -math.pi / 2, rtol=1e-12)
    if not EOMGEN:
        pytest.skip("EOMGEN names no eomgen executable")
    out = tmp_path / "sweep.csv"
    subprocess.run([EOMGEN, "run", model_path("door"), "--quiet", "--t-end", "100", "--until", "psi=-pi/2",
                    "--sweep", "theta=" + ",".join(map(repr, thetas)), "--out", str(out)], check=True)
    with open(out) as f:
        rows = list(csv.DictReader(f))
    t_key = next(k for k in rows[0] if k.split(" [")[0] == "t")
    np.testing.assert_array_equal(e.t, [float(r[t_key]) for r in rows])  # the same driver: to the bit


def test_sweeps_on_threads_grids_zips_and_samples(door):
    thetas, starts = np.linspace(0.05, 1.0, 12), [0.0, 0.2]
    one = door.sweep({"theta": thetas, "psi": starts}, t_end=100.0, until="psi=-pi/2", threads=1)
    many = door.sweep({"theta": thetas, "psi": starts}, t_end=100.0, until="psi=-pi/2", threads=4)
    assert len(one) == 24
    np.testing.assert_array_equal(one.t, many.t)  # the same members in the same order whatever the threads
    np.testing.assert_array_equal(one.values["theta"], np.repeat(thetas, 2))  # the first name varies slowest
    np.testing.assert_array_equal(one.values["psi"], np.tile(starts, 12))
    np.testing.assert_allclose(one.t[::2], door_closing_time(thetas), rtol=1e-9)
    zipped = door.sweep({"theta": thetas, "psi": np.zeros(12)}, grid=False, t_end=100.0, until="psi=-pi/2")
    np.testing.assert_array_equal(zipped.t, one.t[::2])
    a = one.to_structured()
    assert a.dtype.names[:2] == ("theta", "psi(0)") and a["t"][0] == one.t[0]
    # In the declared units ("deg" would be a string for simulate; here numbers in the file's unit, rad).
    mc = door.sample(50, {"theta": ("uniform", 0.05, 0.5)}, seed=3, t_end=100.0, until="psi=-pi/2")
    np.testing.assert_allclose(mc.t, door_closing_time(mc.values["theta"]), rtol=1e-9)
    again = door.sample(50, {"theta": ("uniform", 0.05, 0.5)}, seed=3, t_end=100.0, until="psi=-pi/2")
    np.testing.assert_array_equal(mc.t, again.t)


def test_a_failed_member_is_a_row_with_its_message(door):
    e = door.sweep({"theta": [0.1, 0.2]}, t_end=100.0, max_steps=3)
    assert not e.ok.any() and all("step" in m for m in e.error)
    with pytest.raises(eomgen.UsageError, match="did you mean 'theta'"):
        door.sweep({"thetta": [0.1]})
    with pytest.raises(eomgen.UsageError, match="as many values"):
        door.sweep({"theta": [0.1, 0.2], "w": [1.0]}, grid=False)


def test_rhs_is_the_equation_of_motion_over_arrays(pendulum):
    rng = np.random.default_rng(7)
    x = rng.uniform(-3, 3, size=(1000, 2))
    xdot = pendulum.rhs(0.0, x)
    assert xdot.shape == (1000, 2)
    np.testing.assert_array_equal(xdot[:, 0], x[:, 1])
    np.testing.assert_allclose(xdot[:, 1], -9.81 / 1.0 * np.sin(x[:, 0]), rtol=1e-14, atol=1e-14)
    # A parameter changed for this call only; one state; one time per row.
    np.testing.assert_allclose(pendulum.rhs(0.0, x, set={"l": 2.0})[:, 1], -9.81 / 2.0 * np.sin(x[:, 0]), rtol=1e-14)
    np.testing.assert_array_equal(pendulum.rhs(0.0, x[3]), xdot[3])
    np.testing.assert_array_equal(pendulum.rhs(np.zeros(1000), x), xdot)


def test_the_jacobians_against_central_differences():
    m = eomgen.load(os.path.join(ROOT, "examples", "double_pendulum.toml"))
    rng = np.random.default_rng(11)
    x = rng.uniform(-1.5, 1.5, size=(5, 4))
    J, Jp = m.jacobian(0.0, x)
    assert J.shape == (5, 4, 4) and Jp.shape == (5, 4, len(m.parameters))
    h = 1e-6
    for k in range(5):
        for j in range(4):
            e = np.zeros(4)
            e[j] = h
            fd = (m.rhs(0.0, x[k] + e) - m.rhs(0.0, x[k] - e)) / (2 * h)
            np.testing.assert_allclose(J[k][:, j], fd, rtol=1e-6, atol=1e-7)
        for j, p in enumerate(m.parameters):
            v = m.parameters[p]
            fd = (m.rhs(0.0, x[k], set={p: v + h}) - m.rhs(0.0, x[k], set={p: v - h})) / (2 * h)
            np.testing.assert_allclose(Jp[k][:, j], fd, rtol=1e-6, atol=1e-7)
    J1, _ = m.jacobian(0.0, x[2])
    np.testing.assert_array_equal(J1, J[2])


def test_modes_of_the_double_pendulum_and_the_jacobian_at_rest():
    m = eomgen.load(os.path.join(ROOT, "examples", "double_pendulum.toml"))
    r = m.modes()
    assert r.coordinates == ["th1", "th2"] and len(r) == 4
    down = r[0]
    assert down.q == {"th1": 0.0, "th2": 0.0} and down.exact == {"th1": "0", "th2": "0"}
    assert down.stability == "stable" and [e.stability for e in r][1:] == ["unstable"] * 3
    g = m.parameters["g"]  # m1 = m2, l1 = l2 = 1: omega^2 = (2 -+ sqrt 2) g
    np.testing.assert_allclose([mode.omega2 for mode in down.modes], [(2 - math.sqrt(2)) * g, (2 + math.sqrt(2)) * g],
                               rtol=1e-12)
    np.testing.assert_allclose(down.modes[0].shape, [1 / math.sqrt(2), 1], rtol=1e-12)
    assert "sqrt" in down.modes[0].omega2_exact
    np.testing.assert_allclose(down.M, [[2, 1], [1, 1]], rtol=1e-15)
    J, _ = m.jacobian(0.0, np.zeros(4))
    np.testing.assert_allclose(down.A, J, atol=1e-12)  # two routes to the linearization: symbolic and compiled
    with pytest.raises(eomgen.UsageError, match="did you mean 'l1'"):
        m.modes(set={"ll1": 2.0})


def test_a_family_from_python():
    m = eomgen.family("pendulum:n=3")
    assert m.name == "pendulum_3" and m.coordinates == ["theta1", "theta2", "theta3"]
    sol = m.simulate(1.0, init={"theta1": 0.3})
    assert sol.max_drift < 1e-9
    with pytest.raises(eomgen.UsageError, match="family"):
        eomgen.family("pendulum:n=0")


def test_rhs_from_threads_gives_the_same_rows(pendulum):
    x = np.random.default_rng(3).uniform(-3, 3, size=(20000, 2))
    expected = pendulum.rhs(0.0, x)
    results = [None] * 4

    def work(k):
        results[k] = pendulum.rhs(0.0, x)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for r in results:
        np.testing.assert_array_equal(r, expected)


def test_the_equations_as_text_and_latex(pendulum):
    e = pendulum.equations
    assert set(e.euler_lagrange) == {"phi"}
    assert "phi''" in e.euler_lagrange["phi"] and "sin(phi)" in e.euler_lagrange["phi"]
    assert e.M == [["m*l^2"]] or e.M == [["l^2*m"]]
    assert "cos(phi)" in e.V
    assert "Euler-Lagrange" in pendulum.show_text()
    assert "\\begin{align" in pendulum.latex()
    assert pendulum._repr_latex_().count("$$") >= 4


def test_check_finds_the_slip(pendulum):
    text = "\n".join([
        "# Pendulum",
        "$$ T = \\frac{1}{2} m l^2 \\dot\\phi^2 $$",
        "$$ V = -m g l \\cos\\phi $$",
        "The equation of motion:",
        "$$ m l^2 \\ddot\\phi + m g l \\cos\\phi = 0 $$",
    ])
    r = eomgen.check(pendulum, text, path="notes.md")
    verdicts = [e.verdict for e in r]
    assert verdicts[:2] == ["agrees", "agrees"]
    assert verdicts[2] == "disagrees"
    slip = r.disagreements[0]
    assert slip.line == 5
    assert "sin" in slip.corrected
    assert r.counts["disagrees"] == 1
    assert "notes.md" in r.text and r.markdown and r.json.startswith("{")
    assert all(e.role == "claim" for e in r)
    # A row that is no claim: not judged, with the role it was taken for.
    defined = eomgen.check(pendulum, "Let $k = g/l$.\n\n$$\\ddot\\phi = -k \\sin\\phi$$\n")
    assert [(e.verdict, e.role) for e in defined] == [("not judged", "definition"), ("agrees", "claim")]
    assert defined.counts["not judged"] == 1
    # The same through the model's method and with a path.
    assert [e.verdict for e in pendulum.check(text)] == verdicts
    assert [e.verdict for e in eomgen.check(model_path("pendulum"), text)] == verdicts


def test_errors_are_exceptions_with_their_place(pendulum):
    with pytest.raises(eomgen.ModelError, match=r"<string>:\d+:\d+"):
        eomgen.loads('name = "x"\n[[coordinates]]\nname = "q"\n[lagrangian]\nT = "1/2*q\'^2 +"\n')
    with pytest.raises(eomgen.ModelError) as e:
        eomgen.loads("[[coordinates]\n")
    assert isinstance(e.value, ValueError) and isinstance(e.value, eomgen.Error)
    with pytest.raises(FileNotFoundError):
        eomgen.load(os.path.join(MODELS, "no_such_model.toml"))
    with pytest.raises(eomgen.UsageError, match="did you mean 'l'"):
        pendulum.simulate(1.0, set={"ll": 2.0})
    with pytest.raises(eomgen.UsageError, match="did you mean 'l'"):
        pendulum.rhs(0.0, [0.1, 0.0], set={"ll": 2.0})
    with pytest.raises(eomgen.UsageError, match="dt"):
        pendulum.simulate(1.0, method="rk4")
    with pytest.raises(eomgen.UsageError, match=r"shape \(2,\)"):
        pendulum.rhs(0.0, np.zeros((4, 3)))
    with pytest.raises(eomgen.SimulationError):
        pendulum.simulate(100.0, max_steps=5)
    with pytest.raises(TypeError):
        pendulum.simulate(1.0, set={"l": [1, 2]})
    with pytest.raises(KeyError, match="there are t, phi"):
        pendulum.simulate(0.1)["theta"]


def test_a_blown_up_state_is_reported_not_nan():
    # x'' = x^2 from x = 2, x' = 2 blows up before t = 1.8 (near x = 6/(1.73 - t)^2): the integration stops with a
    # message, not NaN.
    m = eomgen.loads('[[coordinates]]\nname = "x"\ninitial = 2.0\nrate = 2.0\n'
                     '[lagrangian]\nT = "1/2*x\'^2"\nV = "-x^3/3"\n', name="blowup")
    assert m.name == "blowup"
    with pytest.raises(eomgen.SimulationError):
        m.simulate(3.0)


def test_models_from_text_and_the_cache_directory(tmp_path):
    text = open(model_path("pendulum")).read()
    m = eomgen.loads(text, name="pendulum_again")
    assert m.name == "pendulum"  # the text names it
    assert eomgen.load(model_path("pendulum"), name="other").name == "pendulum"
    assert eomgen.cache_directory() == os.path.join(os.environ["XDG_CACHE_HOME"], "eomgen")
    assert os.path.dirname(m.shared_object) == eomgen.cache_directory() and m.shared_object.endswith(".so")
    before = {f for f in os.listdir(eomgen.cache_directory()) if f.endswith(".so")}
    m.simulate(0.1)
    after = {f for f in os.listdir(eomgen.cache_directory()) if f.endswith(".so")}
    assert after >= before


def test_interpret_equals_eomgen_run_interpret_and_the_compiled_run(door, tmp_path):
    sol = door.simulate(1.0, samples=50, set={"theta": 0.1}, interpret=True)
    header, run = eomgen_run_csv(tmp_path, model_path("door"), "--t-end", "1", "--samples", "50", "--set",
                                 "theta=0.1", "--interpret")
    np.testing.assert_array_equal(sol.to_array(), run)  # the same tapes, driver and options
    compiled = door.simulate(1.0, samples=50, set={"theta": 0.1})
    # Rounding differs in the last bits (the header was compiled with its own order of operations); the integration
    # tolerance (rtol 1e-10) bounds what that can grow to.
    np.testing.assert_allclose(sol.to_array(), compiled.to_array(), rtol=1e-9, atol=1e-9)


def test_interpret_needs_no_compiler_even_for_radau5_and_sensitivities(tmp_path, monkeypatch):
    monkeypatch.setenv("CXX", "no-such-compiler-x")
    m = eomgen.family("pendulum:n=5")  # not in any cache: a compile would fail
    init = {"theta1": 0.2}
    sol = m.simulate(2.0, init=init, interpret=True)
    assert sol.max_drift < 1e-8
    x = np.random.default_rng(3).uniform(-1, 1, (7, 10))
    xdot = m.rhs(0.0, x, interpret=True)
    np.testing.assert_array_equal(xdot[:, :5], x[:, 5:])
    ens = m.sweep({"theta1": [0.1, 0.2]}, t_end=0.5, interpret=True)
    assert len(ens.t) == 2 and ens.ok.all()
    # The Jacobians by forward differentiation of the tapes: radau5 and the sensitivities run too.
    stiff = m.simulate(2.0, init=init, method="radau5", interpret=True)
    np.testing.assert_allclose(stiff.x[-1], sol.x[-1], atol=1e-6)
    S = m.simulate(1.0, init=init, sensitivities=["g"], interpret=True)
    h = 1e-5
    up = m.simulate(1.0, init=init, set={"g": 9.81 + h}, interpret=True).x[-1]
    down = m.simulate(1.0, init=init, set={"g": 9.81 - h}, interpret=True).x[-1]
    np.testing.assert_allclose(S.S[-1, :, 0], (up - down) / (2 * h), rtol=1e-5, atol=1e-7)
    with pytest.raises(eomgen.CompileError, match="no-such-compiler-x"):
        m.simulate(1.0, init=init)


def test_interpreted_jacobians_and_sensitivities_equal_the_compiled_ones(door):
    x = np.array([[-0.3, -0.1], [-1.0, -0.4]])
    J, Jp = door.jacobian(0.0, x)
    Ji, Jpi = door.jacobian(0.0, x, interpret=True)
    A, B = door.linearize(0.0, x)
    np.testing.assert_array_equal(A, J)
    np.testing.assert_array_equal(B, Jp)
    np.testing.assert_allclose(Ji, J, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(Jpi, Jp, rtol=1e-12, atol=1e-12)
    a = door.simulate(100.0, until="psi=-pi/2", sensitivities=["theta", "w", "x0:psi"])
    b = door.simulate(100.0, until="psi=-pi/2", sensitivities=["theta", "w", "x0:psi"], interpret=True)
    assert b.event_dt["psi=-pi/2"] == pytest.approx(a.event_dt["psi=-pi/2"], rel=1e-9)
    np.testing.assert_allclose(b.S[-1], a.S[-1], rtol=1e-8, atol=1e-10)

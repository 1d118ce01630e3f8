"""The client against a stopped, silent, lying or interrupted oracle: it never hands back
another request's answer, never waits forever, and raises only OracleError."""

import os
import signal
import stat
import sys
import textwrap
import threading
from fractions import Fraction

import pytest

from casteljau_oracle import Oracle, OracleError, OracleInputError, OracleProtocolError, OracleTimeout


def in_thread(fn, seconds=20):
    """fn() in a thread: ("value", v), ("error", e), or ("hang", None) after `seconds`."""
    box = {}

    def run():
        try:
            box["value"] = fn()
        except BaseException as e:  # noqa: BLE001 - the test looks at what came out
            box["error"] = e

    th = threading.Thread(target=run, daemon=True)
    th.start()
    th.join(seconds)
    if th.is_alive():
        return ("hang", None)
    return ("value", box["value"]) if "value" in box else ("error", box["error"])


def fake_oracle(tmp_path, body):
    """An executable that plays the oracle: `body` handles each request line `req`
    (a dict) and writes to `out`."""
    script = tmp_path / "fake_oracle"
    script.write_text(
        f"#!{sys.executable}\n"
        + textwrap.dedent(
            """\
            import json, sys, time
            out = sys.stdout
            for line in sys.stdin:
                req = json.loads(line)
                rid = req.get("id")
            """
        )
        + textwrap.indent(textwrap.dedent(body), "    ")
        + "    out.flush()\n"
    )
    script.chmod(script.stat().st_mode | stat.S_IXUSR)
    return str(script)


class Alarm(Exception):
    pass


def interrupt_when_reading(o, delay):
    """Raises Alarm in this (the main) thread `delay` s after `o` began an exchange."""
    main = threading.get_ident()

    def watch():
        while not o._lock.locked():  # held for the whole exchange
            threading.Event().wait(0.001)
        threading.Event().wait(delay)
        if o._lock.locked():  # an exchange that already ended is not interrupted
            signal.pthread_kill(main, signal.SIGALRM)

    threading.Thread(target=watch, daemon=True).start()


def on_alarm(*_):
    raise Alarm()


@pytest.mark.skipif(not hasattr(signal, "pthread_kill"), reason="needs signal.pthread_kill")
@pytest.mark.parametrize("delay", [0.0, 0.05, 0.3])
def test_an_interrupted_batch_leaves_nothing_for_the_next_request(casteljau_oracle, delay):
    o = Oracle(casteljau_oracle.binary)
    # long enough to be still under way at the latest delay on a fast machine (40,000 took
    # under 0.3 s here)
    big = [{"op": "eval", "points": [[k], [k + 1]], "t": "1/2"} for k in range(400000)]
    old = signal.signal(signal.SIGALRM, on_alarm)
    try:
        interrupt_when_reading(o, delay)
        with pytest.raises(Alarm):
            o.requests(big)
    finally:
        signal.signal(signal.SIGALRM, old)
    # the answers to the interrupted batch are never read as this request's
    outcome = in_thread(lambda: [o.eval_exact([[0], [2]], Fraction(1, 2)) for _ in range(3)])
    assert outcome == ("value", [[Fraction(1)]] * 3)
    assert o.restarts == 1
    o.close()


def test_an_interrupted_batch_of_a_slow_oracle_leaves_nothing_behind(tmp_path):
    # an oracle that answers each request with its first coordinate, 2 ms apart
    binary = fake_oracle(
        tmp_path,
        """
        time.sleep(0.002)
        out.write(json.dumps({"id": rid, "ok": True, "point": [str(req["points"][0][0])]}) + "\\n")
        """,
    )
    o = Oracle(binary)
    old = signal.signal(signal.SIGALRM, on_alarm)
    try:
        interrupt_when_reading(o, 0.2)
        with pytest.raises(Alarm):
            o.requests([{"op": "eval", "points": [[k]], "t": 0} for k in range(5000)])
    finally:
        signal.signal(signal.SIGALRM, old)
    assert in_thread(lambda: o.eval_exact([[-7]], 0)) == ("value", [Fraction(-7)])
    o.close()


def test_an_answer_with_another_requests_id_is_refused(tmp_path):
    # answers the previous request's id: the answer is out of step
    binary = fake_oracle(
        tmp_path,
        """
        out.write(json.dumps({"id": (rid or 0) - 1, "ok": True, "point": ["7"]}) + "\\n")
        """,
    )
    o = Oracle(binary)
    outcome = in_thread(lambda: o.eval_exact([[0], [2]], Fraction(1, 2)))
    assert outcome[0] == "error" and isinstance(outcome[1], OracleProtocolError), outcome
    assert "out of step" in str(outcome[1])
    o.close()


def test_an_answer_that_is_not_json_is_an_oracle_error(tmp_path):
    binary = fake_oracle(tmp_path, 'out.write("{\\"id\\": 1, garbled\\n")\n')
    o = Oracle(binary)
    outcome = in_thread(lambda: o.eval_exact([[0], [2]], Fraction(1, 2)))
    assert outcome[0] == "error" and isinstance(outcome[1], OracleProtocolError), outcome
    o.close()


def test_a_silent_oracle_times_out_and_the_next_request_starts_a_new_one(tmp_path):
    # answers only the second request of each process: the first waits for nothing
    binary = fake_oracle(
        tmp_path,
        """
        if rid % 2 == 0:
            out.write(json.dumps({"id": rid, "ok": True, "point": ["1"]}) + "\\n")
        """,
    )
    o = Oracle(binary, timeout=0.5)
    outcome = in_thread(lambda: o.eval_exact([[0], [2]], Fraction(1, 2)))
    assert outcome[0] == "error" and isinstance(outcome[1], OracleTimeout), outcome
    assert "0.5 s" in str(outcome[1])
    assert in_thread(lambda: o.eval_exact([[0], [2]], Fraction(1, 2))) == ("value", [Fraction(1)])
    assert o.restarts == 1
    o.close()


@pytest.mark.skipif(not hasattr(signal, "SIGSTOP"), reason="needs SIGSTOP")
def test_a_stopped_oracle_times_out(casteljau_oracle):
    o = Oracle(casteljau_oracle.binary, timeout=1.0)
    stopped = o._proc
    os.kill(stopped.pid, signal.SIGSTOP)
    try:
        outcome = in_thread(lambda: o.eval_exact([[0], [2]], Fraction(1, 2)))
    finally:
        os.kill(stopped.pid, signal.SIGCONT)
    assert outcome[0] == "error" and isinstance(outcome[1], OracleTimeout), outcome
    assert o.eval_exact([[0], [2]], Fraction(1, 2)) == [Fraction(1)]
    # the stopped process was killed, and reaped when the next one started (no zombie)
    assert stopped.returncode == -signal.SIGKILL and o._proc is not stopped
    o.close()


def test_an_oracle_that_died_is_an_oracle_error_then_restarted(casteljau_oracle):
    o = Oracle(casteljau_oracle.binary)
    o._proc.kill()
    o._proc.wait()
    with pytest.raises(OracleError, match=f"stopped \\(exit status {-signal.SIGKILL}\\)"):
        o.eval_exact([[1]], 0)
    assert o.eval_exact([[1]], 0) == [Fraction(1)]
    o.close()
    with pytest.raises(OracleError, match="closed"):
        o.eval_exact([[1]], 0)


def test_the_timeout_is_checked():
    for bad in (0, -1.0, float("nan"), float("inf"), "5", True):
        with pytest.raises(OracleError, match="timeout"):
            Oracle(sys.executable, timeout=bad)
    with pytest.raises(OracleInputError, match="path"):
        Oracle(3.5)


def test_every_error_is_an_oracle_error(casteljau_oracle):
    o = casteljau_oracle
    with pytest.raises(OracleError, match="bound"):  # an exact t has no float bound
        o.bound([[0.1], [0.2]], Fraction(1, 3))
    with pytest.raises(OracleError, match="bound"):
        o.within_bound([[0.1], [0.2]], Fraction(1, 3), [0.125])
    with pytest.raises(OracleInputError, match="beyond the largest float"):
        o.judge([[0.1], [0.2]], 0.5, [10**400])
    with pytest.raises(OracleInputError, match="not a float"):
        o.judge([[0.1], [0.2]], 0.5, [Fraction(1, 3)])
    with pytest.raises(OracleInputError, match="NaN"):
        o.eval_exact([[float("nan")]], 0)
    with pytest.raises(OracleInputError, match="inf"):
        o.eval_exact([[1.0]], float("inf"))
    with pytest.raises(OracleInputError, match="not a number"):
        o.eval_exact([[object()]], 0)
    with pytest.raises(OracleInputError, match="a number, not True"):
        o.eval_exact([[True]], 0)
    with pytest.raises(OracleInputError, match="list of points"):
        o.eval_exact(3, 0)
    with pytest.raises(OracleInputError, match="JSON"):
        o.request({"op": "eval", "points": [[object()]], "t": 0})
    with pytest.raises(OracleInputError, match="JSON"):
        o.request({"op": "eval", "points": [[float("nan")]], "t": 0})
    with pytest.raises(OracleError, match="cannot run"):
        Oracle(os.path.join(os.path.dirname(__file__), "no", "such", "casteljau"))
    # the oracle goes on after all of these
    assert o.eval_exact([[0], [2]], Fraction(1, 2)) == [Fraction(1)]


def test_a_requests_own_id_comes_back_and_the_clients_ids_stay_inside(casteljau_oracle):
    a, b = casteljau_oracle.requests(
        [{"id": "mine", "op": "eval", "points": [[3]], "t": 0}, {"op": "eval", "points": [[4]], "t": 0}]
    )
    assert a == {"id": "mine", "ok": True, "point": ["3"]}
    assert b == {"ok": True, "point": ["4"]}


def test_an_over_long_request_gets_its_own_error_answer(casteljau_oracle):
    # the oracle skips a line over 1 MiB unread and answers with the id only when the line
    # starts with it: the client writes its id first
    huge = {"op": "eval", "points": [[1.2345678901234567] for _ in range(60000)], "t": 0.5}
    with pytest.raises(OracleError, match="longer than"):
        casteljau_oracle.request(huge)
    first, second = casteljau_oracle.requests([huge, {"op": "eval", "points": [[3]], "t": 0}], check=False)
    assert not first["ok"] and "longer than" in first["error"] and second["point"] == ["3"]

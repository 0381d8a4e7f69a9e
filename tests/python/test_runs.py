"""How runs behave in a Python process: the GIL is released while they run, Ctrl-C stops them
(KeyboardInterrupt, nothing half-written, an earlier output kept), the progress callback."""
import os
import signal
import threading
import time

import pytest

import rollnoise
from conftest import SOURCE

SDOF = SOURCE / "models" / "cases" / "larsson2000_sdof_sine.toml"
# The SDOF case rolled for long enough to take a few seconds.
LONG = {"rolling.duration": 60.0}


def test_other_threads_run_while_a_case_runs():
    counted = [0]
    running = threading.Event()
    stop = threading.Event()

    def count():
        running.set()
        while not stop.is_set():
            counted[0] += 1

    thread = threading.Thread(target=count)
    thread.start()
    running.wait()
    before = counted[0]
    started = time.monotonic()
    rollnoise.simulate(SDOF, set={"rolling.duration": 10.0})
    elapsed = time.monotonic() - started
    during = counted[0] - before
    stop.set()
    thread.join()
    # A thread kept off by the GIL would count a few switch intervals (5 ms each) at most.
    assert elapsed > 0.2 and during > 10000, (elapsed, during)


def test_ctrl_c_stops_a_run_and_keeps_the_earlier_output(tmp_path):
    out = tmp_path / "out"
    rollnoise.simulate(SDOF, out=out)
    earlier = (out / "contact.csv").read_bytes()
    stages = []
    timer = threading.Timer(0.5, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    started = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        rollnoise.simulate(SDOF, set=LONG, out=out, progress=lambda *a: stages.append(a))
    stopped = time.monotonic() - started
    timer.join()
    assert stopped < 5.0, stopped
    assert stages and stages[-1][1] < stages[-1][2], "stopped before the end"
    assert sorted(os.listdir(tmp_path)) == ["out"], "no staging folder left"
    assert (out / "contact.csv").read_bytes() == earlier
    # The next run is not stopped by the last one's Ctrl-C.
    assert rollnoise.simulate(SDOF).force.shape[0] == 5001


def test_an_exception_in_the_callback_stops_the_run(tmp_path):
    class Enough(Exception):
        pass

    def progress(stage, done, total):
        if done > 0:
            raise Enough(stage)

    with pytest.raises(Enough):
        rollnoise.simulate(SDOF, set=LONG, out=tmp_path / "out", progress=progress)
    assert os.listdir(tmp_path) == []


def test_progress_ends_with_the_whole_run():
    calls = []
    rollnoise.simulate(SDOF, progress=lambda *a: calls.append(a))
    assert calls[-1] == ("simulate larsson2000_sdof_sine.toml", 5001, 5001)
    assert all(isinstance(s, str) and 0 <= d <= t for s, d, t in calls)

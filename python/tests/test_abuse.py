"""The module tried as a careful user trying to break it would (issue 36): wrong arrays for out=, one Log
shared by threads (and closed under them), Ctrl-C inside events() and state(), and requests for more than
memory holds. Each must end in a Python exception with a clear message or in the right answer: never a
crash, a hang, or a wrong array."""
import hashlib
import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np
import pytest

import ede
from conftest import ROOT

SENTINEL = np.iinfo(np.uint64).max


@pytest.fixture(scope="module")
def long_log(tmp_path_factory):
    """8e6 engine events of 2000 disks with a keyframe only at the start and the end: a state before the end
    replays every logged event, and the events are walked on one thread, so both take long enough to be
    interrupted."""
    path = tmp_path_factory.mktemp("long") / "long.ede"
    ede.run(ROOT / "examples" / "bench" / "gas-N1000000-phi0.5-periodic.toml", log=path, progress=False,
            set={"species[0].count": 2000, "stop.events": 8_000_000, "log.keyframe_interval": 100_000_000,
                 "engine.rebuild_interval": 100_000_000})
    return path


# --- out= -------------------------------------------------------------------------------------------

def test_out_of_the_wrong_kind_is_refused_before_anything_is_written(gas_log, tmp_path):
    log = ede.open(gas_log)
    buf = log.events(first=0, last=300, before=True)
    kept = buf.copy()
    cases = [
        (TypeError, "expected a numpy array", [0] * 300),
        (TypeError, "expected a numpy array", memoryview(bytearray(300 * buf.dtype.itemsize))),
        (TypeError, "is not the one these arguments give", np.zeros(300)),                   # plain float64
        (TypeError, "is not the one these arguments give", np.zeros(300, np.int64)),
        (TypeError, "is not the one these arguments give", buf.astype(buf.dtype.newbyteorder())),  # byte order
        (TypeError, "is not the one these arguments give", log.events(first=0, last=300)),    # other fields
        (ValueError, "contiguous 1-D", buf.reshape(3, 100)),
        (ValueError, "contiguous 1-D", buf[::3]),
        (ValueError, "contiguous 1-D", buf[:1].reshape(())),                                   # 0-d
        (TypeError, "expected a numpy array", buf[0]),                                         # a row, not an array
        (ValueError, "holds 300 events, the array 299 rows", buf[:299]),
        (ValueError, "holds 300 events, the array 0 rows", buf[:0]),
    ]
    for error, message, out in cases:
        with pytest.raises(error, match=message):
            log.events(first=0, last=300, before=True, out=out)
    read_only = buf.copy()
    read_only.flags.writeable = False
    with pytest.raises(ValueError, match="writable"):
        log.events(first=0, last=300, before=True, out=read_only)
    np.testing.assert_array_equal(buf, kept)  # nothing was written by a refused call
    # A float log's rows are not a double log's, whatever the field names.
    float_log = tmp_path / "float.ede"
    ede.run(ROOT / "examples" / "scenes" / "periodic.toml", log=float_log, progress=False,
            set={"engine.scalar": "float", "stop.collisions_per_particle": 1})
    with pytest.raises(TypeError, match="is not the one these arguments give"):
        ede.open(float_log).events(first=0, last=10, out=log.events(first=0, last=10))


def test_out_that_is_a_window_of_a_longer_array_gets_exactly_the_rows(gas_log):
    log = ede.open(gas_log)
    every = log.events()
    big = np.zeros(1000, every.dtype)
    big["index"] = SENTINEL
    rows = log.events(first=100, last=400, out=big[50:])
    np.testing.assert_array_equal(rows, every[100:400])
    np.testing.assert_array_equal(big[50:350], every[100:400])
    assert (big["index"][:50] == SENTINEL).all() and (big["index"][350:] == SENTINEL).all()  # untouched


# --- threads ------------------------------------------------------------------------------------------

def test_one_log_shared_by_threads_gives_each_the_right_arrays(gas_log):
    log = ede.open(gas_log)
    n = log.info["events"]
    times = np.linspace(0.0, log.end_time, 7)
    expected_states = {t: ede.open(gas_log).state(t).x for t in times}
    every = ede.open(gas_log).events(before=True)
    failures = []

    def reader(seed):
        rng = np.random.default_rng(seed)
        try:
            for _ in range(25):
                t = times[rng.integers(len(times))]
                np.testing.assert_array_equal(log.state(t).x, expected_states[t])
                a = int(rng.integers(0, n - 1))
                b = int(rng.integers(a + 1, n + 1))
                np.testing.assert_array_equal(log.events(first=a, last=b, before=True), every[a:b])
                ede.distribution(log, t)  # an analysis between the seeks: it shares the Log too
        except BaseException as e:  # noqa: B902 -- reported below with its thread
            failures.append((seed, repr(e)))

    threads = [threading.Thread(target=reader, args=(k,)) for k in range(6)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(timeout=300)
    assert not any(t.is_alive() for t in threads), "a reader hung"
    assert not failures, failures


def test_closing_a_log_under_its_readers_gives_results_or_the_closed_error(gas_log):
    log = ede.open(gas_log)
    every = ede.open(gas_log).events()
    outcomes = []

    def reader():
        while True:
            try:
                rows = log.events()
            except ede.InvalidError as e:
                assert "was closed" in str(e)
                outcomes.append("closed")
                return
            np.testing.assert_array_equal(rows, every)
            outcomes.append("rows")

    threads = [threading.Thread(target=reader) for _ in range(4)]
    for t in threads:
        t.start()
    time.sleep(0.3)
    log.close()
    for t in threads:
        t.join(timeout=120)
    assert not any(t.is_alive() for t in threads)
    assert outcomes.count("closed") == 4 and "rows" in outcomes


# --- Ctrl-C --------------------------------------------------------------------------------------------

def interrupted_after(seconds, call):
    """Calls call() with a KeyboardInterrupt raised by a signal `seconds` later (SIGALRM, whose Python
    handler raises it as Ctrl-C's does); returns how long the call ran."""
    def handler(signum, frame):
        raise KeyboardInterrupt

    old = signal.signal(signal.SIGALRM, handler)
    t0 = time.perf_counter()
    try:
        signal.setitimer(signal.ITIMER_REAL, seconds)
        with pytest.raises(KeyboardInterrupt):
            call()
        return time.perf_counter() - t0
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


def test_ctrl_c_stops_state_inside_the_replay_and_the_log_reads_on(long_log):
    last = ede.open(long_log).info["events"] - 1  # from the first keyframe: a replay of every event
    t0 = time.perf_counter()
    end_state = ede.open(long_log).state(event=last)
    whole = time.perf_counter() - t0
    log = ede.open(long_log)
    stopped = interrupted_after(0.05, lambda: log.state(event=last))
    assert stopped < 0.6 * whole, (stopped, whole)  # stopped inside the call, not after it (loaded machine)
    again = log.state(event=last)
    for k in ("x", "y", "vx", "vy"):
        np.testing.assert_array_equal(getattr(again, k), getattr(end_state, k))
    assert again.events == end_state.events


def test_ctrl_c_stops_events_and_leaves_no_array(long_log):
    log = ede.open(long_log)
    buf = log.events()
    reference = buf.copy()
    buf["index"] = SENTINEL
    interrupted_after(0.05, lambda: log.events(out=buf))
    assert (buf["index"] == SENTINEL).any()  # the walk stopped before its end
    np.testing.assert_array_equal(log.events(out=buf), reference)  # and the Log reads on, exactly
    collision = log.events(first=0, last=2_000_000, collision=True)  # derived columns stop too
    interrupted_after(0.05, lambda: log.events(first=0, last=2_000_000, collision=True))
    np.testing.assert_array_equal(log.events(first=0, last=2_000_000, collision=True), collision)


def test_a_real_ctrl_c_with_python_s_own_handler(long_log):
    """SIGINT itself, as a terminal's Ctrl-C sends it, with Python's default handler, in a fresh process."""
    code = textwrap.dedent("""
        import os, signal, sys, threading, numpy as np, ede
        log = ede.open(sys.argv[1])
        buf = log.events()
        buf["index"] = np.iinfo(np.uint64).max
        threading.Timer(0.05, os.kill, (os.getpid(), signal.SIGINT)).start()
        try:
            log.events(out=buf)
            print("finished")
        except KeyboardInterrupt:
            print("KeyboardInterrupt", int((buf["index"] == np.iinfo(np.uint64).max).sum()))
        print("after", log.state(event=1000).events)
    """)
    p = subprocess.run([sys.executable, "-c", code, str(long_log)], capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    interrupted, after = p.stdout.strip().split("\n")
    assert interrupted.startswith("KeyboardInterrupt ") and int(interrupted.split()[1]) > 0, p.stdout
    assert after == "after 1000"


# --- memory ---------------------------------------------------------------------------------------------

LIMITED = textwrap.dedent("""
    import hashlib, resource, sys
    import numpy as np, ede
    log = ede.open(sys.argv[1])
    resource.setrlimit(resource.RLIMIT_AS, (int(sys.argv[2]), resource.RLIM_INFINITY))
    for name, call in (("events", lambda: log.events(collision=True)), ("state", lambda: log.state().x)):
        try:
            print(name, hashlib.sha256(call()).hexdigest(), flush=True)  # no copy: a copy could not fit
        except MemoryError as e:
            print(name, "MemoryError", str(e).replace("\\n", " "), flush=True)
    print("small", len(log.events(first=0, last=100)), flush=True)
""")


def vm_size_after_import():
    code = "import ede, numpy; print(open('/proc/self/status').read().split('VmSize:')[1].split()[0])"
    return int(subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout) * 1024


def test_more_events_than_memory_holds_is_a_memory_error_saying_so(long_log):
    log = ede.open(long_log)
    rows = log.events(first=0, last=10, collision=True).dtype.itemsize * log.info["events"]
    expected = {"events": None, "state": None}
    base = vm_size_after_import()
    # Caps from far too small to enough for the rows: each step either gives the same bytes as an unlimited
    # read or a MemoryError naming the request; the process always lives on to read a small range.
    for extra in (16 << 20, rows // 4, rows // 2, rows + (400 << 20)):
        p = subprocess.run([sys.executable, "-c", LIMITED, str(long_log), str(base + extra)], capture_output=True,
                           text=True, timeout=300)
        assert p.returncode == 0, (extra, p.stderr[-2000:])
        lines = dict(line.split(" ", 1) for line in p.stdout.strip().split("\n"))
        assert lines["small"] == "100", p.stdout
        for name in ("events", "state"):
            if lines[name].startswith("MemoryError"):
                assert str(long_log) in lines[name] and "allocate" in lines[name], lines[name]
                if name == "events" and extra < rows:
                    assert "window by window" in lines[name] and "events" in lines[name]
            else:
                if expected[name] is None:
                    full = log.events(collision=True) if name == "events" else log.state().x
                    expected[name] = hashlib.sha256(full).hexdigest()
                assert lines[name] == expected[name], (name, extra)
        if extra == 16 << 20:
            assert lines["events"].startswith("MemoryError"), lines
    assert lines["events"] == expected["events"]  # with room enough, the rows arrive whole

"""Hostile schedulers through the real command line: `runout study --scheduler ADDRESS`.

The review found a port that accepts connections and never answers holding `runout study` for
150 s without a word, and malformed addresses (``http://x``, ``tcp://[::1``, ``local:abc``)
ending in exit status 70 ("internal error"). Now a malformed address is refused before any
connection, a scheduler is given a connect and a response timeout
(``RUNOUT_SCHEDULER_CONNECT_TIMEOUT``, ``RUNOUT_SCHEDULER_RESPONSE_TIMEOUT``), and each failure
is one line naming ``--scheduler`` with exit status 2. The tests lower the response timeout
through its environment variable so that they end in seconds.
"""

from __future__ import annotations

import os
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

CASE = Path(__file__).resolve().parents[2] / "examples" / "seed001_kim_table9.toml"
#: Seconds a command may take: the refusals are immediate, the timeouts below are 1 s.
TIMEOUT = 60.0


def _study(address: str, **env: str) -> tuple[subprocess.CompletedProcess[str], float]:
    start = time.monotonic()
    done = subprocess.run(
        [sys.executable, "-m", "runout.cli", "study", str(CASE), "--json", "--scheduler", address],
        capture_output=True,
        text=True,
        timeout=TIMEOUT,
        env={**os.environ, **env},
    )
    return done, time.monotonic() - start


def _one_line_naming_the_option(done: subprocess.CompletedProcess[str]) -> str:
    assert done.returncode == 2, (done.returncode, done.stderr[-2000:])
    assert "Traceback" not in done.stderr
    lines = done.stderr.splitlines()
    assert len(lines) == 1, done.stderr
    assert lines[0].startswith("error: --scheduler: "), lines[0]
    assert done.stdout == ""
    return lines[0]


@pytest.mark.parametrize(
    "address",
    [
        "http://x",
        "tcp://[::1",
        "local:abc",
        "tcp://host",
        "tcp://host:0",
        "tcp://host:99999",
        "tcp://::1:8786",
        "tcp://[zz]:8786",
        "tcp://a b:8786",
        "",
    ],
)
def test_a_malformed_address_is_refused_before_connecting(address: str) -> None:
    done, _ = _study(address)
    line = _one_line_naming_the_option(done)
    assert "tcp://HOST:PORT" in line and "local" in line  # the accepted forms


@pytest.fixture
def silent_server() -> Iterator[tuple[str, list[socket.socket]]]:
    """A TCP port that accepts every connection and never sends a byte."""
    server = socket.create_server(("127.0.0.1", 0))
    accepted: list[socket.socket] = []
    stop = threading.Event()

    def serve() -> None:
        server.settimeout(0.1)
        while not stop.is_set():
            try:
                conn, _ = server.accept()
            except TimeoutError:
                continue
            accepted.append(conn)

    thread = threading.Thread(target=serve, daemon=True)
    thread.start()
    try:
        yield f"tcp://127.0.0.1:{server.getsockname()[1]}", accepted
    finally:
        stop.set()
        thread.join()
        for conn in accepted:
            conn.close()
        server.close()


def test_a_scheduler_that_accepts_and_never_answers_times_out(
    silent_server: tuple[str, list[socket.socket]],
) -> None:
    address, accepted = silent_server
    done, took = _study(address, RUNOUT_SCHEDULER_RESPONSE_TIMEOUT="1 s")
    line = _one_line_naming_the_option(done)
    assert "did not answer within 1 s" in line and "RUNOUT_SCHEDULER_RESPONSE_TIMEOUT" in line
    assert accepted  # it did connect: the timeout is the response's
    assert took < 30.0  # 1 s of waiting, plus Python, NumPy and the case


def test_a_closed_port_is_refused_at_once() -> None:
    with socket.create_server(("127.0.0.1", 0)) as probe:
        port = probe.getsockname()[1]
    done, _ = _study(f"127.0.0.1:{port}")
    assert "cannot connect to tcp://127.0.0.1:" in _one_line_naming_the_option(done)


@pytest.mark.parametrize("value", ["soon", "0 s", "-3", "nan"])
def test_a_timeout_that_is_not_a_positive_time_names_its_variable(value: str) -> None:
    done, _ = _study("tcp://127.0.0.1:9", RUNOUT_SCHEDULER_CONNECT_TIMEOUT=value)
    assert done.returncode == 2, done.stderr
    lines = done.stderr.splitlines()
    assert len(lines) == 1 and "RUNOUT_SCHEDULER_CONNECT_TIMEOUT" in lines[0], done.stderr


@pytest.mark.parametrize(
    ("text", "uri"),
    [
        ("local", None),
        (" local ", None),
        ("tcp://127.0.0.1:8786", "tcp://127.0.0.1:8786"),
        ("scheduler.example.org:8786", "tcp://scheduler.example.org:8786"),
        ("tls://scheduler:443", "tls://scheduler:443"),
        ("tcp://[::1]:8786", "tcp://[::1]:8786"),
        ("tcp://[fe80::1%eth0]:1", "tcp://[fe80::1%eth0]:1"),
    ],
)
def test_the_accepted_forms_parse(text: str, uri: str | None) -> None:
    from runout.study.scheduler import scheduler_address

    parsed = scheduler_address(text)
    assert (parsed.uri if parsed is not None else None) == uri


@given(
    host=st.ip_addresses(),
    port=st.integers(1, 65535),
    scheme=st.sampled_from(["tcp", "tls"]),
)
def test_every_ip_address_and_port_round_trips(host: object, port: int, scheme: str) -> None:
    from runout.study.scheduler import scheduler_address

    shown = f"[{host}]" if ":" in str(host) else str(host)
    parsed = scheduler_address(f"{scheme}://{shown}:{port}")
    assert parsed is not None
    assert (parsed.scheme, parsed.host, parsed.port) == (scheme, str(host), port)
    assert scheduler_address(parsed.uri) == parsed


@given(port=st.one_of(st.integers(max_value=0), st.integers(min_value=65536)))
def test_a_port_outside_the_range_is_refused(port: int) -> None:
    from runout.study._plan import StudyError
    from runout.study.scheduler import scheduler_address

    with pytest.raises(StudyError, match=r"^--scheduler: .*PORT 1 to 65535"):
        scheduler_address(f"tcp://127.0.0.1:{port}")

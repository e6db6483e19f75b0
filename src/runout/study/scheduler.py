"""The Dask scheduler of ``runout study --scheduler``: its address and bounded connection.

A scheduler is a peer on the network: it may be down, behind a firewall that drops packets,
or a program that accepts connections and never answers. Every connection to one is therefore
bounded twice, and a malformed address is refused before any connection is tried:

* the *connect timeout* (default :data:`DEFAULT_CONNECT_TIMEOUT`, 10 s; environment variable
  ``RUNOUT_SCHEDULER_CONNECT_TIMEOUT``): how long the TCP connection may take to be accepted;
* the *response timeout* (default :data:`DEFAULT_RESPONSE_TIMEOUT`, 30 s; environment variable
  ``RUNOUT_SCHEDULER_RESPONSE_TIMEOUT``): how long the scheduler may take, once connected, to
  answer Dask's handshake and to register the client.

Both variables take a time with its unit (``"2 min"``) or a number of seconds. A scheduler that
misses either is a :class:`StudyError` naming ``--scheduler`` (one line, exit status 2 on the
command line), never a hang.
"""

from __future__ import annotations

import asyncio
import math
import os
import re
import socket
import threading
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from runout.study._plan import StudyError

__all__ = [
    "ACCEPTED_FORMS",
    "DEFAULT_CONNECT_TIMEOUT",
    "DEFAULT_RESPONSE_TIMEOUT",
    "ENV_CONNECT_TIMEOUT",
    "ENV_RESPONSE_TIMEOUT",
    "SchedulerAddress",
    "connect_client",
    "scheduler_address",
    "scheduler_timeouts",
]

#: Seconds the scheduler may take to accept the TCP connection [s].
DEFAULT_CONNECT_TIMEOUT = 10.0
#: Seconds the scheduler may take to answer once connected (handshake, registration) [s].
DEFAULT_RESPONSE_TIMEOUT = 30.0
ENV_CONNECT_TIMEOUT = "RUNOUT_SCHEDULER_CONNECT_TIMEOUT"
ENV_RESPONSE_TIMEOUT = "RUNOUT_SCHEDULER_RESPONSE_TIMEOUT"
#: The forms ``--scheduler`` takes, in words (the refusal of a malformed address says them).
ACCEPTED_FORMS = (
    "tcp://HOST:PORT, tls://HOST:PORT, HOST:PORT or local (HOST a name, an IPv4 address or an "
    "IPv6 address in brackets such as [::1]; PORT 1 to 65535)"
)

_HOST_NAME = re.compile(r"[A-Za-z0-9](?:[A-Za-z0-9.-]{0,251}[A-Za-z0-9])?")
_IPV6 = re.compile(r"[0-9A-Fa-f:.]+(?:%[A-Za-z0-9_.-]+)?")

#: The refusal when Dask's ``distributed`` (the ``dask`` extra) is not installed.
_NO_DASK = "--scheduler needs Dask distributed: pip install 'runout[dask]'"


@dataclass(frozen=True)
class SchedulerAddress:
    """A scheduler address that parsed.

    Attributes
    ----------
    scheme : {"tcp", "tls"}
        Dask's comm protocol.
    host : str
        Host name or IP address (an IPv6 address without its brackets).
    port : int
        TCP port (1..65535).
    """

    scheme: str
    host: str
    port: int

    @property
    def uri(self) -> str:
        """The address as Dask takes it (``tcp://host:port``, IPv6 in brackets)."""
        host = f"[{self.host}]" if ":" in self.host else self.host
        return f"{self.scheme}://{host}:{self.port}"


def _refuse(text: str, why: str) -> StudyError:
    shown = text if len(text) <= 80 else text[:77] + "..."
    return StudyError(f"--scheduler: {shown!r} {why}; write {ACCEPTED_FORMS}")


def scheduler_address(text: str) -> SchedulerAddress | None:
    """Parse ``--scheduler``: None for ``local`` (a local cluster), else the address.

    Parameters
    ----------
    text : str
        ``tcp://HOST:PORT``, ``tls://HOST:PORT``, ``HOST:PORT`` (TCP) or ``local``.

    Returns
    -------
    SchedulerAddress or None
        The scheduler to connect to; None for a local cluster.

    Raises
    ------
    StudyError
        A malformed address (another scheme, no port, a port outside 1..65535, an IPv6
        address without its closing bracket), naming ``--scheduler`` and the accepted forms.
    """
    if not isinstance(text, str):
        raise _refuse(repr(text), "is not text")
    stripped = text.strip()
    if stripped == "local":
        return None
    scheme, sep, rest = stripped.partition("://")
    if not sep:
        scheme, rest = "tcp", stripped
    if scheme not in ("tcp", "tls"):
        raise _refuse(text, f"has the scheme {scheme!r}, which is not a Dask scheduler's")
    if rest.startswith("["):
        close = rest.find("]")
        if close < 0:
            raise _refuse(text, "opens an IPv6 address with [ but does not close it")
        host, after = rest[1:close], rest[close + 1 :]
        if not _IPV6.fullmatch(host) or ":" not in host:
            raise _refuse(text, f"has {host!r} in brackets, which is not an IPv6 address")
        if not after.startswith(":"):
            raise _refuse(text, "gives no port after the IPv6 address")
        port_text = after[1:]
    else:
        host, colon, port_text = rest.rpartition(":")
        if not colon:
            raise _refuse(text, "gives no port")
        if ":" in host:
            raise _refuse(text, "has an IPv6 address without brackets")
        if not _HOST_NAME.fullmatch(host):
            raise _refuse(text, f"has {host!r}, which is not a host name or an IPv4 address")
    if not port_text.isdigit() or not 1 <= int(port_text) <= 65535:
        raise _refuse(text, f"has the port {port_text!r}, not a number from 1 to 65535")
    return SchedulerAddress(scheme, host, int(port_text))


def _seconds(name: str, default: float, environ: Mapping[str, str]) -> float:
    from runout.base.units import UnitError, to_si

    text = environ.get(name, "").strip()
    if not text:
        return default
    try:
        value = float(text)
    except ValueError:
        try:
            value = to_si(text, "time")
        except UnitError as exc:
            raise StudyError(f"{name}: environment variable: {exc}") from None
    if not (math.isfinite(value) and value > 0.0):
        raise StudyError(f"{name}: environment variable: must be a time > 0, got {text!r}")
    return value


def scheduler_timeouts(environ: Mapping[str, str] | None = None) -> tuple[float, float]:
    """The connect and response timeouts of a scheduler connection [s].

    Parameters
    ----------
    environ : mapping, optional
        Environment (default ``os.environ``), read for :data:`ENV_CONNECT_TIMEOUT` and
        :data:`ENV_RESPONSE_TIMEOUT`.

    Returns
    -------
    connect, response : float
        Seconds to accept the connection, and to answer once connected [s].

    Raises
    ------
    StudyError
        A variable that is not a positive time, naming it.
    """
    env = os.environ if environ is None else environ
    return (
        _seconds(ENV_CONNECT_TIMEOUT, DEFAULT_CONNECT_TIMEOUT, env),
        _seconds(ENV_RESPONSE_TIMEOUT, DEFAULT_RESPONSE_TIMEOUT, env),
    )


def _accepts(address: SchedulerAddress, connect: float, response: float) -> None:
    """A TCP connection accepted within ``connect`` seconds and, for ``tcp``, a first byte
    within ``response`` seconds after it (a Dask scheduler sends its handshake first)."""
    silent = StudyError(
        f"--scheduler: {address.uri} accepted the connection but did not answer within "
        f"{response:g} s; is it a Dask scheduler? (raise {ENV_RESPONSE_TIMEOUT} for a slow one)"
    )
    try:
        with socket.create_connection((address.host, address.port), timeout=connect) as sock:
            if address.scheme == "tcp":  # TLS: the client speaks first; _answers bounds it
                sock.settimeout(response)
                try:
                    first = sock.recv(1)
                except TimeoutError:
                    raise silent from None
                if not first:
                    raise StudyError(
                        f"--scheduler: {address.uri} closed the connection without answering"
                    )
    except TimeoutError:
        raise StudyError(
            f"--scheduler: {address.uri} did not accept a connection within {connect:g} s "
            f"(raise {ENV_CONNECT_TIMEOUT} for a slow network)"
        ) from None
    except OSError as exc:
        raise StudyError(
            f"--scheduler: cannot connect to {address.uri} ({exc.strerror or exc})"
        ) from None


def _answers(address: SchedulerAddress, connect: float, response: float) -> None:
    """Dask's handshake with the scheduler, within ``connect + response`` seconds.

    Dask's own ``connect`` bounds the TCP connection but waits for the peer's handshake without
    a limit: a port that accepts and never answers held ``runout study`` for minutes. The
    handshake runs here under a deadline, in a thread of its own (the caller may be inside an
    event loop, e.g. a notebook).
    """
    try:  # the dask extra (study.run checked it already; a direct caller gets the message)
        from distributed.comm import connect as dask_connect
        from distributed.security import Security
    except ImportError:  # pragma: no cover - depends on the installation
        raise StudyError(_NO_DASK) from None

    args = Security().get_connection_args("client") if address.scheme == "tls" else {}

    async def handshake() -> None:
        comm = await asyncio.wait_for(
            dask_connect(address.uri, timeout=connect, **args), timeout=connect + response
        )
        await comm.close()

    failure: list[BaseException] = []

    def probe() -> None:
        try:
            asyncio.run(handshake())
        except BaseException as exc:  # reported by the caller
            failure.append(exc)

    thread = threading.Thread(target=probe, name="runout-scheduler-probe", daemon=True)
    thread.start()
    thread.join(connect + response + 1.0)
    if thread.is_alive() or (failure and isinstance(failure[0], TimeoutError)):
        raise StudyError(
            f"--scheduler: {address.uri} accepted the connection but did not answer within "
            f"{response:g} s; is it a Dask scheduler? (raise {ENV_RESPONSE_TIMEOUT} for a slow "
            "one)"
        )
    if failure:
        exc = failure[0]
        raise StudyError(
            f"--scheduler: {address.uri} did not answer as a Dask scheduler "
            f"({type(exc).__name__}: {exc})"
        )


def connect_client(address: SchedulerAddress, environ: Mapping[str, str] | None = None) -> Any:
    """A Dask ``Client`` of the scheduler at ``address``, every step bounded in time.

    Parameters
    ----------
    address : SchedulerAddress
        From :func:`scheduler_address`.
    environ : mapping, optional
        Environment of the timeouts (:func:`scheduler_timeouts`); default ``os.environ``.

    Returns
    -------
    distributed.Client

    Raises
    ------
    StudyError
        The scheduler refused the connection, did not accept it within the connect timeout,
        or did not answer within the response timeout; each names ``--scheduler``.
    """
    try:  # the dask extra
        from distributed import Client
    except ImportError:  # pragma: no cover - depends on the installation
        raise StudyError(_NO_DASK) from None

    connect, response = scheduler_timeouts(environ)
    _accepts(address, connect, response)
    _answers(address, connect, response)
    try:
        # the handshake answered: Dask bounds the rest (scheduler info, registration) by
        # ``timeout``
        return Client(address.uri, timeout=response)
    except (OSError, TimeoutError) as exc:
        raise StudyError(
            f"--scheduler: {address.uri} did not register the client ({exc})"
        ) from None

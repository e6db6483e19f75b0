"""The compile notice: one line when the first kernel compiles, nothing after the command."""

from __future__ import annotations

import io
from types import SimpleNamespace

import pytest

from runout.cli import compile_notice as notice


def _event(module: str) -> dict[str, object]:
    return {"dispatcher": SimpleNamespace(py_func=SimpleNamespace(__module__=module))}


@pytest.fixture(autouse=True)
def _fresh(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv(notice.ENV, "1")  # a StringIO is no terminal
    monkeypatch.setattr(notice._State, "announced", False)
    monkeypatch.setattr(notice._State, "depth", 0)
    notice.stop()


def test_one_line_at_the_first_kernel_and_what_was_compiled() -> None:
    stream = io.StringIO()
    notice.watch(stream)
    notice._on_start(_event("runout.models._roller_kernels"))
    notice._on_start(_event("numba.np.arrayobj"))  # a library overload inside it: no topic
    notice._on_end()
    notice._on_end()
    notice._on_start(_event("runout.analysis._line_kernels"))
    notice._on_end()
    lines = stream.getvalue().splitlines()
    assert len(lines) == 1 and "(roller_constraint model)" in lines[0]
    done = notice.finish()
    assert done is not None
    assert "roller_constraint model, spectral lines in " in done


def test_nothing_is_printed_once_the_command_has_ended() -> None:
    # a command's stderr (a test runner's capture) is closed after it: a later compilation
    # (another test, a library call) must neither print nor fail
    stream = io.StringIO()
    notice.watch(stream)
    notice.stop()
    stream.close()
    notice._on_start(_event("runout.models._equilibrium_kernels"))
    notice._on_end()
    assert notice.finish() is None


def test_a_closed_stream_during_the_command_is_not_an_error() -> None:
    stream = io.StringIO()
    notice.watch(stream)
    stream.close()
    notice._on_start(_event("runout.models._dynamic_kernels"))
    notice._on_end()


def test_topics_name_the_models() -> None:
    assert notice.topic_of("runout.models._spindle_kernels") == "spindle model"
    assert notice.topic_of("runout.models.quasi_static_3d") == "quasi_static_3d model"
    assert notice.topic_of("runout.something_new") == "something_new"


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_only_a_terminal_gets_the_notices_unless_asked(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv(notice.ENV)
    assert notice.wanted(_Terminal())
    assert not notice.wanted(io.StringIO())
    monkeypatch.setenv(notice.ENV, "0")
    assert not notice.wanted(_Terminal())
    monkeypatch.setenv(notice.ENV, "1")
    assert notice.wanted(io.StringIO())
    closed = io.StringIO()
    closed.close()
    monkeypatch.delenv(notice.ENV)
    assert not notice.wanted(closed)

"""Ctrl+C and SIGTERM while a command runs: raised where the program is, held while a pool starts or stops
its workers (an interrupt in the middle of starting one left a worker nobody stopped, and a parent waiting
for it for ever), and a second one while held is raised at once."""
import os
import signal

import pytest

from exgen.runtime.interrupts import Terminated, handled, held


def test_sigterm_raises_terminated_and_sigint_keyboard_interrupt():
    with handled():
        with pytest.raises(Terminated):
            os.kill(os.getpid(), signal.SIGTERM)  # the handler runs as soon as this returns
        with pytest.raises(KeyboardInterrupt) as caught:
            os.kill(os.getpid(), signal.SIGINT)
        assert not isinstance(caught.value, Terminated)


def test_an_interrupt_waits_while_held_and_a_second_one_does_not():
    reached = []
    with handled():
        with pytest.raises(Terminated):
            with held():
                os.kill(os.getpid(), signal.SIGTERM)
                reached.append("after the signal")  # the block goes on to its end
        assert reached == ["after the signal"]
        with pytest.raises(KeyboardInterrupt):
            with held():
                os.kill(os.getpid(), signal.SIGINT)
                os.kill(os.getpid(), signal.SIGINT)  # asked twice: now
                reached.append("never")
        assert reached == ["after the signal"]


def test_handlers_are_put_back_after_the_command():
    before = signal.getsignal(signal.SIGTERM), signal.getsignal(signal.SIGINT)
    with handled():
        pass
    assert (signal.getsignal(signal.SIGTERM), signal.getsignal(signal.SIGINT)) == before

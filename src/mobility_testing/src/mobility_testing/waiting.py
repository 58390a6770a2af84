"""Waiting for a condition with a deadline, instead of sleeping and hoping."""
import time


class Timeout(AssertionError):
    """A condition did not hold before its deadline."""


def wait_for(condition, timeout_s, what, poll_s=0.05):
    """Calls condition() until it returns a truthy value and returns that value.

    Raises Timeout naming `what` when timeout_s (wall seconds) pass first.
    """
    deadline = time.monotonic() + timeout_s
    while True:
        value = condition()
        if value:
            return value
        if time.monotonic() > deadline:
            raise Timeout(f'timed out after {timeout_s:.1f} s waiting for {what}')
        time.sleep(poll_s)
